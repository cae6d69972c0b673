package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.handsim.TestPaths;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.ScenarioException;
import org.handsim.files.SpecialFiles;
import org.junit.jupiter.api.Test;

/**
 * A FIFO, a directory, a socket or a device given as any input — scenario, sweep file, sweep base,
 * sweep scenario, object file (a scenario's, a sweep row's, {@code mesh}, {@code collide},
 * {@code plan}), CSV input ({@code quality}, bulk {@code fk}), window script, the window's open —
 * is refused at once: exit 3, one line saying it "is not a regular file" and what it is. Before,
 * a FIFO hung each of them forever, and {@code run /dev/zero} filled 5 GB of memory.
 */
class SpecialFileInputsTest {
    static final Path PAPER = TestPaths.root().resolve("scenarios/paper-breakaway.json");
    static final Path CUBE = TestPaths.root().resolve("vrml/objects/cube.wrl");

    /** The command lines that read {@code f} as an input; {@code dir} holds what they need besides. */
    static List<String[]> commands(Path f, Path dir) throws Exception {
        String paper = Files.readString(PAPER);
        Path withObject = Files.writeString(dir.resolve("object-" + f.getFileName() + ".json"),
            paper.replaceFirst("\"file\": *\"[^\"]*\"", "\"file\": \"" + f + "\""));
        Path base = Files.writeString(dir.resolve("base-" + f.getFileName() + ".json"),
            "{\"name\": \"s\", \"base\": \"" + f + "\", \"runs\": [{\"label\": \"a\"}]}");
        Path scenarios = Files.writeString(dir.resolve("scenarios-" + f.getFileName() + ".json"),
            "{\"name\": \"s\", \"scenarios\": [\"" + f + "\"]}");
        Path out = dir.resolve("out");
        return List.of(
            new String[] {"run", f.toString(), "--out", out.toString()},
            new String[] {"run", withObject.toString(), "--out", out.toString()},
            new String[] {"sweep", f.toString(), "--out", out.toString()},
            new String[] {"sweep", base.toString(), "--out", out.toString()},
            new String[] {"sweep", scenarios.toString(), "--out", out.toString()},
            new String[] {"mesh", f.toString()},
            new String[] {"collide", f.toString(), CUBE.toString()},
            new String[] {"collide", CUBE.toString(), f.toString()},
            new String[] {"plan", f.toString(), "--trials", "1", "--out", out.toString()},
            new String[] {"quality", f.toString()},
            new String[] {"fk", "--input", f.toString(), "--output", out.resolve("fk.csv").toString()},
            new String[] {"grasp", f.toString()},
            new String[] {"gui", "--script", f.toString()});
    }

    @Test
    void everyInputRefusesASpecialFileAtOnce() throws Exception {
        try (SpecialFiles sf = new SpecialFiles()) {
            for (Map.Entry<String, Path> e : sf.all.entrySet()) {
                for (String[] cmd : commands(e.getValue(), sf.dir)) {
                    String what = String.join(" ", cmd);
                    CliTesting.Run r = assertTimeoutPreemptively(Duration.ofSeconds(60), () -> CliTesting.run(cmd), what);
                    assertEquals(3, r.code(), what + ": " + r.err());
                    assertTrue(r.err().contains("is not a regular file (" + e.getKey() + ")"), what + ": " + r.err());
                    assertFalse(r.err().contains("\n") || r.err().contains("Exception"), what + ": " + r.err());
                    assertFalse(Files.exists(sf.dir.resolve("out")), what + " wrote its output folder");
                }
            }
        }
    }

    /** A hand description file goes through the same gate. */
    @Test
    void aHandFileThatIsNotARegularFileIsRefused() throws Exception {
        try (SpecialFiles sf = new SpecialFiles()) {
            for (Map.Entry<String, Path> e : sf.all.entrySet()) {
                org.handsim.files.InputFile.InputFileException x = assertTimeoutPreemptively(Duration.ofSeconds(60),
                    () -> assertThrows(org.handsim.files.InputFile.InputFileException.class, () -> org.handsim.hand.HandDescription.load(e.getValue())));
                assertEquals(e.getValue() + ": is not a regular file (" + e.getKey() + ")", x.getMessage());
            }
        }
    }

    /**
     * An entry of the mesh cache that is a FIFO, a folder or a socket is a miss, at once: the mesh
     * is made from the file (before, a FIFO planted at an entry's name hung every load of that
     * object).
     */
    @Test
    void aMeshCacheEntryThatIsNotARegularFileIsAMiss() throws Exception {
        String before = System.getProperty("handsim.cache");
        try (SpecialFiles sf = new SpecialFiles()) {
            Path cache = sf.dir.resolve("cache");
            System.setProperty("handsim.cache", cache.toString());
            Path first = Files.copy(CUBE, sf.dir.resolve("cube-first.wrl"));
            org.handsim.mesh.TriangleMesh made = org.handsim.scenario.SceneMeshes.mesh(first, 24, 1.0);
            List<String> entries = TestPaths.names(cache.resolve("meshes"));
            assertEquals(1, entries.size(), entries.toString());
            Path entry = cache.resolve("meshes").resolve(entries.get(0));
            int n = 0;
            for (Map.Entry<String, Path> e : sf.all.entrySet()) {
                if (e.getKey().equals("a character device")) continue;   // cannot be moved into the folder
                Files.delete(entry);
                Files.move(e.getValue(), entry);
                Path again = Files.copy(CUBE, sf.dir.resolve("cube-" + n++ + ".wrl"));   // a new path: not in memory
                org.handsim.mesh.TriangleMesh m = assertTimeoutPreemptively(Duration.ofSeconds(60),
                    () -> org.handsim.scenario.SceneMeshes.mesh(again, 24, 1.0), e.getKey());
                assertEquals(made.triangleCount(), m.triangleCount(), e.getKey());
                Files.move(entry, e.getValue());
                Files.writeString(entry, "");
            }
            assertTrue(n >= 2, "special files tried: " + n);
        } finally {
            if (before == null) System.clearProperty("handsim.cache"); else System.setProperty("handsim.cache", before);
        }
    }

    /** The window's File ▸ Open reads the scenario through Scenario.load, as run does. */
    @Test
    void theWindowsOpenRefusesASpecialFile() throws Exception {
        try (SpecialFiles sf = new SpecialFiles()) {
            for (Map.Entry<String, Path> e : sf.all.entrySet()) {
                ScenarioException x = assertTimeoutPreemptively(Duration.ofSeconds(60),
                    () -> assertThrows(ScenarioException.class, () -> Scenario.load(e.getValue())));
                assertEquals(e.getValue() + ": is not a regular file (" + e.getKey() + ")", x.getMessage());
            }
        }
    }

    /** {@code run /dev/zero}: once 5.4 GB and "Requested array size exceeds VM limit". */
    @Test
    void devZeroIsACharacterDevice() {
        List<String> seen = new ArrayList<>();
        for (String cmd : new String[] {"run", "mesh", "sweep", "quality"}) {
            CliTesting.Run r = assertTimeoutPreemptively(Duration.ofSeconds(60), () -> CliTesting.run(cmd, "/dev/zero"));
            assertEquals(3, r.code(), cmd + ": " + r.err());
            assertTrue(r.err().contains("/dev/zero") && r.err().contains("is not a regular file (a character device)"), r.err());
            seen.add(r.err());
        }
        assertEquals(4, seen.size());
    }
}
