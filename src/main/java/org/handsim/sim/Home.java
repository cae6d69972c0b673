package org.handsim.sim;

import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Enumeration;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;

/**
 * Where HandSim's data folders are ({@code vrml/}, {@code scenarios/}): the system property
 * {@code handsim.home} (the {@code ./handsim} launcher sets it), else {@code handsim.root} (the
 * tests), else the current directory or the nearest parent that holds {@code vrml/hand/}, else
 * — when HandSim runs from the one runnable jar ({@code gradle fatJar}), which carries the hand
 * and object models and the scenarios under {@code handsim-home/} — a copy of those unpacked
 * once into {@code <temp>/handsim-home-<jar size>-<jar time>/}, so the jar runs by itself
 * anywhere.
 */
public final class Home {
    private Home() {}

    /** Where the runnable jar keeps the data folders. */
    static final String JAR_FOLDER = "handsim-home/";

    private static volatile Path unpacked;

    public static Path dir() {
        for (String prop : new String[] {"handsim.home", "handsim.root"}) {
            String p = System.getProperty(prop);
            if (p != null && Files.isDirectory(Path.of(p, "vrml", "hand"))) return Path.of(p);
        }
        Path d = Path.of("").toAbsolutePath();
        for (Path p = d; p != null; p = p.getParent()) {
            if (Files.isDirectory(p.resolve("vrml").resolve("hand"))) return p;
        }
        Path jar = fromJar();
        return jar != null ? jar : d;
    }

    /** The data folders unpacked from the running jar, or null when not running from one that has them. */
    private static Path fromJar() {
        Path done = unpacked;
        if (done != null) return done;
        synchronized (Home.class) {
            if (unpacked != null) return unpacked;
            try {
                Path jar = Path.of(Home.class.getProtectionDomain().getCodeSource().getLocation().toURI());
                if (!Files.isRegularFile(jar)) return null;
                try (ZipFile z = new ZipFile(jar.toFile())) {
                    if (z.getEntry(JAR_FOLDER + "vrml/hand/palm.wrl") == null) return null;
                    Path target = Path.of(System.getProperty("java.io.tmpdir"),
                        "handsim-home-" + Files.size(jar) + "-" + Files.getLastModifiedTime(jar).toMillis());
                    if (!Files.isRegularFile(target.resolve(".complete"))) {
                        Path work = Files.createTempDirectory(target.getParent(), "handsim-home-unpacking");
                        for (Enumeration<? extends ZipEntry> e = z.entries(); e.hasMoreElements(); ) {
                            ZipEntry en = e.nextElement();
                            if (!en.getName().startsWith(JAR_FOLDER) || en.isDirectory()) continue;
                            Path out = work.resolve(en.getName().substring(JAR_FOLDER.length())).normalize();
                            if (!out.startsWith(work)) continue;
                            Files.createDirectories(out.getParent());
                            try (InputStream in = z.getInputStream(en)) {
                                Files.copy(in, out, StandardCopyOption.REPLACE_EXISTING);
                            }
                        }
                        Files.createFile(work.resolve(".complete"));
                        try {
                            Files.move(work, target, StandardCopyOption.ATOMIC_MOVE);
                        } catch (IOException raced) {
                            // another process unpacked it first: use theirs
                            if (!Files.isRegularFile(target.resolve(".complete"))) throw raced;
                        }
                    }
                    unpacked = target;
                    return target;
                }
            } catch (IOException | URISyntaxException | RuntimeException e) {
                return null;
            }
        }
    }

    /** Whether the data folders in use are the ones unpacked from the runnable jar (not a checkout's). */
    public static boolean fromRunnableJar() {
        Path u = unpacked;
        return u != null && dir().equals(u);
    }

    /** {@code vrml/hand/} */
    public static Path handModels() { return dir().resolve("vrml").resolve("hand"); }

    /** {@code scenarios/} */
    public static Path scenarios() { return dir().resolve("scenarios"); }

    /** The paper's experiment, the default scenario. */
    public static Path paperScenario() { return scenarios().resolve("paper-breakaway.json"); }
}
