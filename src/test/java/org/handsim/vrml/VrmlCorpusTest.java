package org.handsim.vrml;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.handsim.TestPaths;
import org.handsim.mesh.TessellationWalk;
import org.handsim.mesh.TriangleMesh;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * Walks the real-world VRML corpus of the shared data folder ({@link org.handsim.TestPaths#shared};
 * read in place, never copied):
 * every entry point of MANIFEST.md loads, its IndexedFaceSet triangle count as written equals
 * the manifest's independent count, and the tessellation walk gives finite bounds; every file in
 * {@code reject/} is refused with the specific message.
 *
 * <p>If the folder is absent the test FAILS, saying so, unless the system property
 * {@code handsim.allowMissingShared=true} or the environment variable
 * {@code HANDSIM_ALLOW_MISSING_SHARED=true} is set (then it is skipped with that reason). The
 * environment variable reaches the forked test JVM without any change to the build.
 */
class VrmlCorpusTest {
    /** The manifest has 31 entry points; fewer parsed rows means its format changed. */
    private static final int ENTRIES = 31;

    /**
     * Entries whose scene is exactly their IndexedFaceSets, each used once (no primitives, LOD,
     * Switch or USE of geometry): there the walk's triangles plus dropped zero-area ones must
     * equal the manifest count.
     */
    private static final List<String> PLAIN_IFS = List.of(
        "rl-examples_barrett-wam/barrett-wam-wrist.wrl", "rl-examples_puma560/unimation-puma560.wrl",
        "rl-examples_alpha1/alpha1.wrl", "openhrp3_pa10_3.wrl", "choreonoid_WAIST.wrl", "choreonoid_vase.wrl",
        "VRMLviewer_terrain_full_80k.wrl", "freewrl_14.wrl", "freewrl_40.wrl");

    private static Path corpus() {
        Path dir = TestPaths.shared().resolve("vrml-corpus");
        if (!Files.isDirectory(dir)) {
            String why = "VRML corpus folder " + dir + " is absent: the corpus test cannot run"
                + " (set HANDSIM_ALLOW_MISSING_SHARED=true or -Dhandsim.allowMissingShared=true to skip it)";
            if (Boolean.getBoolean("handsim.allowMissingShared") || "true".equalsIgnoreCase(System.getenv("HANDSIM_ALLOW_MISSING_SHARED"))) {
                Assumptions.assumeTrue(false, why);
            }
            fail(why);
        }
        return dir;
    }

    private record Entry(int number, String file, long ifsTriangles) {}

    /** Rows "| # | `file` | origin | license | files/bytes | IFS triangles (...) | what |". */
    private static List<Entry> entries(Path dir) throws IOException {
        List<Entry> out = new ArrayList<>();
        Pattern row = Pattern.compile("^\\|\\s*(\\d+)\\s*\\|\\s*`([^`]+)`\\s*\\|([^|]*)\\|([^|]*)\\|([^|]*)\\|\\s*([\\d,]+)");
        for (String line : Files.readAllLines(dir.resolve("MANIFEST.md"), StandardCharsets.UTF_8)) {
            Matcher m = row.matcher(line);
            if (m.find()) out.add(new Entry(Integer.parseInt(m.group(1)), m.group(2), Long.parseLong(m.group(6).replace(",", ""))));
        }
        assertEquals(ENTRIES, out.size(), "entry points parsed from MANIFEST.md");
        return out;
    }

    @TestFactory
    List<DynamicTest> everyEntryPointLoads() throws IOException {
        Path dir = corpus();
        List<DynamicTest> tests = new ArrayList<>();
        for (Entry e : entries(dir)) {
            tests.add(DynamicTest.dynamicTest("#" + e.number() + " " + e.file(), () -> {
                VrmlScene scene = new VrmlLoader().load(dir.resolve(e.file()));
                assertEquals(e.ifsTriangles(), scene.writtenIfsTriangles(), "IndexedFaceSet triangles as written (manifest count)");
                TessellationWalk.Result r = new TessellationWalk().run(scene.getSceneGroup());
                TriangleMesh m = r.merged();
                if (e.ifsTriangles() > 0) assertTrue(m.triangleCount() > 0, "triangles from the walk");
                if (PLAIN_IFS.contains(e.file())) {
                    assertEquals(e.ifsTriangles(), m.triangleCount() + r.degenerate, "walk triangles + dropped zero-area = manifest count");
                }
                for (double[] b : m.bounds()) for (double x : b) assertTrue(Double.isFinite(x), "finite bounds");
                for (String w : scene.warnings()) assertTrue(w.contains(": warning: "), w);
            }));
        }
        return tests;
    }

    @TestFactory
    List<DynamicTest> rejectFilesAreRefusedWithTheReason() {
        Path dir = corpus().resolve("reject");
        String[][] cases = {
            {"globe-3d_skotknot.wrl", "VRML 1.0 is not supported"},
            {"VRMLviewer_pi1246924519_007006045l.wrz", "VRML 1.0 is not supported"},
            {"choreonoid_J1.wrl", "not a VRML97 file: the first line is not the header '#VRML V2.0 utf8'"},
        };
        List<DynamicTest> tests = new ArrayList<>();
        for (String[] c : cases) {
            tests.add(DynamicTest.dynamicTest(c[0], () -> {
                Path p = dir.resolve(c[0]);
                assertTrue(Files.isRegularFile(p), "reject file present: " + p);
                VrmlParseException e = assertThrows(VrmlParseException.class, () -> new VrmlLoader().load(p));
                assertTrue(e.getMessage().startsWith(p + ":1:1: "), e.getMessage());
                assertTrue(e.detail().contains(c[1]), e.getMessage());
            }));
        }
        try (java.util.stream.Stream<Path> s = Files.list(dir)) {
            assertEquals(cases.length, s.count(), "every file in reject/ has a case");
        } catch (IOException e) {
            throw new AssertionError(e);
        }
        return tests;
    }

    @TestFactory
    List<DynamicTest> knownCorpusDetails() {
        Path dir = corpus();
        List<DynamicTest> tests = new ArrayList<>();
        tests.add(DynamicTest.dynamicTest("X3D field in entry 16 is a warning", () -> {
            VrmlScene s = new VrmlLoader().load(dir.resolve("freewrl_14.wrl"));
            assertEquals(1, s.warnings().size(), s.warnings().toString());
            assertTrue(s.warnings().get(0).contains("unknown field 'centerOfRotation' in Viewpoint"), s.warnings().get(0));
        }));
        tests.add(DynamicTest.dynamicTest("96 missing textures of entry 14 are warnings, gzip by content", () -> {
            VrmlScene s = new VrmlLoader().load(dir.resolve("VRMLviewer_terrain_full_80k.wrl"));
            assertEquals(96, s.warnings().stream().filter(w -> w.contains("texture not available")).count());
        }));
        tests.add(DynamicTest.dynamicTest("LOD of entry 31 shows the finest level, inlined from gzip files", () -> {
            VrmlScene s = new VrmlLoader().load(dir.resolve("web3dguide_worlds/tut38.wrl"));
            assertEquals(4, s.files().size(), s.files().toString());
            assertEquals(2144, VrmlTesting.walk(s).merged().triangleCount()); // lump_near
            assertEquals(132, new TessellationWalk().run(new VrmlLoader().lodLevel(2).load(dir.resolve("web3dguide_worlds/tut38.wrl"))
                .getSceneGroup()).merged().triangleCount()); // lump_far
        }));
        tests.add(DynamicTest.dynamicTest("EXTERNPROTO of entry 21 resolves to the local file", () -> {
            VrmlScene s = new VrmlLoader().load(dir.resolve("openvrml_ExternPROTO/ExternPROTO.wrl"));
            assertTrue(s.warnings().isEmpty(), s.warnings().toString());
            assertEquals(2, s.files().size());
        }));
        tests.add(DynamicTest.dynamicTest("unresolvable EXTERNPROTO of entry 22 is a warning and an empty scene", () -> {
            VrmlScene s = new VrmlLoader().load(dir.resolve("openvrml_unrecognized-externproto.wrl"));
            assertFalse(s.warnings().isEmpty());
            assertTrue(s.warnings().get(0).contains("EXTERNPROTO UnrecognizedNode not resolved"), s.warnings().get(0));
            assertEquals(0, s.getSceneGroup().numChildren());
        }));
        tests.add(DynamicTest.dynamicTest("entry 8 is in millimetres scaled to metres by a Transform", () -> {
            TriangleMesh m = TessellationWalk.mesh(new VrmlLoader().load(dir.resolve("choreonoid_hand_base.wrl")).getSceneGroup());
            double[][] b = m.bounds();
            assertTrue(b[1][0] - b[0][0] < 1.0 && b[1][0] - b[0][0] > 0.01, "size in metres: " + (b[1][0] - b[0][0]));
        }));
        return tests;
    }
}
