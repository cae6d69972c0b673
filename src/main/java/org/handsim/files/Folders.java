package org.handsim.files;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

/** Removing a folder HandSim made. */
public final class Folders {
    private Folders() {}

    /**
     * Deletes a folder and everything in it; links inside are removed, never followed. Tried
     * three times: a writer thread may still be adding a file while the folder goes.
     */
    public static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir, LinkOption.NOFOLLOW_LINKS)) return;
        IOException last = null;
        for (int attempt = 0; attempt < 3; attempt++) {
            try (Stream<Path> s = Files.walk(dir)) {
                List<Path> all = new ArrayList<>();
                s.forEach(all::add);
                all.sort(Comparator.reverseOrder());
                for (Path p : all) Files.deleteIfExists(p);
                return;
            } catch (IOException e) {
                last = e;
            } catch (UncheckedIOException e) {
                last = e.getCause();
            }
        }
        throw last;
    }
}
