package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.handsim.TestPaths;
import org.handsim.scenario.Home;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Clean output at the command line: one-line errors with input escaped, never a stack trace; the
 * command list without arguments; help that works; and output files read back with no -0, no
 * integer written as a float and no accumulated time noise.
 */
public class CleanOutputTest {
    /** A number token of JSON or CSV text. */
    static final Pattern NUMBER = Pattern.compile("(?<![\\w.\"-])-?\\d+(\\.\\d+)?([eE][-+]?\\d+)?(?![\\w.\"])");

    /** Fails on -0, on an integer written as a float (44732.0, 1.0E7), on a Java exponent (5.0E-4). */
    public static void assertCleanNumbers(String what, String text) {
        Matcher m = NUMBER.matcher(text);
        int n = 0;
        while (m.find()) {
            String t = m.group();
            n++;
            assertFalse(t.equals("-0") || t.matches("-0\\.0+"), what + ": negative zero '" + t + "'");
            assertFalse(t.matches("-?\\d+\\.0+"), what + ": integer written as a float '" + t + "'");
            assertFalse(t.contains("E"), what + ": Java exponent form '" + t + "'");
        }
        assertTrue(n > 0, what + ": no numbers found");
    }

    public static void assertOneLineNoStackTrace(String what, String err) {
        assertFalse(err.isEmpty(), what + ": no message");
        assertEquals(1, err.split("\n", -1).length, what + ": one line: " + err);
        assertFalse(err.contains("\tat ") || err.contains("Exception in thread") || err.matches("(?s).*\\bat org\\.handsim\\..*"), what + ": " + err);
        for (int i = 0; i < err.length(); i++) {
            char c = err.charAt(i);
            assertFalse(c < 0x20 || (c >= 0x7f && c <= 0x9f) || c == 0x2028 || c == 0x2029, what + ": raw U+" + Integer.toHexString(c) + " in " + err);
        }
    }

    @Test
    void noArgumentsListsTheCommandsAndExits2() {
        CliTesting.Run r = CliTesting.run();
        assertEquals(2, r.code());
        for (Class<?> c : CliTesting.COMMANDS) {
            String name = c.getAnnotation(picocli.CommandLine.Command.class).name();
            assertTrue(r.err().contains("\n  " + name + " "), name + " listed: " + r.err());
        }
        assertTrue(r.err().contains("Commands:") && r.err().endsWith("'handsim help CMD' for one command)"), r.err());
    }

    /** The command list shows each command's first description line: a whole sentence. */
    @Test
    void theCommandListShowsWholeFirstSentences() {
        for (Class<?> c : CliTesting.COMMANDS) {
            picocli.CommandLine.Command a = c.getAnnotation(picocli.CommandLine.Command.class);
            String first = a.description()[0].trim();
            assertTrue(first.endsWith(".") || first.endsWith(")"), a.name() + ": first description line is not a whole sentence: " + first);
        }
    }

    @Test
    void helpCommandShowsAnyCommandsHelp() {
        for (Class<?> c : CliTesting.COMMANDS) {
            String name = c.getAnnotation(picocli.CommandLine.Command.class).name();
            CliTesting.Run viaHelp = CliTesting.run("help", name), viaOption = CliTesting.run(name, "--help");
            assertEquals(0, viaHelp.code(), name);
            assertEquals(viaOption.out(), viaHelp.out(), name);
        }
        CliTesting.Run bad = CliTesting.run("help", "nosuchcommand");
        assertEquals(2, bad.code(), bad.err());
    }

    /** The table headers the help of sweep and plan quote are the headers the commands write (laid out over lines). */
    @Test
    void helpQuotesTheTableHeadersTheCommandsWrite() {
        String sweep = CliTesting.run("sweep", "--help").out().replaceAll("\\s+", "");
        assertTrue(sweep.contains(SweepCommand.HEADER), "sweep --help quotes summary.csv's header " + SweepCommand.HEADER);
        String plan = CliTesting.run("plan", "--help").out().replaceAll("\\s+", "");
        assertTrue(plan.contains(org.handsim.plan.TrialResult.HEADER), "plan --help quotes plan.csv's header " + org.handsim.plan.TrialResult.HEADER);
    }

