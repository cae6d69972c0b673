package org.handsim;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * Where the tests find the project root and the shared folder (real-world VRML corpus, bench
 * meshes): the system property {@code handsim.shared} (the build sets it to {@code ../shared}
 * beside the checkout), else the environment variable {@code HANDSIM_SHARED}, else
 * {@code ../shared} or {@code ../../shared} from the project root, else {@code /work/shared}.
 * The folder is never copied into the repository (its files carry their own licences).
 */
public final class TestPaths {
    private TestPaths() {}

    /** The project root (system property {@code handsim.root}, set by the build). */
    public static Path root() {
        String p = System.getProperty("handsim.root");
        return p != null ? Path.of(p) : Path.of("").toAbsolutePath();
    }

    /** The shared folder (the first candidate that holds {@code vrml-corpus/}, else the build's). */
    public static Path shared() {
        String prop = System.getProperty("handsim.shared");
        String env = System.getenv("HANDSIM_SHARED");
        Path[] candidates = {
            prop != null ? Path.of(prop) : null,
            env != null ? Path.of(env) : null,
            root().resolve("../shared").normalize(),
            root().resolve("../../shared").normalize(),
            Path.of("/work/shared")};
        for (Path c : candidates) {
            if (c != null && Files.isDirectory(c.resolve("vrml-corpus"))) return c;
        }
        return prop != null ? Path.of(prop) : root().resolve("../shared").normalize();
    }

    /** True if the shared folder with the VRML corpus is present. */
    public static boolean hasShared() {
        return Files.isDirectory(shared().resolve("vrml-corpus"));
    }

    /** The names of the entries of {@code dir}, sorted. */
    public static List<String> names(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            List<String> n = new ArrayList<>();
            s.forEach(p -> n.add(p.getFileName().toString()));
            n.sort(null);
            return n;
        }
    }
}
