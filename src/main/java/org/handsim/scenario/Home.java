package org.handsim.scenario;

import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFileAttributes;
import java.nio.file.attribute.UserPrincipal;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Arrays;
import java.util.Enumeration;
import java.util.HexFormat;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;
import org.handsim.process.ExitCleanup;
import org.handsim.files.Folders;
import org.handsim.files.PrivateFolder;

/**
 * Where HandSim's data folders are ({@code vrml/}, {@code scenarios/}): the system property
 * {@code handsim.home} (the {@code ./handsim} launcher sets it), else {@code handsim.root} (the
 * tests), else the current directory or the nearest parent that holds {@code vrml/hand/}, else
 * — when HandSim runs from the one runnable jar ({@code gradle fatJar}), which carries the hand
 * and object models and the scenarios under {@code handsim-home/} — a copy of those unpacked
 * from the jar ({@link #unpack}).
 *
 * <p>The copy is trusted only if nobody else can have changed it: it lives in the user's own
 * cache folder ({@code $XDG_CACHE_HOME/handsim/} or {@code ~/.cache/handsim/}, mode 700, owned by
 * the user and writable by nobody else), under a name made of the SHA-256 of the jar's files, and
 * every file is checked against that hash before use. A copy that fails the check is replaced.
 * Without such a folder the models go to a fresh private temporary folder (mode 700, a random
 * name), deleted when the program ends. Concurrent first runs each unpack into their own
 * {@code .unpack-PID-…} folder and rename it into place; the losers delete theirs.
 */
public final class Home {
    private Home() {}

    /** Where the runnable jar keeps the data folders. */
    static final String JAR_FOLDER = "handsim-home/";

    private static volatile Path unpacked;
    private static volatile String unpackFailure;

