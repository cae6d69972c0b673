package org.handsim.bench;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Random;
import org.handsim.mesh.TessellationWalk;
import org.handsim.mesh.TriangleMesh;
import org.handsim.vrml.VrmlLoader;
import org.handsim.vrml.VrmlScene;

/**
 * Suite "vrml": parse + tessellate throughput of the public path (VRML file ⇒ VrmlLoader ⇒
 * BranchGroup ⇒ TessellationWalk ⇒ TriangleMesh), in MB/s of file text and triangles/s, on
 * the largest corpus file (choreonoid_WAIST.wrl, 3.0 MB, 67 210 triangles), the gzip terrain
 * (VRMLviewer_terrain_full_80k.wrl, 1.6 MB gzip ⇒ 7.1 MB, 84 231 triangles) and a generated
 * 1 000 000-triangle IndexedFaceSet (written to build/bench/, seed 345, never committed).
 * Also reported separately: loading alone (parse + Java3D scene) and the walk alone, and the
 * first (cold) load of the 1M file in this JVM. Goal: the 1M file in under 2 s.
 */
final class VrmlBench implements BenchMain.Suite {
    /** Cells of the generated grid: 500 x 1000 cells x 2 = 1 000 000 triangles. */
    static final int NX = 500, NZ = 1000;

    @Override
    public void run() throws Exception {
        Path root = Path.of(System.getProperty("handsim.root", "."));
        Path corpus = Path.of(System.getProperty("handsim.shared", root.resolve("../shared").toString())).resolve("vrml-corpus");
        Path big = root.resolve("build/bench/ifs-1m.wrl");
        generate(big);
        // the cold first load, before anything is warm
        long t0 = System.nanoTime();
        VrmlScene first = new VrmlLoader().load(big);
        TriangleMesh firstMesh = TessellationWalk.mesh(first.getSceneGroup());
        double coldMs = (System.nanoTime() - t0) / 1e6;
        System.out.printf(Locale.ROOT, "generated 1M IFS: %s (%.1f MB, %d triangles); first (cold JVM) load + walk: %.0f ms%n",
            big.getFileName(), Files.size(big) / 1e6, firstMesh.triangleCount(), coldMs);
        if (Files.isDirectory(corpus)) {
            suite("choreonoid_WAIST.wrl", corpus.resolve("choreonoid_WAIST.wrl"), 2000, 11);
            suite("VRMLviewer_terrain_full_80k.wrl (gzip)", corpus.resolve("VRMLviewer_terrain_full_80k.wrl"), 2000, 11);
        } else {
            System.out.println("corpus folder " + corpus + " absent: corpus files not measured");
        }
        suite("generated 1M-triangle IFS", big, 3000, 7);
    }

    private static void suite(String label, Path file, long warmupMs, int samples) throws IOException {
        long bytes = Files.size(file);
        VrmlScene probe = new VrmlLoader().load(file);
        long plainBytes = 0;
        byte[] head = new byte[2];
        try (java.io.InputStream in = Files.newInputStream(file)) {
            if (in.read(head) == 2 && (head[0] & 0xff) == 0x1f && (head[1] & 0xff) == 0x8b) {
                try (java.io.InputStream g = new java.util.zip.GZIPInputStream(Files.newInputStream(file))) {
                    byte[] buf = new byte[1 << 16];
                    int n;
                    while ((n = g.read(buf)) > 0) plainBytes += n;
                }
            }
        }
        long text = plainBytes > 0 ? plainBytes : bytes;
        long tris = TessellationWalk.mesh(probe.getSceneGroup()).triangleCount();
        Bench.Result full = Bench.measure("vrml " + label + ": load + walk", () -> {
            VrmlScene s = new VrmlLoader().load(file);
            return TessellationWalk.mesh(s.getSceneGroup()).triangleCount();
        }, warmupMs, samples, 1);
        Bench.Result load = Bench.measure("vrml " + label + ": load only (parse + Java3D scene)", () -> {
            VrmlScene s = new VrmlLoader().load(file);
            return s.getSceneGroup().numChildren();
        }, warmupMs / 2, samples, 1);
        Bench.Result walk = Bench.measure("vrml " + label + ": walk only", () -> TessellationWalk.mesh(probe.getSceneGroup()).triangleCount(),
            warmupMs / 2, samples, 1);
        double s = full.medianNs / 1e9;
        System.out.printf(Locale.ROOT, "  => %s: %.1f MB text%s, %d triangles: median %.1f ms = %.1f MB/s, %.2f M triangles/s"
                + " (load %.1f ms, walk %.1f ms)%n",
            label, text / 1e6, plainBytes > 0 ? String.format(Locale.ROOT, " (%.1f MB gzip)", bytes / 1e6) : "", tris,
            full.medianMs(), text / 1e6 / s, tris / 1e6 / s, load.medianMs(), walk.medianMs());
    }

    /** Writes a 1 000 000-triangle IndexedFaceSet height field (seed 345) unless it is already there. */
    static void generate(Path p) throws IOException {
        if (Files.isRegularFile(p) && Files.size(p) > 30_000_000) return;
        Files.createDirectories(p.getParent());
        Random r = new Random(345);
        Path tmp = p.resolveSibling(p.getFileName() + ".partial");
        try (Writer w = new BufferedWriter(Files.newBufferedWriter(tmp, StandardCharsets.US_ASCII), 1 << 20)) {
            w.write("#VRML V2.0 utf8\n# generated by VrmlBench: " + (2 * NX * NZ) + " triangles\n");
            w.write("Shape { geometry IndexedFaceSet {\n coord Coordinate { point [\n");
            StringBuilder sb = new StringBuilder(64);
            for (int j = 0; j <= NZ; j++) {
                for (int i = 0; i <= NX; i++) {
                    sb.setLength(0);
                    sb.append(String.format(Locale.ROOT, "%.5f %.5f %.5f,\n", i * 1e-3, r.nextDouble() * 1e-2, j * 1e-3));
                    w.write(sb.toString());
                }
            }
            w.write(" ] }\n coordIndex [\n");
            int n = NX + 1;
            for (int j = 0; j < NZ; j++) {
                for (int i = 0; i < NX; i++) {
                    int a = i + j * n;
                    w.write(a + " " + (a + n) + " " + (a + n + 1) + " -1 " + a + " " + (a + n + 1) + " " + (a + 1) + " -1\n");
                }
            }
            w.write(" ]\n} }\n");
        }
        Files.move(tmp, p, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
    }
}
