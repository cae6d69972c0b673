package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.handsim.TestPaths;
import org.handsim.text.Json;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Test;

/**
 * What the help and the README say is what the program does: each {@code --help} example's
 * output is the real output, every option of every command is in the README's command table,
 * an option's description is indented one way, and an error quotes the value as typed.
 */
class HelpMatchesTheProgramTest {
    private static List<String> commandNames() {
        List<String> names = new ArrayList<>();
        for (Class<?> c : CliTesting.COMMANDS) names.add(c.getAnnotation(picocli.CommandLine.Command.class).name());
        return names;
    }

    /**
     * Every example in a command's help — a line {@code   handsim CMD ARGS} followed by the JSON
     * it prints — gives that output when run (timings aside), with the input rows the help lists.
     */
    @Test
    @SuppressWarnings("unchecked")
    void everyHelpExamplePrintsWhatTheHelpShows() throws Exception {
        int examples = 0;
        for (String name : commandNames()) {
            String help = CliTesting.run(name, "--help").out().replace("\r", "");
            String[] lines = help.split("\n");
            for (int i = 0; i < lines.length; i++) {
                Matcher m = Pattern.compile("^\\s+handsim (" + name + ") (.*)$").matcher(lines[i]);
                if (!m.find()) continue;
                // the output: the JSON object on the lines after the command
                StringBuilder shown = new StringBuilder();
                for (int j = i + 1; j < lines.length && !lines[j].trim().startsWith("("); j++) shown.append(lines[j].trim());
                assertTrue(shown.toString().startsWith("{"), name + ": no output shown after " + lines[i]);
                Path dir = Files.createTempDirectory("handsim-help");
                try {
                    List<String> args = new ArrayList<>(List.of(m.group(1)));
                    for (String a : m.group(2).trim().split("\\s+")) args.add(a.endsWith(".csv") ? dir.resolve(a).toString() : a);
                    assertEquals("quality", name, "an example of a command this test does not know how to feed: " + lines[i]);
                    Files.writeString(dir.resolve("cube.csv"), qualityRows(help));
                    CliTesting.Run r = CliTesting.run(args.toArray(new String[0]));
                    assertEquals(0, r.code(), r.err());
                    Map<String, Object> real = (Map<String, Object>) Json.parse("stdout", r.out());
                    Map<String, Object> expected = (Map<String, Object>) Json.parse("help", shown.toString().replace("...", "0"));
                    assertEquals(expected, real, name + " --help example:\n" + shown);
                    examples++;
                } finally {
                    VrmlTesting.deleteTree(dir);
                }
            }
        }
        assertEquals(1, examples, "the examples in the help (quality's)");
    }

    /** The CSV rows quality's help lists: the header, then two rows a line. */
    private static String qualityRows(String help) {
        StringBuilder csv = new StringBuilder();
        Matcher m = Pattern.compile("(?m)^[ \\t]+(x,y,z,nx,ny,nz|-?[0-9.]+(?:,-?[0-9.]+){5})(?:[ \\t]+(-?[0-9.]+(?:,-?[0-9.]+){5}))?").matcher(help);
        while (m.find()) {
            csv.append(m.group(1)).append('\n');
            if (m.group(2) != null) csv.append(m.group(2)).append('\n');
        }
        assertEquals(7, csv.toString().split("\n").length, "header and six contacts:\n" + csv);
        return csv.toString();
    }

    /** Each option in the README's command table, for each command (rows naming it, e.g. `handsim fk|ik|id ...`). */
    @Test
    void theReadmeTableListsEveryOptionOfEveryCommand() throws Exception {
        List<String> rows = new ArrayList<>();
        for (String line : Files.readAllLines(TestPaths.root().resolve("README.md"))) {
            if (line.startsWith("| `handsim ")) rows.add(line.replace("\\|", "|"));
        }
        assertFalse(rows.isEmpty());
        for (String name : commandNames()) {
            TreeSet<String> documented = new TreeSet<>();
            for (String row : rows) {
                String cmd = row.substring("| `handsim ".length()).split(" ")[0];
                if (!List.of(cmd.split("\\|")).contains(name)) continue;
                Matcher m = Pattern.compile("--[a-z][a-z0-9-]*").matcher(row);
                while (m.find()) documented.add(m.group());
            }
            picocli.CommandLine.Model.CommandSpec spec = HandSim.commandLine(null, List.of(org.handsim.server.ServerCommand.class)).getSubcommands().get(name).getCommandSpec();
            TreeSet<String> options = new TreeSet<>();
            for (picocli.CommandLine.Model.OptionSpec o : spec.options()) {
                if (!o.usageHelp() && !o.versionHelp()) options.add(o.longestName());
            }
            assertEquals(options, documented, "README's command table, handsim " + name);
        }
    }

    /**
     * An option's description is indented one way: its first line at the description column, each
     * further line two spaces in (picocli's wrapping), never back at the column.
     */
    @Test
    void optionDescriptionsContinueAtOneIndent() {
        for (String name : commandNames()) {
            String[] lines = CliTesting.run(name, "--help").out().replace("\r", "").split("\n");
            int column = -1;
            for (String line : lines) {
                Matcher opt = Pattern.compile("^(  -\\w, | {6})(--?[\\w-]+(=\\S+)?|\\[?[A-Z][A-Za-z.]*\\]?)( +)\\S").matcher(line);
                if (opt.find()) {
                    column = opt.end() - 1;
                    continue;
                }
                if (line.matches("^(  -\\w, | {6})--\\S+$")) {   // a long label: the description starts on the next line
                    column = -2;
                    continue;
                }
                if (column == -2) {
                    column = line.length() - line.stripLeading().length();
                    continue;
                }
                if (column < 0 || line.isBlank() || !line.startsWith(" ".repeat(Math.min(column, 20)))) {
                    if (!line.startsWith("      ")) column = -1;   // left the option list
                    continue;
                }
                int indent = line.length() - line.stripLeading().length();
                if (indent == column || indent == column + 2) {
                    assertEquals(column + 2, indent, name + " --help: a continuation line back at the description column: '" + line + "'");
                }
            }
        }
    }

    @Test
    void smallLiesAreGone() {
        CliTesting.Run dt = CliTesting.run("run", "--dt", "0");
        assertEquals(2, dt.code());
        assertEquals("handsim: --dt must be in (0, 0.1] seconds, got 0", dt.err());
        String collide = CliTesting.run("collide", "--help").out();
        assertTrue(collide.startsWith("Usage: handsim collide [-hV] ") && collide.contains(" A B\n"), collide);
        assertFalse(collide.contains(".wrl B"), collide);
        String tradeoff = CliTesting.run("tradeoff", "--help").out();
        assertFalse(tradeoff.contains("a few minutes"), tradeoff);
        assertTrue(tradeoff.replaceAll("\\s+", " ").contains("about a minute"), tradeoff);
    }
}
