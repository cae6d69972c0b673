package org.handsim.vrml;

import java.io.IOException;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.stream.Stream;
import org.handsim.mesh.TessellationWalk;
import org.handsim.mesh.TriangleMesh;

/** Helpers shared by the VRML tests: load text, walk it, temporary folders. */
public final class VrmlTesting {
    private VrmlTesting() {}

    /** Relative tolerance for exact-arithmetic results (Box areas, transforms). */
    public static final double EXACT = 1e-12;

    public static final String HEADER = "#VRML V2.0 utf8\n";

    /** Loads VRML text (the header is added if missing). */
    public static VrmlScene load(String text) {
        return load(new VrmlLoader(), text);
    }

    public static VrmlScene load(VrmlLoader loader, String text) {
        String t = text.startsWith("#VRML") ? text : HEADER + text;
        return loader.load("test.wrl", new StringReader(t));
    }

    /** Loads VRML text and returns the whole scene as one mesh. */
    public static TriangleMesh mesh(String text) {
        return TessellationWalk.mesh(load(text).getSceneGroup());
    }

    public static TessellationWalk.Result walk(VrmlScene s) {
        return new TessellationWalk().run(s.getSceneGroup());
    }

    /** A fresh temporary folder (delete with {@link #deleteTree}). */
    public static Path tempDir() throws IOException {
        return Files.createTempDirectory("handsim-vrml-test").toRealPath();
    }

    public static Path write(Path dir, String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.createDirectories(p.getParent());
        Files.write(p, text.getBytes(StandardCharsets.UTF_8));
        return p;
    }

    public static void deleteTree(Path dir) throws IOException {
        if (dir == null || !Files.exists(dir)) return;
        try (Stream<Path> s = Files.walk(dir)) {
            s.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        }
    }
}
