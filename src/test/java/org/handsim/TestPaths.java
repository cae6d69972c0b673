package org.handsim;

import java.nio.file.Files;
import java.nio.file.Path;

/** Where the tests find the project root and the shared folder (../shared beside the repo). */
public final class TestPaths {
    private TestPaths() {}

    /** The project root (system property {@code handsim.root}, set by the build). */
    public static Path root() {
        String p = System.getProperty("handsim.root");
        return p != null ? Path.of(p) : Path.of("").toAbsolutePath();
    }

    /** {@code ../shared} relative to the project root (system property {@code handsim.shared}). */
    public static Path shared() {
        String p = System.getProperty("handsim.shared");
        return p != null ? Path.of(p) : root().resolve("../shared").normalize();
    }

    /** True if the shared folder with the VRML corpus is present. */
    public static boolean hasShared() {
        return Files.isDirectory(shared().resolve("vrml-corpus"));
    }
}
