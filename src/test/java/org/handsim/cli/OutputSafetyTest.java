package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.handsim.TestPaths;
import org.handsim.scenario.Home;
import org.handsim.files.DeviceNodes;
import org.junit.jupiter.api.Test;

/**
 * What the commands write, and where: never over a device, a FIFO or the input; never outside
 * the output folder (a scenario named ".." wrote into the current folder, {@code --out ''} too);
 * a re-run replaces the whole set and nothing else; a folder that cannot take the set is refused
 * before the run, with one line and exit 2.
 */
class OutputSafetyTest {
    static final String FK_IN = "finger,t1,t2,t3\n1,0,0.1,0.2\n3,0,0.5,0.5\n";
    static final String IK_IN = "finger,x,y,z\n1,0.1,0,0.05\n";
    static final String ID_IN = "finger,q1,q2,q3,qd1,qd2,qd3,qdd1,qdd2,qdd3,gx,gy,gz\n1,0,0.1,0.2,0,0,0,0,0,0,0,0,-9.81\n";

    static Path cube() {
        return TestPaths.root().resolve("vrml/objects/cube.wrl");
    }

    /** Everything in the folder by relative path (contents of regular files; "<other>" for anything else). */
    static Map<String, String> tree(Path dir) throws IOException {
        Map<String, String> m = new TreeMap<>();
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                if (p.equals(dir)) continue;
                String rel = dir.relativize(p).toString();
                m.put(rel, Files.isRegularFile(p) ? new String(Files.readAllBytes(p), StandardCharsets.ISO_8859_1)
                    : Files.isDirectory(p) ? "<folder>" : "<other>");
            }
        }
        return m;
    }

    /** Every command that writes a file or a folder, pointed at the device {@code dev}: it stays a device. */
    private static void writeEverythingTo(Path dir, Path dev, boolean fits) throws Exception {
        Path in = dir.resolve("fk.csv"), ik = dir.resolve("ik.csv"), id = dir.resolve("id.csv");
        Files.writeString(in, FK_IN);
        Files.writeString(ik, IK_IN);
        Files.writeString(id, ID_IN);
        List<String[]> writers = List.of(
            new String[] {"fk", "--input", in.toString(), "--output", dev.toString()},
            new String[] {"ik", "--input", ik.toString(), "--output", dev.toString()},
            new String[] {"id", "--input", id.toString(), "--output", dev.toString()},
            // --units m: the unit chosen, so the unit rule's notice does not join the error line
            new String[] {"mesh", cube().toString(), "--units", "m", "--stl", dev.toString()},
            new String[] {"mesh", cube().toString(), "--units", "m", "--obj", dev.toString()});
        for (String[] args : writers) {
            CliTesting.Run r = CliTesting.run(args);
            String what = String.join(" ", args);
            assertTrue(DeviceNodes.isCharDevice(dev), what + ": " + dev + " is still a character device");
            if (fits) {
                assertEquals(0, r.code(), what + ": " + r.err());
            } else {
                assertEquals(1, r.code(), what);
                assertTrue(r.err().contains("No space left on device"), r.err());
                CleanOutputTest.assertOneLineNoStackTrace(what, r.err());
            }
        }
        Path sweep = dir.resolve("sweep.json");
        Files.writeString(sweep, "{\"name\": \"s\", \"base\": \"" + Home.paperScenario() + "\", \"runs\": [{\"label\": \"a\"}]}");
        List<String[]> folders = List.of(
            new String[] {"run", "--out", dev.toString()},
            new String[] {"swing", "--out", dev.toString()},
            new String[] {"sweep", sweep.toString(), "--out", dev.toString()},
            new String[] {"plan", cube().toString(), "--trials", "1", "--units", "m", "--out", dev.toString()},
            new String[] {"tradeoff", "--quick", "--only", "4", "--out", dev.toString()});
        for (String[] args : folders) {
            CliTesting.Run r = CliTesting.run(args);
            String what = String.join(" ", args);
            assertEquals(2, r.code(), what + ": " + r.err());
            assertTrue(r.err().equals("handsim: --out " + dev + ": exists and is not a folder"), r.err());
            assertTrue(DeviceNodes.isCharDevice(dev), what);
        }
    }

    @Test
    void devicesStayDevicesWhateverWritesToThem() throws Exception {
        Path dir = Files.createTempDirectory("handsim-devices");
        try {
            Path nul = DeviceNodes.charDevice(dir, "null", 1, 3), full = DeviceNodes.charDevice(dir, "full", 1, 7);
            assumeTrue(nul != null && full != null, "mknod needs root (CI runs as root)");
            writeEverythingTo(dir, nul, true);
            writeEverythingTo(dir, full, false);
            // a device where the set has a file: refused before the run, the device and the folder as they were
            Path out = Files.createDirectories(dir.resolve("out"));
            Path trace = DeviceNodes.charDevice(out, "trace.csv", 1, 3);
            CliTesting.Run r = CliTesting.run("run", "--dt", "0.01", "--out", out.toString());
            assertEquals(2, r.code(), r.err());
            assertEquals("handsim: --out " + out + ": " + trace + " is a device, FIFO or socket, not a file this command may replace", r.err());
            assertTrue(DeviceNodes.isCharDevice(trace));
            assertEquals(Map.of("trace.csv", "<other>"), tree(out));
            Path chartCsv = DeviceNodes.charDevice(dir, "g.csv", 1, 3);
            r = CliTesting.run("grasp", "--at", "0.1", "--chart", dir.resolve("g").toString());
            assertEquals(2, r.code(), r.err());
            assertTrue(DeviceNodes.isCharDevice(chartCsv));
            assertFalse(Files.exists(dir.resolve("g.png")));
            // proven on our own nodes: now the machine's own, which must stay devices too
            try {
                writeEverythingTo(dir, Path.of("/dev/null"), true);
                CliTesting.Run f = CliTesting.run("fk", "--input", dir.resolve("fk.csv").toString(), "--output", "/dev/full");
                assertEquals(1, f.code(), f.err());
            } finally {
                assertTrue(DeviceNodes.restoreIfBroken("/dev/null", 3), "/dev/null was replaced (restored)");
                assertTrue(DeviceNodes.restoreIfBroken("/dev/full", 7), "/dev/full was replaced (restored)");
            }
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    @Test
    void aFifoOutputIsWrittenInPlace() throws Exception {
        Path dir = Files.createTempDirectory("handsim-fifo");
        try {
            Path fifo = DeviceNodes.fifo(dir, "out.csv");
            assumeTrue(fifo != null, "mkfifo");
            Files.writeString(dir.resolve("in.csv"), FK_IN);
            CompletableFuture<List<String>> read = CompletableFuture.supplyAsync(() -> {
                try {
                    return Files.readAllLines(fifo);
                } catch (IOException e) {
                    return List.of("failed: " + e);
                }
            });
            CliTesting.Run r = CliTesting.run("fk", "--input", dir.resolve("in.csv").toString(), "--output", fifo.toString());
            assertEquals(0, r.code(), r.err());
            List<String> lines = read.get(60, TimeUnit.SECONDS);
            assertEquals(3, lines.size(), lines.toString());
            assertTrue(lines.get(0).startsWith("finger,t1,t2,t3,o0x"), lines.get(0));
            assertTrue(DeviceNodes.isFifo(fifo));
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    /** --output naming the input (directly, through a link, or a hard link) is refused: the input is never overwritten. */
    @Test
    void theOutputIsNeverTheInput() throws Exception {
        Path dir = Files.createTempDirectory("handsim-same");
        try {
            Path in = dir.resolve("in.csv");
            Files.writeString(in, FK_IN);
            Files.createSymbolicLink(dir.resolve("link.csv"), Path.of("in.csv"));
            Files.createLink(dir.resolve("hard.csv"), in);
            for (String out : new String[] {"in.csv", "link.csv", "hard.csv", "./in.csv"}) {
                CliTesting.Run r = CliTesting.run("fk", "--input", in.toString(), "--output", dir.resolve(out).toString());
                assertEquals(2, r.code(), out + ": " + r.err());
                assertTrue(r.err().contains("is the input --input") && r.err().endsWith("refusing to overwrite it"), r.err());
                CleanOutputTest.assertOneLineNoStackTrace(out, r.err());
                assertEquals(FK_IN, Files.readString(in));
            }
            Object[][] others = {{"ik", IK_IN}, {"id", ID_IN}};
            for (Object[] o : others) {
                Path other = dir.resolve(o[0] + ".csv");
                Files.writeString(other, (String) o[1]);
                CliTesting.Run r = CliTesting.run((String) o[0], "--input", other.toString(), "--output", other.toString());
                assertEquals(2, r.code(), o[0] + ": " + r.err());
                assertEquals(o[1], Files.readString(other));
            }
            Path wrl = Files.copy(cube(), dir.resolve("cube.wrl"));
            String before = Files.readString(wrl);
            CliTesting.Run r = CliTesting.run("mesh", wrl.toString(), "--stl", wrl.toString());
            assertEquals(2, r.code(), r.err());
            assertEquals(before, Files.readString(wrl));
            r = CliTesting.run("fk", "--input", in.toString(), "--output", dir.toString());
            assertEquals(2, r.code(), r.err());
            assertEquals("handsim: --output " + dir + " is a folder, not a file", r.err());
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    /** An empty output name (which wrote into the current folder) is refused by every command, naming the option. */
    @Test
    void anEmptyOutputNameIsRefused() throws Exception {
        Path dir = Files.createTempDirectory("handsim-empty");
        try {
            Path sweep = dir.resolve("sweep.json");
            Files.writeString(sweep, "{\"name\": \"s\", \"base\": \"" + Home.paperScenario() + "\", \"runs\": [{\"label\": \"a\"}]}");
            Files.writeString(dir.resolve("in.csv"), FK_IN);
            Object[][] cases = {
                {new String[] {"run", "--out", ""}, "--out must name a folder, got ''"},
                {new String[] {"sweep", sweep.toString(), "--out", ""}, "--out must name a folder, got ''"},
                {new String[] {"plan", cube().toString(), "--trials", "1", "--units", "m", "--out", ""}, "--out must name a folder, got ''"},
                {new String[] {"tradeoff", "--quick", "--out", ""}, "--out must name a folder, got ''"},
                {new String[] {"swing", "--out", ""}, "--out must name a folder, got ''"},
                {new String[] {"grasp", "--chart", ""}, "--chart must name a file, got ''"},
                {new String[] {"fk", "--input", dir.resolve("in.csv").toString(), "--output", ""}, "--output must name a file, got ''"},
                {new String[] {"mesh", cube().toString(), "--stl", ""}, "--stl must name a file, got ''"}};
            for (Object[] c : cases) {
                String[] args = (String[]) c[0];
                CliTesting.Run r = CliTesting.run(args);
                assertEquals(2, r.code(), String.join(" ", args) + ": " + r.err());
                assertEquals("handsim: " + c[1], r.err());
                assertEquals("", r.out());
            }
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    /** A scenario or sweep named ".", ".." (which wrote outside out/), with a separator or a control character: exit 3 naming the field. */
    @Test
    void namesThatAreNotFileNamesAreRefused() throws Exception {
        Path dir = Files.createTempDirectory("handsim-names");
        try {
            String paper = Files.readString(Home.paperScenario())
                .replace("../vrml/objects/cube.wrl", cube().toString().replace("\\", "/"));
            for (String name : new String[] {".", "..", "...", "a/b", "..\\\\x", "x\\u0007y", ""}) {
                Path s = dir.resolve("s.json");
                Files.writeString(s, paper.replace("\"name\": \"paper-breakaway\"", "\"name\": \"" + name + "\""));
                CliTesting.Run r = CliTesting.run("run", s.toString(), "--out", dir.resolve("out").toString());
                assertEquals(3, r.code(), name + ": " + r.err());
                assertTrue(r.err().contains("field name: must"), r.err());
                CleanOutputTest.assertOneLineNoStackTrace(name, r.err());
                assertFalse(Files.exists(dir.resolve("out")));
            }
            Path sweep = dir.resolve("sweep.json");
            Files.writeString(sweep, "{\"name\": \"..\", \"base\": \"" + Home.paperScenario() + "\", \"runs\": [{\"label\": \"a\"}]}");
            CliTesting.Run r = CliTesting.run("sweep", sweep.toString());
            assertEquals(3, r.code(), r.err());
            assertTrue(r.err().contains("field name: must not be '.' or '..'"), r.err());
            List<String> left = new ArrayList<>();
            try (Stream<Path> s = Files.list(dir)) {
                s.forEach(p -> left.add(p.getFileName().toString()));
            }
            left.sort(null);
            assertEquals(List.of("s.json", "sweep.json"), left);
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    /**
     * A re-run replaces the whole set: a chart the new run does not draw goes (before the fix, a
     * stale chart of the previous run stayed beside the new table); files that are not the
     * set's stay; a folder in place of one of the set's files is refused before the run.
     */
    @Test
    void aReRunReplacesTheWholeSetAndNothingElse() throws Exception {
        Path dir = Files.createTempDirectory("handsim-rerun");
        try {
            Path out = dir.resolve("out");
            CliTesting.Run r = CliTesting.run("run", "--dt", "0.01", "--out", out.toString());
            assertEquals(0, r.code(), r.err());
            assertTrue(Files.exists(out.resolve("fig7_finger3.svg")));
            Files.writeString(out.resolve("fig7_finger1.png"), "a chart of a finger that moved in an older run");
            Files.writeString(out.resolve("notes.txt"), "the user's notes");
            Files.createDirectories(out.resolve("mine"));
            r = CliTesting.run("run", "--dt", "0.02", "--no-charts", "--out", out.toString());
            assertEquals(0, r.code(), r.err());
            Map<String, String> t = tree(out);
            assertEquals(List.of("mine", "notes.txt", "summary.json", "trace.csv"), new ArrayList<>(t.keySet()));
            assertTrue(t.get("summary.json").contains("\"dt_s\": 0.02"), t.get("summary.json"));
            assertEquals("the user's notes", t.get("notes.txt"));
            Files.createDirectories(out.resolve("fig8_finger3.svg"));
            r = CliTesting.run("run", "--dt", "0.01", "--out", out.toString());
            assertEquals(2, r.code(), r.err());
            assertTrue(r.err().endsWith("fig8_finger3.svg is a folder, not a file this command may replace"), r.err());
            assertEquals(t.keySet().size() + 1, tree(out).size(), "nothing written");
            assertTrue(tree(out).get("summary.json").contains("\"dt_s\": 0.02"));
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    /**
     * The battery's two symlink tricks through the commands: {@code plan} into a folder whose
     * {@code best/} links to another folder, and {@code run} into a folder with a killed writer's
     * crafted manifest that moves and drops files through a linked subfolder. Each is refused
     * with one line naming the link (exit 2), and the other folder is unchanged, byte for byte.
     */
    @Test
    void symlinksInTheOutputFolderLeadNothingOut() throws Exception {
        Path dir = Files.createTempDirectory("handsim-links");
        try {
            Path victim = Files.createDirectories(dir.resolve("victim"));
            Files.writeString(victim.resolve("01.json"), "the victim's grasp");
            Files.writeString(victim.resolve("keep.txt"), "keep");
            Map<String, String> before = tree(victim);
            Path plan = Files.createDirectories(dir.resolve("plan"));
            Files.createSymbolicLink(plan.resolve("best"), Path.of("../victim"));
            CliTesting.Run r = CliTesting.run("plan", cube().toString(), "--trials", "2", "--units", "m", "--out", plan.toString());
            assertEquals(2, r.code(), r.err());
            assertEquals("handsim: --out " + plan + ": " + plan.resolve("best") + " is a symbolic link: an output set is never written"
                + " through it (it could lead out of the output folder)", r.err());
            assertEquals(before, tree(victim));

            Path run = Files.createDirectories(dir.resolve("run"));
            Path stage = Files.createDirectories(run.resolve(".handsim-writing/stage-4000000-1/sub"));
            Files.writeString(stage.resolve("evil.txt"), "planted");
            Files.writeString(stage.getParent().resolve(".publish"), "move sub/evil.txt\ndrop sub/keep.txt\n");
            Files.createSymbolicLink(run.resolve("sub"), Path.of("../victim"));
            r = CliTesting.run("run", "--dt", "0.01", "--out", run.toString());
            assertEquals(2, r.code(), r.err());
            assertTrue(r.err().startsWith("handsim: --out " + run + ": not completing the publication a stopped writer left in "
                + stage.getParent() + ": " + run.resolve("sub") + " is a symbolic link"), r.err());
            CleanOutputTest.assertOneLineNoStackTrace("manifest", r.err());
            assertEquals(before, tree(victim));
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }
}
