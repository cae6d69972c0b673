package org.handsim.vrml;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.handsim.TestPaths;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * Bad input must give {@code FILE:LINE:COL: message}: never a hang (a guard of 60 s stops one;
 * each file takes milliseconds), a StackOverflowError or an OutOfMemoryError. The small cases are files in
 * {@code src/test/resources/vrml/bad/} listed with their expected position and message in
 * {@code expected.tsv} (every file must be listed); the huge ones are generated here.
 */
class MalformedVrmlTest {
    private static final Duration LIMIT = Duration.ofSeconds(60);
    private static final Path BAD = TestPaths.root().resolve("src/test/resources/vrml/bad");

    @BeforeAll
    static void warmUp() {
        VrmlTesting.load("Shape { geometry Box { } }"); // Java3D's class initialisation is not the parser's time
    }

    private static VrmlParseException refused(Path file) {
        return assertTimeoutPreemptively(LIMIT, () -> assertThrows(VrmlParseException.class, () -> new VrmlLoader().load(file)),
            "a hang (no error within " + LIMIT + "): " + file);
    }

    private static void assertMessage(VrmlParseException e, Path file, String lineCol, String fragment) {
        String m = e.getMessage();
        assertFalse(m.contains("\n"), "one line: " + m);
        assertTrue(m.startsWith(file + ":" + lineCol + ": "), "expected " + file + ":" + lineCol + ": ... but got " + m);
        assertTrue(e.detail().contains(fragment), "expected '" + fragment + "' in " + m);
        assertEquals(file.toString(), e.file());
    }

