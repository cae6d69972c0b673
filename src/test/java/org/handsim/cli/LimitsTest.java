package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.zip.GZIPOutputStream;
import org.handsim.TestPaths;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The limits that hold on every path, each in a child JVM with a small heap (they need seconds):
 * the Shape bomb, {@code quality} with 5 000 contacts and with 4 contacts of 256 edges,
 * {@code grasp --edges 1024}, {@code collide} of a 358 800-triangle sphere with itself, and a
 * plan trial on a flat 1 000-gon. Before: 6.0 GB and 147 s; out of memory after 184 s; out of
 * memory; 34 s and 5.2 GB then out of memory; nothing in 300 s; 100 s a trial. The wall-time
 * bounds below only catch a hang; the figures are printed (docs: README, "Limits").
 */
@Tag("slow")
class LimitsTest {
    static final long MB = 1L << 20;
    static Path dir;

    @BeforeAll
    static void folder() throws Exception {
        dir = Files.createTempDirectory("handsim-limits");
    }

    @AfterAll
    static void clean() throws Exception {
        ChildJvm.deleteTree(dir);
    }

    static void oneLine(ChildJvm.Result r) {
        assertFalse(r.err().contains("\tat ") || r.err().contains("Exception") || r.err().contains("out of memory"), r.err());
    }

    static String last(ChildJvm.Result r) {
        return r.err().substring(r.err().lastIndexOf('\n') + 1);
    }

    /** 2e6 {@code Shape { geometry Box {} }} in a 126 KB gzip: refused while parsing, under 300 MB resident. */
    @Test
    void theShapeBombIsRefusedWhileParsing() throws Exception {
        Path bomb = dir.resolve("shapes.wrl");
        try (OutputStream o = new GZIPOutputStream(Files.newOutputStream(bomb), 1 << 16)) {
            o.write("#VRML V2.0 utf8\n".getBytes(StandardCharsets.US_ASCII));
            byte[] shape = "Shape { geometry Box {} }\n".getBytes(StandardCharsets.US_ASCII);
            for (int i = 0; i < 2_000_000; i++) o.write(shape);
        }
        assertTrue(Files.size(bomb) < 200_000, "bomb of " + Files.size(bomb) + " bytes");
        long t0 = System.nanoTime();
        ChildJvm.Result r = ChildJvm.run(dir, "512m", 3, "mesh", bomb.toString());
        double s = (System.nanoTime() - t0) / 1e9;
        assertEquals(3, r.code(), r.err());
        assertEquals(bomb + ":50002:1: more than 50000 Shape nodes (the limit of shapes per object file)", r.err());
        assertTrue(r.peakBytes() > 0 && r.peakBytes() < 300 * MB, "peak resident " + r.peakBytes() / MB + " MB");
        System.out.printf("LimitsTest: Shape bomb refused in %.1f s, peak resident %d MB%n", s, r.peakBytes() / MB);
        // the same through a scenario's object
        Path scenario = Files.writeString(dir.resolve("bomb.json"), Files.readString(TestPaths.root().resolve("scenarios/paper-breakaway.json"))
            .replaceFirst("\"file\": *\"[^\"]*\"", "\"file\": \"" + bomb + "\""));
        ChildJvm.Result run = ChildJvm.run(dir, "512m", 3, "run", scenario.toString(), "--out", dir.resolve("out").toString());
        assertEquals(3, run.code(), run.err());
        assertTrue(run.peakBytes() < 300 * MB, "peak resident " + run.peakBytes() / MB + " MB");
    }

    /**
     * A scenario naming a 3 GB object file (sparse): {@code run} refuses it with the limit of
     * object files, the line {@code mesh} prints for the same file, exit 3 (before: out of memory,
     * "give Java more heap", exit 1, after reading it whole).
     */
    @Test
    void aThreeGigabyteObjectIsRefusedByItsSizeInEveryCommand() throws Exception {
        for (String name : new String[] {"huge.stl", "huge.wrl"}) {
            Path huge = dir.resolve(name);
            try (java.io.RandomAccessFile f = new java.io.RandomAccessFile(huge.toFile(), "rw")) {
                f.setLength(3L << 30);
            }
            try {
                ChildJvm.Result mesh = ChildJvm.run(dir, "256m", 3, "mesh", huge.toString());
                assertEquals(3, mesh.code(), mesh.err());
                String limit = "is 3221225472 bytes, more than the limit of object files (268435456 bytes)";
                assertTrue(mesh.err().endsWith(limit), mesh.err());
                Path scenario = Files.writeString(dir.resolve("huge.json"), Files.readString(TestPaths.root().resolve("scenarios/paper-breakaway.json"))
                    .replaceFirst("\"file\": *\"[^\"]*\"", "\"file\": \"" + huge + "\""));
                ChildJvm.Result run = ChildJvm.run(dir, "256m", 3, "run", scenario.toString(), "--out", dir.resolve("out").toString());
                assertEquals(3, run.code(), run.err());
                oneLine(run);
                assertEquals(mesh.err().substring(mesh.err().indexOf(huge.toString())), run.err().substring(run.err().indexOf(huge.toString())));
                assertFalse(Files.exists(dir.resolve("out")));
            } finally {
                Files.deleteIfExists(huge);
            }
        }
    }

