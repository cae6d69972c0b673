package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.handsim.text.Json;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** {@code handsim mesh}: output contract, exit codes, --obj, --scale, --help. */
class MeshCommandTest {
    private Path dir;
    private String out, err;

    @BeforeEach
    void makeDir() throws IOException {
        dir = Files.createTempDirectory("handsim-mesh-cmd").toRealPath();
    }

    @AfterEach
    void removeDir() throws IOException {
        VrmlTesting.deleteTree(dir);
    }

    private int run(String... args) {
        CliTesting.Run r = CliTesting.run(args);
        out = r.out();
        err = r.err();
        return r.code();
    }

    private Path file(String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.write(p, text.getBytes(StandardCharsets.UTF_8));
        return p;
    }

    @SuppressWarnings("unchecked")
    private Map<String, Object> json() {
        String[] lines = out.split("\n");
        assertEquals(1, lines.length, "exactly one line: " + out);
        return (Map<String, Object>) Json.parse("stdout", lines[0]);
    }

    @Test
    void boxReportsTheContract() throws IOException {
        Path p = file("box.wrl", "#VRML V2.0 utf8\nShape { geometry Box { size 1 2 3 } }\n");
        // 3 units across would be judged millimetres by its size (UnitRule): this box is in metres
        assertEquals(0, run("mesh", p.toString(), "--units", "m"));
        assertEquals("", err);
        Map<String, Object> j = json();
        assertEquals(List.of("file", "shapes", "triangles", "vertices", "degenerate", "area_m2", "volume_m3", "closed", "bounds", "load_ms", "units"),
            List.copyOf(j.keySet()));
        assertEquals(p.toString(), j.get("file"));
        assertEquals(1.0, j.get("shapes"));
        assertEquals(12.0, j.get("triangles"));
        assertEquals(8.0, j.get("vertices"));
        assertEquals(0.0, j.get("degenerate"));
        assertEquals(22.0, (Double) j.get("area_m2"), 1e-12);
        assertEquals(6.0, (Double) j.get("volume_m3"), 1e-12);
        assertEquals(Boolean.TRUE, j.get("closed"));
        assertEquals(List.of(List.of(-0.5, -1.0, -1.5), List.of(0.5, 1.0, 1.5)), j.get("bounds"));
        assertTrue((Double) j.get("load_ms") >= 0);
    }

    @Test
    void scaleDivisionsAndObjOutput() throws IOException {
        Path p = file("ball.wrl", "#VRML V2.0 utf8\nShape { geometry Sphere { radius 50 } }\n");
        Path obj = dir.resolve("out/ball.obj");
        assertEquals(0, run("mesh", p.toString(), "--scale", "0.001", "--divisions", "64", "--obj", obj.toString()));
        Map<String, Object> j = json();
        double r = 0.05;
        assertEquals(4 * Math.PI * r * r, (Double) j.get("area_m2"), 0.01 * 4 * Math.PI * r * r);
        assertEquals(4.0 / 3 * Math.PI * r * r * r, (Double) j.get("volume_m3"), 0.01 * 4.0 / 3 * Math.PI * r * r * r);
        List<String> lines = Files.readAllLines(obj);
        assertEquals(((Double) j.get("vertices")).longValue(), lines.stream().filter(l -> l.startsWith("v ")).count());
        assertEquals(((Double) j.get("triangles")).longValue(), lines.stream().filter(l -> l.startsWith("f ")).count());
        assertTrue(Files.list(obj.getParent()).noneMatch(f -> f.getFileName().toString().endsWith(".partial")));
    }

    @Test
    void openSurfaceHasNullVolumeAndWarningsGoToStderr() throws IOException {
        Path p = file("open.wrl", "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { solidity 1\n"
            + " coord Coordinate { point [ 0 0 0, 1 0 0, 0 1 0 ] } coordIndex [ 0 1 2 ] } }\n");
        assertEquals(0, run("mesh", p.toString(), "--units", "m"));
        Map<String, Object> j = json();
        assertEquals(Boolean.FALSE, j.get("closed"));
        assertTrue(j.containsKey("volume_m3") && j.get("volume_m3") == null);
        assertTrue(out.contains("\"volume_m3\":null"), out);
        assertTrue(err.startsWith(p + ":2:35: warning: unknown field 'solidity'"), err);
    }

    @Test
    void unloadableFileExitsThreeWithOneLine() throws IOException {
        Path p = file("bad.wrl", "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet {\n coord Coordinate { point [ 0 0 0 ] }\n coordIndex [ 0 5 0 ] } }\n");
        assertEquals(3, run("mesh", p.toString()));
        assertEquals("", out);
        assertEquals(p + ":4:17: coordIndex[1] = 5 in IndexedFaceSet is out of range: the Coordinate has 1 entry (0..0)", err);
        assertEquals(3, run("mesh", dir.resolve("absent.wrl").toString()));
        assertEquals(dir.resolve("absent.wrl") + ":1:1: cannot read the file: no such file", err);
    }

    @Test
    void badArgumentsExitTwo() throws IOException {
        Path p = file("box.wrl", "#VRML V2.0 utf8\nShape { geometry Box { } }\n");
        assertEquals(2, run("mesh"));
        assertEquals(2, run("mesh", p.toString(), "--divisions", "2"));
        assertTrue(err.contains("--divisions must be in 3..100000"), err);
        assertEquals(2, run("mesh", p.toString(), "--scale", "-1"));
        assertEquals(2, run("mesh", p.toString(), "--scale", "abc"));
        assertEquals(2, run("mesh", p.toString(), "--frobnicate"));
    }

    @Test
    void helpDescribesTheCommand() {
        assertEquals(0, run("mesh", "--help"));
        assertTrue(out.contains("--divisions") && out.contains("--scale") && out.contains("--obj") && out.contains("volume_m3"), out);
    }

    @Test
    void useBombIsRefusedBeforeExpanding() throws IOException {
        // each level USEs the previous one twice: 2^40 boxes from a 2 kB file
        StringBuilder sb = new StringBuilder("#VRML V2.0 utf8\nDEF L0 Shape { geometry Box { } }\n");
        for (int i = 1; i <= 40; i++) sb.append("DEF L").append(i).append(" Group { children [ USE L").append(i - 1).append(" USE L").append(i - 1).append(" ] }\n");
        Path p = file("bomb.wrl", sb.toString());
        assertEquals(3, run("mesh", p.toString()));
        assertTrue(err.startsWith(p + ":1:1: the scene expands to "), err);
        assertEquals(1, err.split("\n").length, err);
    }
}