    /**
     * Help lays out tokens whole: every line fits 80 columns; the synopsis breaks only between
     * options (each [..] group opens and closes on one line); a line of a JSON template never
     * ends inside a string (an even number of double quotes).
     */
    @Test
    void helpNeverBreaksInsideAToken() {
        List<String> names = new ArrayList<>(List.of(""));
        for (Class<?> c : CliTesting.COMMANDS) names.add(c.getAnnotation(picocli.CommandLine.Command.class).name());
        for (String name : names) {
            CliTesting.Run r = name.isEmpty() ? CliTesting.run("--help") : CliTesting.run(name, "--help");
            boolean synopsis = true;
            for (String line : r.out().split("\n")) {
                assertTrue(line.length() <= HandSim.HELP_WIDTH, name + ": longer than " + HandSim.HELP_WIDTH + ": " + line);
                if (synopsis && !line.startsWith("Usage:") && !line.startsWith("        ")) synopsis = false;
                if (synopsis) {
                    int depth = 0;
                    for (char c : line.toCharArray()) depth += c == '[' ? 1 : c == ']' ? -1 : 0;
                    assertEquals(0, depth, name + ": synopsis broken inside an option: " + line);
                }
                if (line.trim().startsWith("{") || line.trim().startsWith("\"")) {
                    assertEquals(0, line.chars().filter(ch -> ch == '"').count() % 2, name + ": a JSON template line ends inside a string: " + line);
                }
            }
        }
    }