    /** 5 000 contacts: refused at once (more than 1 600 distinct wrenches), in -Xmx512m; 100 are answered with progress lines. */
    @Test
    void qualityTakesAnyNumberOfContactsInBoundedTimeAndMemory() throws Exception {
        Path many = contacts("c5000.csv", 5000, 1);
        long t0 = System.nanoTime();
        ChildJvm.Result r = ChildJvm.run(dir, "512m", 1, "quality", many.toString());
        double s = (System.nanoTime() - t0) / 1e9;
        assertEquals(2, r.code(), r.err());
        assertEquals("handsim: " + many + ": 5000 contacts x 8 cone edges give 40000 distinct wrenches, more than the limit of 1600 for the"
            + " whole grasp wrench space (its facets grow about as the square of the wrenches: 1 600 take 30 s and 300 MB); use fewer"
            + " contacts: at most 200 at the default 8 cone edges", r.err());
        assertTrue(s < 60, s + " s");
        System.out.printf("LimitsTest: quality of 5 000 contacts refused in %.1f s (whole JVM), peak resident %d MB%n", s, r.peakBytes() / MB);
        // 5 000 rows of 150 distinct contacts: identical wrenches count once, so this one is answered
        StringBuilder rows = new StringBuilder("x,y,z,nx,ny,nz\n");
        java.util.List<String> lines = Files.readAllLines(contacts("c150.csv", 150, 2));
        for (int i = 0; i < 5000; i++) rows.append(lines.get(1 + i % 150)).append('\n');
        Path repeated = Files.writeString(dir.resolve("repeated.csv"), rows);
        t0 = System.nanoTime();
        ChildJvm.Result a = ChildJvm.run(dir, "512m", 3, "quality", repeated.toString());
        double sa = (System.nanoTime() - t0) / 1e9;
        assertEquals(0, a.code(), a.err());
        assertTrue(a.out().startsWith("{\"contacts\":5000,\"wrenches\":40000,\"force_closure\":true"), a.out());
        assertTrue(a.err().isEmpty() || a.err().startsWith("handsim quality: 5000 contacts, 40000 wrenches: "), a.err());
        System.out.printf("LimitsTest: quality of 5 000 rows (150 distinct contacts) answered in %.1f s, peak resident %d MB%n", sa,
            a.peakBytes() / MB);
    }

    /** Four contacts of 256 edges (points on four circles): 1 024 wrenches whose hull passes 2^20 facets, refused in -Xmx512m. */
    @Test
    void aHullOfTooManyFacetsIsRefusedNotOutOfMemory() throws Exception {
        Path four = contacts("c4.csv", 4, 3);
        // progress from the start, so the line is there however fast the machine reaches the limit
        ChildJvm.Result r = ChildJvm.run(dir, "512m", List.of("-Dhandsim.quality.progressAfterS=0"), 3,
            "quality", four.toString(), "--edges", "256");
        assertEquals(2, r.code(), r.err());
        oneLine(r);
        assertEquals("handsim: " + four + ": 4 contacts x 256 cone edges: the convex hull of 1024 points needs more than 1048576 facets"
            + " (the limit of its memory, about 175 MB); use fewer contacts or --edges", last(r));
        assertTrue(r.err().contains("handsim quality: 4 contacts, 1024 wrenches: "), "progress: " + r.err());
        System.out.printf("LimitsTest: 4 contacts x 256 edges refused, peak resident %d MB%n", r.peakBytes() / MB);
    }