    @TestFactory
    List<DynamicTest> everyBadFileIsRefusedWithItsMessage() throws IOException {
        Map<String, String[]> expected = new TreeMap<>();
        for (String line : Files.readAllLines(BAD.resolve("expected.tsv"), StandardCharsets.UTF_8)) {
            if (line.startsWith("#") || line.isBlank()) continue;
            String[] f = line.split("\t");
            assertEquals(3, f.length, "expected.tsv line: " + line);
            expected.put(f[0], f);
        }
        List<String> files = new ArrayList<>();
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(BAD, "*.wrl")) {
            ds.forEach(p -> files.add(p.getFileName().toString()));
        }
        assertEquals(new java.util.TreeSet<>(expected.keySet()), new java.util.TreeSet<>(files), "every bad file is listed in expected.tsv, and only those");
        assertTrue(files.size() >= 30, "at least 30 malformed files, found " + files.size());
        List<DynamicTest> tests = new ArrayList<>();
        for (String[] f : expected.values()) {
            tests.add(DynamicTest.dynamicTest(f[0], () -> {
                Path p = BAD.resolve(f[0]);
                assertMessage(refused(p), p, f[1], f[2]);
            }));
        }
        return tests;
    }

    /** Writes a generated bad file under build/tmp/vrml-bad. */
    private static Path generated(String name, byte[] bytes) throws IOException {
        Path dir = TestPaths.root().resolve("build/tmp/vrml-bad");
        Files.createDirectories(dir);
        return Files.write(dir.resolve(name), bytes);
    }

    private static Path generated(String name, String text) throws IOException {
        return generated(name, text.getBytes(StandardCharsets.UTF_8));
    }

    @Test
    void nesting100000LevelsIsRefusedAtTheDepthLimit() throws IOException {
        int levels = 100_000;
        StringBuilder sb = new StringBuilder(VrmlTesting.HEADER);
        for (int i = 0; i < levels; i++) sb.append("Group { children [\n");
        for (int i = 0; i < levels; i++) sb.append("] }\n");
        Path p = generated("deep100000.wrl", sb.toString());
        // the 1001st Group is on line 1002 (line 1 is the header)
        assertMessage(refused(p), p, "1002:1", "nested more than 1000 levels deep");
    }

    @Test
    void nesting100000TransformsWithoutBracketsIsRefused() throws IOException {
        StringBuilder sb = new StringBuilder(VrmlTesting.HEADER);
        for (int i = 0; i < 100_000; i++) sb.append("Transform { children ");
        Path p = generated("deep-transforms.wrl", sb.toString());
        assertMessage(refused(p), p, "2:21001", "nested more than 1000 levels deep");
    }

    @Test
    void hundredThousandOpenBracketsAreRefused() throws IOException {
        StringBuilder sb = new StringBuilder(VrmlTesting.HEADER + "Group { children [ ");
        for (int i = 0; i < 100_000; i++) sb.append("[ ");
        Path p = generated("brackets.wrl", sb.toString());
        assertMessage(refused(p), p, "2:20", "expected a node");
    }

    @Test
    void depthLimitHoldsOnAOneMegabyteThreadStack() throws Exception {
        // 998 Transforms + Shape + Box = 1000 levels (the limit) must load from a thread with an ordinary stack
        StringBuilder ok = new StringBuilder(VrmlTesting.HEADER);
        for (int i = 0; i < 998; i++) ok.append("Transform { translation 0 0 0.001 children [ ");
        ok.append("Shape { geometry Box { } } ");
        for (int i = 0; i < 998; i++) ok.append("] } ");
        Path p = generated("deep999.wrl", ok.toString());
        Throwable[] failure = new Throwable[1];
        long[] triangles = new long[1];
        Thread t = new Thread(null, () -> {
            try {
                triangles[0] = VrmlTesting.walk(new VrmlLoader().load(p)).triangleCount();
            } catch (Throwable e) {
                failure[0] = e;
            }
        }, "one-megabyte-stack", 1 << 20);
        t.start();
        t.join();
        if (failure[0] != null) throw new AssertionError("1000 levels on a 1 MB stack failed", failure[0]);
        assertEquals(12, triangles[0]);
    }

    @Test
    void exponentialProtoExpansionIsRefused() throws IOException {
        StringBuilder sb = new StringBuilder(VrmlTesting.HEADER + "PROTO P0 [ ] { Shape { geometry Box { } } }\n");
        for (int i = 1; i <= 30; i++) {
            sb.append("PROTO P").append(i).append(" [ ] { Group { children [ P").append(i - 1).append(" { } P").append(i - 1).append(" { } ] } }\n");
        }
        sb.append("P30 { }\n");
        Path p = generated("proto-bomb.wrl", sb.toString());
        VrmlParseException e = refused(p);
        assertTrue(e.getMessage().startsWith(p + ":"), e.getMessage());
        assertTrue(e.detail().contains("PROTO expansion creates more than"), e.getMessage());
    }

    @Test
    void extrusionClaimingBillionsOfPointsIsRefused() throws IOException {
        StringBuilder sb = new StringBuilder(VrmlTesting.HEADER + "Shape { geometry Extrusion {\n spine [");
        for (int i = 0; i < 5000; i++) sb.append(" 0 ").append(i).append(" 0,");
        sb.append(" ]\n crossSection [");
        for (int i = 0; i < 5000; i++) sb.append(' ').append(Math.cos(i * 1e-3)).append(' ').append(Math.sin(i * 1e-3)).append(',');
        sb.append(" ]\n} }\n");
        Path p = generated("extrusion-claims.wrl", sb.toString());
        assertMessage(refused(p), p, "2:18", "Extrusion would generate 25000000 points");
    }

    @Test
    void longRunsOfJunkAfterTheHeaderAreRefusedQuickly() throws IOException {
        java.util.Random r = new java.util.Random(345);
        byte[] junk = new byte[2_000_000];
        r.nextBytes(junk);
        byte[] head = VrmlTesting.HEADER.getBytes(StandardCharsets.US_ASCII);
        byte[] all = new byte[head.length + junk.length];
        System.arraycopy(head, 0, all, 0, head.length);
        System.arraycopy(junk, 0, all, head.length, junk.length);
        Path p = generated("junk-after-header.wrl", all);
        VrmlParseException e = refused(p);
        assertTrue(e.getMessage().startsWith(p + ":2:"), e.getMessage());
    }
}