    /**
     * The folder that holds {@code vrml/} and {@code scenarios/} (the rule above); the current
     * folder when none does (then {@link #handModels} says what is missing).
     */
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
                try {
                    unpacked = unpack(jar, userCache());
                } catch (IOException | RuntimeException e) {
                    unpackFailure = "the models and scenarios of " + jar.getFileName() + " could not be unpacked: " + e.getMessage()
                        + " (the cache " + userCache() + " and the temporary folder " + System.getProperty("java.io.tmpdir")
                        + " must be writable)";
                    return null;
                }
                return unpacked;
            } catch (URISyntaxException | RuntimeException e) {
                return null;
            }
        }
    }

    /**
     * Why the runnable jar's models could not be unpacked (a read-only cache and temporary
     * folder), or null: an error that follows from their absence says this too.
     */
    public static String unpackFailure() {
        return unpackFailure;
    }

    /** Whether the data folders in use are the ones unpacked from the runnable jar (not a checkout's). */
    public static boolean fromRunnableJar() {
        Path u = unpacked;
        return u != null && dir().equals(u);
    }

    /** {@code $XDG_CACHE_HOME/handsim} (an absolute XDG_CACHE_HOME), else {@code ~/.cache/handsim}; null without a home. */
    static Path userCache() {
        String xdg = System.getenv("XDG_CACHE_HOME");
        if (xdg != null && !xdg.isEmpty() && Path.of(xdg).isAbsolute()) return Path.of(xdg, "handsim");
        String home = System.getProperty("user.home");
        if (home == null || home.isEmpty() || home.equals("?")) return null;
        return Path.of(home, ".cache", "handsim");
    }

    /**
     * The {@code handsim-home/} files of {@code jar}, unpacked and verified: in {@code cache}
     * (created if missing) when it is the user's alone, else in a fresh private temporary
     * folder deleted at exit. Null if the jar has no models.
     */
    static Path unpack(Path jar, Path cache) throws IOException {
        try (ZipFile z = new ZipFile(jar.toFile())) {
            if (z.getEntry(JAR_FOLDER + "vrml/hand/palm.wrl") == null) return null;
            Map<String, byte[]> hashes = hashes(z);
            if (cache != null) {
                Path home = unpackIntoCache(z, hashes, cache);
                if (home != null) return home;
            }
            Path tmp = Files.createTempDirectory("handsim-home-");   // mode 700, a random name
            ExitCleanup.register(() -> {
                try {
                    Folders.deleteTree(tmp);
                } catch (IOException e) {
                    // best effort at exit
                }
            });
            extract(z, tmp);
            if (!verified(tmp, hashes, null)) throw new IOException("the models unpacked into " + tmp + " do not match the jar");
            return tmp;
        }
    }

    /** The verified copy in the user's cache folder, or null if that folder is not the user's alone. */
    private static Path unpackIntoCache(ZipFile z, Map<String, byte[]> hashes, Path cache) throws IOException {
        if (!PrivateFolder.ensure(cache)) return null;
        removeDeadUnpacking(cache);
        Path work;
        try {
            work = Files.createTempDirectory(cache, ".unpack-" + ProcessHandle.current().pid() + "-");
        } catch (IOException e) {
            return null;
        }
        try {
            UserPrincipal me = Files.getOwner(work);
            Path home = cache.resolve("home-" + HexFormat.of().formatHex(folderDigest(hashes), 0, 12));
            if (verified(home, hashes, me)) return home;
            extract(z, work);
            if (!verified(work, hashes, me)) return null;
            for (int attempt = 0; attempt < 3; attempt++) {
                try {
                    Files.move(work, home, StandardCopyOption.ATOMIC_MOVE);
                    return home;
                } catch (IOException taken) {
                    if (verified(home, hashes, me)) return home;   // another first run got there first
                    if (Files.exists(home, LinkOption.NOFOLLOW_LINKS)) {   // a damaged copy: move it aside and delete it
                        Path aside = cache.resolve(".damaged-" + ProcessHandle.current().pid() + "-" + attempt + "-" + System.nanoTime());
                        try {
                            Files.move(home, aside, StandardCopyOption.ATOMIC_MOVE);
                            Folders.deleteTree(aside);
                        } catch (IOException e) {
                            // someone else moved it: try again
                        }
                    }
                }
            }
            return null;
        } finally {
            try {
                Folders.deleteTree(work);   // still there unless it became the copy
            } catch (IOException e) {
                // removed by the next run (its process id names a process that is gone)
            }
        }
    }

    /** Removes {@code .unpack-PID-…} folders of processes that are gone (killed while unpacking). */
    private static void removeDeadUnpacking(Path cache) {
        try (DirectoryStream<Path> s = Files.newDirectoryStream(cache, ".unpack-*")) {
            for (Path p : s) {
                String[] parts = p.getFileName().toString().split("-");
                try {
                    long pid = Long.parseLong(parts[1]);
                    if (ProcessHandle.of(pid).isEmpty()) Folders.deleteTree(p);
                } catch (NumberFormatException | ArrayIndexOutOfBoundsException | IOException e) {
                    // not ours, or gone already
                }
            }
        } catch (IOException e) {
            // nothing to clean
        }
    }

    /** SHA-256 of every {@code handsim-home/} file of the jar, by its path below that folder. */
    private static Map<String, byte[]> hashes(ZipFile z) throws IOException {
        Map<String, byte[]> h = new TreeMap<>();
        for (Enumeration<? extends ZipEntry> e = z.entries(); e.hasMoreElements(); ) {
            ZipEntry en = e.nextElement();
            if (!en.getName().startsWith(JAR_FOLDER) || en.isDirectory()) continue;
            String rel = en.getName().substring(JAR_FOLDER.length());
            if (!safeRelative(rel)) continue;
            try (InputStream in = z.getInputStream(en)) {
                h.put(rel, sha256(in));
            }
        }
        return h;
    }

    /** One digest of the whole folder (names and file hashes): it names the cached copy. */
    private static byte[] folderDigest(Map<String, byte[]> hashes) {
        MessageDigest d = sha256();
        for (Map.Entry<String, byte[]> e : hashes.entrySet()) {
            d.update(e.getKey().getBytes(java.nio.charset.StandardCharsets.UTF_8));
            d.update((byte) 0);
            d.update(e.getValue());
        }
        return d.digest();
    }

    private static boolean safeRelative(String rel) {
        return !rel.isEmpty() && !rel.startsWith("/") && !rel.contains("\\") && !Arrays.asList(rel.split("/")).contains("..")
            && !Arrays.asList(rel.split("/")).contains(".");
    }

    private static void extract(ZipFile z, Path to) throws IOException {
        for (Enumeration<? extends ZipEntry> e = z.entries(); e.hasMoreElements(); ) {
            ZipEntry en = e.nextElement();
            if (!en.getName().startsWith(JAR_FOLDER) || en.isDirectory()) continue;
            String rel = en.getName().substring(JAR_FOLDER.length());
            if (!safeRelative(rel)) continue;
            Path out = to.resolve(rel);
            Files.createDirectories(out.getParent());
            try (InputStream in = z.getInputStream(en)) {
                Files.copy(in, out);
            }
        }
    }

    /**
     * Whether {@code dir} holds exactly the jar's files with their SHA-256, as regular files and
     * folders (no links), all owned by {@code me} when given.
     */
    static boolean verified(Path dir, Map<String, byte[]> hashes, UserPrincipal me) {
        if (!Files.isDirectory(dir, LinkOption.NOFOLLOW_LINKS)) return false;
        Map<String, byte[]> found = new TreeMap<>();
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                PosixFileAttributes a = Files.readAttributes(p, PosixFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
                if (me != null && !a.owner().equals(me)) return false;
                if (a.isDirectory()) continue;
                if (!a.isRegularFile()) return false;
                String rel = dir.relativize(p).toString().replace(java.io.File.separatorChar, '/');
                try (InputStream in = Files.newInputStream(p, LinkOption.NOFOLLOW_LINKS)) {
                    found.put(rel, sha256(in));
                }
            }
        } catch (IOException | RuntimeException e) {
            return false;
        }
        if (!found.keySet().equals(hashes.keySet())) return false;
        for (Map.Entry<String, byte[]> e : hashes.entrySet()) {
            if (!MessageDigest.isEqual(e.getValue(), found.get(e.getKey()))) return false;
        }
        return true;
    }

    private static byte[] sha256(InputStream in) throws IOException {
        MessageDigest d = sha256();
        byte[] buf = new byte[1 << 16];
        for (int n; (n = in.read(buf)) > 0; ) d.update(buf, 0, n);
        return d.digest();
    }

    private static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is part of every Java", e);
        }
    }

    /** {@code vrml/hand/} */
    public static Path handModels() {
        Path d = dir().resolve("vrml").resolve("hand");
        if (!Files.isDirectory(d)) throw new ScenarioException(NOT_FOUND);
        return d;
    }

    /**
     * Why the hand's models are nowhere: what was looked for, and the property to set. Said
     * instead of "vrml/hand/palm.wrl: no such file" when a program that embeds HandSim runs with
     * neither a HandSim jar that holds the models nor a checkout around it.
     */
    public static final String NOT_FOUND = "HandSim's models and scenarios (vrml/hand/*.wrl, scenarios/) were not found: not under the system property"
        + " handsim.home, not in the current folder or a folder above it, and not in a HandSim jar on the class path"
        + " (handsim.jar and the runnable jar carry them); set -Dhandsim.home=DIR to a HandSim checkout or install";

    /** {@code scenarios/} */
    public static Path scenarios() {
        Path d = dir().resolve("scenarios");
        if (!Files.isDirectory(d)) throw new ScenarioException(NOT_FOUND);
        return d;
    }

    /** The paper's experiment, the default scenario. */
    public static Path paperScenario() { return scenarios().resolve("paper-breakaway.json"); }
}