    /** grasp --edges 1024 (the documented maximum) on the mug: the run completes, the wrench space is refused naming the edges that fit. */
    @Test
    void graspWithTheMostEdgesIsBounded() throws Exception {
        ChildJvm.Result r = ChildJvm.run(dir, "512m", 5, "grasp", TestPaths.root().resolve("scenarios/mug-grasp.json").toString(), "--edges", "1024");
        assertEquals(2, r.code(), r.err());
        oneLine(r);
        assertTrue(r.err().matches("handsim: [0-9]+ contacts x 1024 cone edges give [0-9]+ distinct wrenches, more than the limit of 1600 .*"
            + "; use fewer contacts, or at most [0-9]+ cone edges \\(--edges\\) for [0-9]+ contacts"), r.err());
        System.out.printf("LimitsTest: grasp --edges 1024 refused, peak resident %d MB%n", r.peakBytes() / MB);
    }

    /** A 358 800-triangle sphere on itself: phases announced, refused at 100 000 intersecting pairs in seconds. */
    @Test
    void collideOfCoincidentMeshesIsBounded() throws Exception {
        Path prim = Files.writeString(dir.resolve("ball.wrl"), "#VRML V2.0 utf8\nShape { geometry Sphere { radius 0.04 } }\n");
        Path stl = dir.resolve("ball.stl");
        CliTesting.Run made = CliTesting.run("mesh", prim.toString(), "--divisions", "600", "--stl", stl.toString());
        assertTrue(made.out().contains("\"triangles\":358800"), made.out());
        long t0 = System.nanoTime();
        ChildJvm.Result r = ChildJvm.run(dir, "1g", 3, "collide", stl.toString(), stl.toString(), "--units", "m");
        double s = (System.nanoTime() - t0) / 1e9;
        assertEquals(2, r.code(), r.err());
        oneLine(r);
        String[] lines = r.err().split("\n");
        assertEquals("handsim collide: building the k-DOP trees of 358800 + 358800 triangles", lines[0]);
        assertTrue(lines[1].startsWith("handsim collide: trees built in "), lines[1]);
        assertEquals("handsim collide: " + stl + " and " + stl + " at --pose-b 0,0,0,0,0,0 intersect in more than 100000 triangle pairs"
            + " (coincident or deeply interpenetrating meshes; the limit of collide, whose contact patches join every pair's segments);"
            + " move B with --pose-b", lines[2]);
        System.out.printf("LimitsTest: coincident 358 800-triangle spheres refused in %.1f s%n", s);
        // crossing at 40 mm: 3 582 pairs along a circle, answered
        ChildJvm.Result x = ChildJvm.run(dir, "1g", 3, "collide", stl.toString(), stl.toString(), "--units", "m", "--pose-b", "0.04,0,0,0,0,0");
        assertEquals(0, x.code(), x.err());
        assertTrue(x.out().contains("\"pairs\":3582"), x.out());
    }

    /** A flat 1 000-gon: its width is 0, so the tunnelling guard once took 100 000 substeps a step (about 100 s a trial). */
    @Test
    void aFlatPolygonPlansInSeconds() throws Exception {
        StringBuilder obj = new StringBuilder();
        for (int i = 0; i < 1000; i++) {
            double a = 2 * Math.PI * i / 1000;
            obj.append(String.format(java.util.Locale.ROOT, "v %.6f %.6f 0%n", 0.05 * Math.cos(a), 0.05 * Math.sin(a)));
        }
        obj.append('f');
        for (int i = 1; i <= 1000; i++) obj.append(' ').append(i);
        Path gon = Files.writeString(dir.resolve("gon.obj"), obj.append('\n'));
        long t0 = System.nanoTime();
        ChildJvm.Result r = ChildJvm.run(dir, "512m", 3, "plan", gon.toString(), "--trials", "4", "--threads", "1", "--out", dir.resolve("plan").toString());
        double s = (System.nanoTime() - t0) / 1e9;
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().startsWith("plan-gon: 4 trials (0 failed)"), r.out());
        System.out.printf("LimitsTest: 4 plan trials on a flat 1 000-gon in %.1f s (whole JVM)%n", s);
    }

    /** n contacts at random points of a 50 mm sphere, normals inward (seeded). */
    static Path contacts(String name, int n, long seed) throws Exception {
        Random rnd = new Random(seed);
        StringBuilder sb = new StringBuilder("x,y,z,nx,ny,nz\n");
        for (int i = 0; i < n; i++) {
            double z = 2 * rnd.nextDouble() - 1, t = 2 * Math.PI * rnd.nextDouble(), r = Math.sqrt(1 - z * z);
            double x = r * Math.cos(t), y = r * Math.sin(t);
            sb.append(String.format(java.util.Locale.ROOT, "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f%n", 0.05 * x, 0.05 * y, 0.05 * z, -x, -y, -z));
        }
        return Files.writeString(dir.resolve(name), sb);
    }
}