    @Test
    void junkWithNextLineLineSeparatorAndNulIsOneEscapedLine() throws Exception {
        Path dir = Files.createTempDirectory("handsim-junk");
        try {
            Path junk = dir.resolve("case.wrl");
            byte[] head = "#VRML V2.0 utf8\nGroup { children [\n".getBytes(StandardCharsets.US_ASCII);
            byte[] word = {'X', (byte) 0xc2, (byte) 0x85, 'Y', (byte) 0xe2, (byte) 0x80, (byte) 0xa8, 'Z', (byte) 0xff, 0, 'W'};
            Files.write(junk, concat(head, word, " { } ] }\n".getBytes(StandardCharsets.US_ASCII)));
            for (String cmd : new String[] {"mesh", "collide"}) {
                CliTesting.Run r = cmd.equals("mesh") ? CliTesting.run("mesh", junk.toString()) : CliTesting.run("collide", junk.toString(), junk.toString());
                assertEquals(3, r.code(), r.err());
                assertOneLineNoStackTrace(cmd, r.err());
                assertEquals(junk + ":3:1: unknown node type 'X\\u0085Y\\u2028Z\\udcff' (not a VRML97 node, and no PROTO of that name was declared before)",
                    r.err());
            }
            // the NUL where a value is expected: named, never printed raw
            Files.write(junk, concat("#VRML V2.0 utf8\nShape { geometry Box { size 1 2 ".getBytes(StandardCharsets.US_ASCII),
                new byte[] {'X', (byte) 0xc2, (byte) 0x85, (byte) 0xe2, (byte) 0x80, (byte) 0xa9, 0}, " } }\n".getBytes(StandardCharsets.US_ASCII)));
            CliTesting.Run r = CliTesting.run("mesh", junk.toString());
            assertEquals(3, r.code());
            assertOneLineNoStackTrace("mesh", r.err());
            assertTrue(r.err().endsWith("found 'X\\u0085\\u2029'"), r.err());
            // a very long junk word is shortened
            Files.writeString(junk, "#VRML V2.0 utf8\n" + "Q".repeat(10_000) + " { }\n");
            r = CliTesting.run("mesh", junk.toString());
            assertOneLineNoStackTrace("mesh", r.err());
            assertTrue(r.err().length() < 300 && r.err().contains("QQQ...QQQ"), r.err());
            // JSON: a scenario whose junk is a NEL between values
            Path json = dir.resolve("s.json");
            Files.write(json, concat("{\"name\": ".getBytes(StandardCharsets.US_ASCII), new byte[] {(byte) 0xc2, (byte) 0x85, 0}, "}".getBytes(StandardCharsets.US_ASCII)));
            r = CliTesting.run("run", json.toString(), "--out", dir.resolve("out").toString());
            assertEquals(3, r.code(), r.err());
            assertOneLineNoStackTrace("run", r.err());
            assertTrue(r.err().endsWith("s.json:1:10: unexpected character '\\u0085'"), r.err());
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    private static byte[] concat(byte[]... parts) {
        int n = 0;
        for (byte[] p : parts) n += p.length;
        byte[] all = new byte[n];
        int at = 0;
        for (byte[] p : parts) {
            System.arraycopy(p, 0, all, at, p.length);
            at += p.length;
        }
        return all;
    }

    /** Every file of the malformed-VRML tests, through every command that loads VRML: exit 3, one line, no stack trace. */
    @Test
    @Tag("slow")   // every command on every malformed input: ./test --all (CI)
    void noStackTraceOnAnyMalformedInput() throws Exception {
        Path bad = TestPaths.root().resolve("src/test/resources/vrml/bad");
        List<Path> files = new ArrayList<>();
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(bad, "*.wrl")) {
            ds.forEach(files::add);
        }
        assertTrue(files.size() >= 30, "the malformed files: " + files.size());
        Path good = TestPaths.root().resolve("vrml/objects/cube.wrl");
        Path dir = Files.createTempDirectory("handsim-malformed");
        try {
            String paper = Files.readString(Home.paperScenario());
            for (Path f : files) {
                // the bad file as the object of the paper's scenario: handsim run and handsim sweep
                Path scenario = dir.resolve("s.json");
                Files.writeString(scenario, paper.replace("../vrml/objects/cube.wrl", f.toString().replace("\\", "/")));
                Path sweep = dir.resolve("w.json");
                Files.writeString(sweep, "{\"name\":\"w\",\"scenarios\":[\"s.json\"]}");
                for (String[] args : new String[][] {{"mesh", f.toString()}, {"collide", good.toString(), f.toString()},
                    {"run", scenario.toString(), "--out", dir.resolve("out").toString()}}) {
                    CliTesting.Run r = CliTesting.run(args);
                    assertEquals(3, r.code(), String.join(" ", args) + ": " + r.err());
                    assertOneLineNoStackTrace(String.join(" ", args), r.err());
                    assertTrue(r.err().startsWith(f + ":"), r.err());
                }
                CliTesting.Run r = CliTesting.run("sweep", sweep.toString(), "--out", dir.resolve("sweep").toString());
                assertEquals(1, r.code(), r.err());
                assertFalse(r.err().contains("\tat ") || r.err().contains("Exception in thread"), r.err());
                String row = Files.readAllLines(dir.resolve("sweep/summary.csv")).get(1);
                assertTrue(row.matches("s,(paper-breakaway)?,failed,.*") && row.contains(f.getFileName().toString()), row);
            }
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    /** An output folder that cannot be made: one line naming the option, the path and the reason, exit 2; nothing left behind. */
    @Test
    void anOutputErrorIsOneLine() throws Exception {
        Path dir = Files.createTempDirectory("handsim-ioerror");
        try {
            Path file = Files.writeString(dir.resolve("a-file"), "x");
            CliTesting.Run r = CliTesting.run("run", "--no-charts", "--out", file.resolve("sub").toString());
            assertEquals(2, r.code(), r.err());
            assertOneLineNoStackTrace("run", r.err());
            assertTrue(r.err().startsWith("handsim: --out '") && r.err().endsWith("/a-file/sub' cannot be written: Not a directory"), r.err());
            try (var s = Files.list(dir)) {
                assertEquals(1, s.count(), "only the file the test made");
            }
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    /** An option that does nothing in context says so on standard error, and the command still runs. */
    @Test
    void divisionsOnAFixedMeshSayItHaveNoEffect() throws Exception {
        Path cube = TestPaths.root().resolve("vrml/objects/cube.wrl");
        // --units m: the unit chosen, so the unit rule's notice does not join the note
        CliTesting.Run r = CliTesting.run("mesh", cube.toString(), "--divisions", "64", "--units", "m");
        assertEquals(0, r.code(), r.err());
        assertEquals("handsim mesh: --divisions has no effect: " + cube + " has no Sphere, Cylinder or Cone (a fixed mesh)", r.err());
        assertEquals("", CliTesting.run("mesh", cube.toString(), "--units", "m").err(), "no note without the option");
        Path dir = Files.createTempDirectory("handsim-sphere");
        try {
            Path sphere = Files.writeString(dir.resolve("sphere.wrl"), "#VRML V2.0 utf8\nShape { geometry Sphere { radius 0.05 } }\n");
            r = CliTesting.run("mesh", sphere.toString(), "--divisions", "64", "--units", "m");
            assertEquals(0, r.code(), r.err());
            assertEquals("", r.err(), "a sphere depends on --divisions");
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    /** Anything unexpected — even an OutOfMemoryError — is one line, exit 1, with the stack in a log file. */
    @Test
    void anUnexpectedErrorIsOneLineAndALogFile() throws Exception {
        for (Throwable t : new Throwable[] {new OutOfMemoryError("Java heap space"), new StackOverflowError(),
            new IllegalStateException("bug\u0085here\nsecond line")}) {
            StringWriter sw = new StringWriter();
            int code = HandSim.failure(new PrintWriter(sw), new picocli.CommandLine.ExecutionException(new picocli.CommandLine(new HandSim()), "x", t));
            String line = sw.toString().trim();
            assertEquals(1, code);
            assertOneLineNoStackTrace(t.toString(), line);
            Matcher m = Pattern.compile("\\(stack trace in (.+\\.log)\\)$").matcher(line);
            assertTrue(m.find(), line);
            Path log = Path.of(m.group(1));
            try {
                assertTrue(Files.readString(log).contains("at org.handsim.cli.CleanOutputTest"), "the log holds the stack");
            } finally {
                Files.deleteIfExists(log);
            }
            if (t instanceof OutOfMemoryError) assertTrue(line.startsWith("handsim: out of memory (Java heap space): give Java more heap"), line);
            if (t instanceof StackOverflowError) assertTrue(line.startsWith("handsim: stack overflow"), line);
            if (t instanceof IllegalStateException) assertTrue(line.contains("bug\\u0085here\\u000asecond line"), line);
        }
    }

    /** summary.json, trace.csv, the sweep table and swing.json/csv read back: clean numbers, times as step × dt. */
    @Test
    void outputFilesHaveCleanNumbers() throws Exception {
        Path dir = Files.createTempDirectory("handsim-clean");
        try {
            CliTesting.Run r = CliTesting.run("run", "--no-charts", "--out", dir.resolve("run").toString());
            assertEquals(0, r.code(), r.err());
            String summary = Files.readString(dir.resolve("run/summary.json"));
            assertCleanNumbers("summary.json", summary);
            assertTrue(summary.contains("\"sim_time_s\": 8.947,") && summary.contains("\"steps\": 8947,") && summary.contains("\"dt_s\": 0.001,"), summary);
            List<String> trace = Files.readAllLines(dir.resolve("run/trace.csv"));
            for (int i = 1; i < trace.size(); i++) {
                String t = trace.get(i).substring(0, trace.get(i).indexOf(','));
                assertEquals(new java.math.BigDecimal(i - 1).movePointLeft(3).stripTrailingZeros().toPlainString(), t, "t of row " + i);
            }
            assertCleanNumbers("trace.csv", String.join("\n", trace.subList(1, trace.size())));

            Path base = dir.resolve("base.json");
            Files.writeString(base, Files.readString(Home.paperScenario())
                .replace("../vrml/objects/cube.wrl", Home.dir().resolve("vrml/objects/cube.wrl").toString().replace("\\", "/")));
            Path sweep = dir.resolve("sweep.json");
            Files.writeString(sweep, "{\"name\":\"t\",\"base\":\"base.json\",\"runs\":[{\"label\":\"a\",\"set\":{}},"
                + "{\"label\":\"b\",\"set\":{\"dt_s\":0.0005,\"duration_s\":2.5}}]}");
            r = CliTesting.run("sweep", sweep.toString(), "--out", dir.resolve("sweep").toString(), "--threads", "2");
            assertEquals(0, r.code(), r.err());
            List<String> rows = Files.readAllLines(dir.resolve("sweep/summary.csv"));
            assertTrue(rows.get(1).startsWith("a,paper-breakaway,ok,8.947,8947,"), rows.get(1));
            assertTrue(rows.get(2).startsWith("b,paper-breakaway,ok,2.5,5000,"), rows.get(2));
            assertCleanNumbers("summary.csv", String.join("\n", rows.subList(1, rows.size())));

            r = CliTesting.run("swing", "--dt", "0.0005", "--duration", "0.3", "--out", dir.resolve("swing").toString());
            assertEquals(0, r.code(), r.err());
            assertTrue(r.out().startsWith("finger 1, rk4, dt = 0.0005 s: 600 steps over 0.3 s"), r.out());
            String json = Files.readString(dir.resolve("swing/swing.json"));
            assertCleanNumbers("swing.json", json);
            assertTrue(json.contains("\"dt_s\": 0.0005,") && json.contains("\"steps\": 600,") && json.contains("\"duration_s\": 0.3,"), json);
            List<String> csv = Files.readAllLines(dir.resolve("swing/swing.csv"));
            for (int i = 1; i < csv.size(); i++) {
                String t = csv.get(i).substring(0, csv.get(i).indexOf(','));
                assertEquals(new java.math.BigDecimal(5 * (i - 1)).movePointLeft(4).stripTrailingZeros().toPlainString(), t, "t of row " + i);
            }
            assertCleanNumbers("swing.csv", String.join("\n", csv.subList(1, csv.size())));
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }
}
