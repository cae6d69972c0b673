package org.handsim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.handsim.TestPaths;
import org.handsim.cli.ChildJvm;
import org.handsim.model.Simulation;
import org.junit.jupiter.api.Test;

/**
 * Every object file goes through the input gate once: a scenario whose object's units are judged
 * by size loads the file at scale 1 (the units) and at the scenario's scale (the model), and the
 * mesh cache keys its entries by the file's bytes, all from one read. Counted by the bytes this
 * process read ({@code rchar} of /proc/self/io), with a binary STL of 4 MB so that what else the
 * load reads (the scenario, the hand's models, each cache entry once on a hit) is told apart from
 * one more read of it (before: three reads per load, and a load per scale).
 */
class ReadOnceTest {
    /** Bytes this process has read through read(2) and friends so far. */
    static long bytesRead() throws IOException {
        for (String l : Files.readAllLines(Path.of("/proc/self/io"))) {
            if (l.startsWith("rchar:")) return Long.parseLong(l.substring(6).trim());
        }
        throw new IllegalStateException("no rchar in /proc/self/io");
    }

    /** A binary STL of {@code n} thin triangles in millimetres (a fan 100 mm across: units judged mm). */
    static Path stl(Path dir, int n) throws IOException {
        ByteBuffer b = ByteBuffer.allocate(84 + 50 * n).order(ByteOrder.LITTLE_ENDIAN);
        b.position(80);
        b.putInt(n);
        for (int i = 0; i < n; i++) {
            double a = 2 * Math.PI * i / n, c = 2 * Math.PI * (i + 1) / n;
            b.putFloat(0).putFloat(0).putFloat(1);
            b.putFloat(0).putFloat(0).putFloat(300);
            b.putFloat((float) (50 * Math.cos(a))).putFloat((float) (50 * Math.sin(a))).putFloat(300);
            b.putFloat((float) (50 * Math.cos(c))).putFloat((float) (50 * Math.sin(c))).putFloat(300);
            b.putShort((short) 0);
        }
        return Files.write(dir.resolve("fan.stl"), b.array());
    }

    @Test
    void aScenariosObjectFileIsReadOnce() throws Exception {
        Path dir = Files.createTempDirectory("handsim-read-once");
        String before = System.getProperty("handsim.cache");
        System.setProperty("handsim.cache", dir.resolve("cache").toString());
        try {
            Path object = stl(dir, 80_000);
            long size = Files.size(object);
            Path scenario = Files.writeString(dir.resolve("fan.json"), Files.readString(TestPaths.root().resolve("scenarios/paper-breakaway.json"))
                .replaceFirst("\"file\": *\"[^\"]*\"", "\"file\": \"" + object + "\"").replaceFirst("\"units\": *\"m\"", "\"units\": \"auto\""));
            for (int pass = 0; pass < 2; pass++) {   // the cache's miss, then its hit (the entry read instead of a tessellation)
                Path copy = Files.copy(object, dir.resolve("fan-" + pass + ".stl"));   // a new path: nothing in memory yet
                Path s = Files.writeString(dir.resolve("s" + pass + ".json"), Files.readString(scenario).replace(object.toString(), copy.toString()));
                long r0 = bytesRead();
                Scenario sc = Scenario.load(s);
                Simulation.model(sc, false);
                long read = bytesRead() - r0;
                assertEquals(Scenario.Units.MM, sc.object().units(), "the size judged the units: the file was loaded at scale 1 too");
                // once: the file, then (the hit) each cache entry once, the scenario and the hand's models (40 KB)
                long entries = 0;
                if (pass == 1) {
                    for (String e : TestPaths.names(dir.resolve("cache/meshes"))) entries += Files.size(dir.resolve("cache/meshes").resolve(e));
                }
                long allowed = size + entries + 2_000_000;
                assertTrue(read < allowed, "pass " + pass + ": read " + read + " bytes for a file of " + size + " (twice would be " + 2 * size + ")");
                assertTrue(read >= size, "read " + read + " bytes, less than the file");
            }
            assertEquals(List.of("meshes"), TestPaths.names(dir.resolve("cache")));
        } finally {
            if (before == null) System.clearProperty("handsim.cache"); else System.setProperty("handsim.cache", before);
            ChildJvm.deleteTree(dir);
        }
    }
}
