package org.handsim.files;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Consumer;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.handsim.process.CommandContext;
import org.handsim.process.ExitCleanup;
import org.handsim.process.Phase;
import org.handsim.text.SafeText;

/**
 * The files one command writes into one folder (trace, summary and charts of {@code run}; table,
 * best grasps, charts and {@code plan.json} of {@code plan} ...), published whole or not at all.
 *
 * <p><b>How.</b> {@link #open} takes the folder's lock, then the command writes every file into
 * its private folder {@link #dir()} ({@code DIR/.handsim-writing/stage-PID-N/}, mode 700).
 * {@link #publish()} then writes a manifest and renames the files into {@code DIR}: first the
 * previous set's marker is removed (its {@code summary.json}, {@code plan.json},
 * {@code tradeoff.json} — the file a reader takes as "this set is complete"), then the tables,
 * then the charts, then the files of the previous set this one does not have (a chart of a
 * finger that no longer moves), and the new marker last. A reader that sees the marker sees a
 * whole set, old or new. Files of {@code DIR} that are not of the set are never touched, and
 * no step follows a symbolic link inside {@code DIR} or the private folder ({@link #folderOf}):
 * nothing a link or a crafted manifest points at outside {@code DIR} is written or removed.
 *
 * <p><b>Failures.</b> An error before {@link #publish()} (or a run that is not published) leaves
 * {@code DIR} as it was: the private folder is deleted, and so is {@code DIR} if this set created
 * it and it is empty. SIGINT and SIGTERM do the same ({@link ExitCleanup}); if they arrive during
 * the publication (after the manifest), the publication is completed instead. SIGKILL leaves
 * {@code .handsim-writing/}: the next command that opens the folder completes a publication whose
 * manifest is there, or deletes the unfinished files.
 *
 * <p><b>Lock.</b> One writer per folder, in any number of processes: the first holds a POSIX
 * record lock on {@code .handsim-writing/lock} for the whole command; the second is told who
 * holds it (the {@code waiting} callback, once) and waits. The lock file is marked released and
 * deleted by its holder when done; a waiter that then wins the lock of the deleted file reads the
 * mark and tries again. Threads of one JVM wait for each other in memory first: a process holds
 * one POSIX lock per file, and closing any descriptor of the file releases it.
 */
public final class OutputSet implements AutoCloseable {
    /** The folder beside the outputs that holds the lock and the private folders. */
    public static final String WORK = ".handsim-writing";
    private static final String LOCK = "lock", MANIFEST = ".publish", STAGE = "stage-", RELEASED = "released\n";
    private static final long PID = ProcessHandle.current().pid();
    private static final SecureRandom RANDOM = new SecureRandom();
    private static final Set<Path> HELD_IN_THIS_JVM = new HashSet<>();

    /**
     * What belongs to a command's set.
     *
     * @param marker     the file published last (the set is complete when it is there), or null
     * @param ours       the relative paths ({@code /}-separated) of every file this command can write
     *                   in the folder: those the new set does not have are removed
     * @param subfolders folders of the set (e.g. {@code best}) searched for such files
     */
    public record Layout(String marker, Pattern ours, List<String> subfolders) {
        public Layout(String marker, String oursRegex, String... subfolders) {
            this(marker, Pattern.compile(oursRegex), List.of(subfolders));
        }
    }

    /** An output folder that cannot be used (not a folder; a member of the set that is not a regular file). */
    public static final class Refused extends IOException {
        private static final long serialVersionUID = 1L;
        Refused(String message) { super(message); }
    }

    private final Path target;
    private final Path work;
    private final Path stage;
    private final Layout layout;
    private final Path jvmKey;
    private final List<Path> created;
    private final FileChannel lockChannel;
    private final FileLock lock;
    private final Runnable atExit = this::stopped;
    private List<String[]> steps;     // the manifest, once written
    private int next;                 // the first step not yet done
    private boolean published, closed;

    private OutputSet(Path target, Path work, Path stage, Layout layout, Path jvmKey, List<Path> created,
                      FileChannel ch, FileLock lock) {
        this.target = target;
        this.work = work;
        this.stage = stage;
        this.layout = layout;
        this.jvmKey = jvmKey;
        this.created = created;
        this.lockChannel = ch;
        this.lock = lock;
    }

    /**
     * Opens the set of {@code dir} (created with its parents if missing): takes the folder's
     * lock (waiting for another writer, which {@code waiting} is told once), completes or
     * removes what a killed writer left, and makes the private folder.
     *
     * @throws Refused if {@code dir} is not a folder, or one of the set's names in it is a folder,
     *                 device, FIFO or socket (it would have to be replaced)
     */
    public static OutputSet open(Path dir, Layout layout, Consumer<String> waiting) throws IOException {
        if (dir.toString().isEmpty()) throw new Refused("'' is not a folder name");
        if (Files.exists(dir) && !Files.isDirectory(dir)) throw new Refused("exists and is not a folder");
        List<Path> created = new ArrayList<>();
        for (Path p = dir.toAbsolutePath().normalize(); p != null && !Files.exists(p, LinkOption.NOFOLLOW_LINKS); p = p.getParent()) created.add(p);
        if (ExitCleanup.stopping()) throw new IOException("not writing " + dir + ": the program is being stopped");
        Files.createDirectories(dir);
        Path key = dir.toRealPath();
        synchronized (HELD_IN_THIS_JVM) {
            boolean told = false;
            while (HELD_IN_THIS_JVM.contains(key)) {
                if (!told && waiting != null) waiting.accept(dir + " is being written by another command of this program; waiting for it");
                told = true;
                try {
                    HELD_IN_THIS_JVM.wait();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new IOException("interrupted while waiting for " + dir, e);
                }
            }
            HELD_IN_THIS_JVM.add(key);
        }
        OutputSet set = null;
        try {
            set = lockAndStage(dir, key, layout, created, waiting);
            return set;
        } finally {
            if (set == null) release(key);
        }
    }

    private static void release(Path key) {
        synchronized (HELD_IN_THIS_JVM) {
            HELD_IN_THIS_JVM.remove(key);
            HELD_IN_THIS_JVM.notifyAll();
        }
    }

    private static OutputSet lockAndStage(Path dir, Path key, Layout layout, List<Path> created, Consumer<String> waiting) throws IOException {
        Path work = dir.resolve(WORK);
        String token = "pid " + PID + "\n";
        boolean told = false;
        while (true) {
            try {
                Files.createDirectory(work, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
            } catch (FileAlreadyExistsException e) {
                if (!Files.isDirectory(work, LinkOption.NOFOLLOW_LINKS)) throw new Refused(work + " exists and is not a folder");
            } catch (UnsupportedOperationException e) {
                try {
                    Files.createDirectory(work);
                } catch (FileAlreadyExistsException e2) {
                    // another writer made it
                }
            } catch (NoSuchFileException e) {
                Files.createDirectories(dir);   // removed by a writer that had created it: make it again
                continue;
            }
            FileChannel ch;
            try {
                ch = FileChannel.open(work.resolve(LOCK), StandardOpenOption.CREATE, StandardOpenOption.READ, StandardOpenOption.WRITE,
                    LinkOption.NOFOLLOW_LINKS);
            } catch (NoSuchFileException e) {
                continue;   // the folder went away between the two calls
            }
            FileLock lock = null;
            try {
                lock = ch.tryLock();
            } catch (OverlappingFileLockException e) {
                lock = null;
            }
            if (lock == null) {
                if (!told && waiting != null) waiting.accept(dir + " is being written by another handsim (" + holder(work) + "); waiting for it");
                told = true;
                ch.close();
                sleep(dir);
                continue;
            }
            // read through the locked channel only: closing any other descriptor of the file would
            // release this process's lock (POSIX record locks)
            ByteBuffer was = ByteBuffer.allocate(RELEASED.length());
            ch.read(was, 0);
            if (new String(was.array(), 0, was.position(), StandardCharsets.US_ASCII).equals(RELEASED)) {
                lock.release();   // the lock of a file its holder had already deleted: try the one at the path now
                ch.close();
                continue;
            }
            ch.truncate(0);
            ch.write(ByteBuffer.wrap(token.getBytes(StandardCharsets.US_ASCII)), 0);
            OutputSet set = null;
            try {
                recoverLeftovers(dir, work);
                Path stage = work.resolve(STAGE + PID + "-" + Long.toHexString(RANDOM.nextLong()));
                Files.createDirectory(stage);
                set = new OutputSet(dir, work, stage, layout, key, created, ch, lock);
                ExitCleanup.register(set.atExit);
                set.checkMembers();
                return set;
            } catch (IOException | RuntimeException e) {
                if (set != null) set.close();
                else unlock(work, ch, lock);
                throw e;
            }
        }
    }

    private static void sleep(Path dir) throws IOException {
        try {
            Thread.sleep(100);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while waiting for " + dir, e);
        }
    }

    /** "pid N" of the lock's holder, as its lock file says. */
    private static String holder(Path work) {
        try {
            String s = Files.readString(work.resolve(LOCK), StandardCharsets.US_ASCII).trim();
            return s.startsWith("pid ") ? s : "finishing";
        } catch (IOException | RuntimeException e) {
            return "finishing";
        }
    }

    /**
     * Marks the lock file released and deletes it (still holding its lock), deletes the work
     * folder if empty, then releases the lock. A writer that was waiting on the deleted file
     * then gets its lock, reads the mark, and tries again with the file at the path.
     */
    private static void unlock(Path work, FileChannel ch, FileLock lock) {
        try {
            ch.truncate(0);
            ch.write(ByteBuffer.wrap(RELEASED.getBytes(StandardCharsets.US_ASCII)), 0);
            Files.deleteIfExists(work.resolve(LOCK));
        } catch (IOException e) {
            // left for the next writer
        }
        try {
            Files.deleteIfExists(work);
        } catch (IOException e) {
            // not empty: a publication to complete stays for the next writer
        }
        try {
            lock.release();
        } catch (IOException e) {
            // closing the channel releases it too
        }
        try {
            ch.close();
        } catch (IOException e) {
            // nothing more to do
        }
    }

    /**
     * Whatever a killed writer left in the work folder (the caller holds the lock, so its owner
     * is gone): a private folder with a manifest is published, any other is deleted.
     */
    private static void recoverLeftovers(Path dir, Path work) throws IOException {
        List<Path> left = new ArrayList<>();
        try (DirectoryStream<Path> s = Files.newDirectoryStream(work, p -> !p.getFileName().toString().equals(LOCK))) {
            for (Path p : s) left.add(p);
        }
        for (Path p : left) {
            Path manifest = p.resolve(MANIFEST);
            if (Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS) && Files.isRegularFile(manifest, LinkOption.NOFOLLOW_LINKS)) {
                List<String[]> steps;
                try {
                    steps = readManifest(manifest);
                    for (String[] step : steps) check(dir, p, step);   // all of them before the first acts
                } catch (Refused e) {
                    throw new Refused("not completing the publication a stopped writer left in " + p + ": " + e.getMessage()
                        + " (remove " + p + " to discard it)");
                }
                for (String[] step : steps) apply(dir, p, step);
            }
            deleteTree(p);
        }
    }

    /** Completes or removes what a killed writer left in {@code dir} (what {@link #open} does first); for tests and tools. */
    public static void recover(Path dir) throws IOException {
        if (!Files.isDirectory(dir.resolve(WORK), LinkOption.NOFOLLOW_LINKS)) return;
        open(dir, new Layout(null, "(?!)"), null).close();
    }

    /** The private folder to write the set's files into (relative names as they will be in the folder). */
    public Path dir() { return stage; }

    /** The folder the set is published into. */
    public Path target() { return target; }

    /**
     * Refuses early if one of the set's subfolders in the folder is not a folder of its own (a
     * link could lead the set's files out of the output folder), or one of the set's names is
     * something a rename must not replace.
     */
    private void checkMembers() throws IOException {
        for (String sub : layout.subfolders()) {
            Path d = target.resolve(sub);
            if (Files.exists(d, LinkOption.NOFOLLOW_LINKS) && !Files.isDirectory(d, LinkOption.NOFOLLOW_LINKS)) throw notAFolder(d);
        }
        for (String rel : existingMembers()) {
            Path p = target.resolve(rel);
            if (!Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS) && !Files.isSymbolicLink(p)) {
                throw new Refused(p + " is " + kind(p) + ", not a file this command may replace");
            }
        }
    }

    private static String kind(Path p) {
        if (Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS)) return "a folder";
        return "a device, FIFO or socket";
    }

    /** The set's names (of {@link Layout#ours}) that exist in the folder now, relative. */
    private List<String> existingMembers() throws IOException {
        List<String> found = new ArrayList<>();
        List<String> folders = new ArrayList<>();
        folders.add("");
        folders.addAll(layout.subfolders());
        for (String sub : folders) {
            Path d = sub.isEmpty() ? target : target.resolve(sub);
            if (!Files.isDirectory(d, LinkOption.NOFOLLOW_LINKS)) continue;
            try (DirectoryStream<Path> s = Files.newDirectoryStream(d)) {
                for (Path p : s) {
                    String rel = sub.isEmpty() ? p.getFileName().toString() : sub + "/" + p.getFileName();
                    if (layout.ours().matcher(rel).matches()) found.add(rel);
                }
            }
        }
        found.sort(null);
        return found;
    }

    /**
     * Publishes the set: every file written into {@link #dir()} is renamed into the folder (the
     * tables, then the charts, then the marker), and the previous set's files this one does not
     * have are removed. Call once every file is complete.
     */
    public void publish() throws IOException {
        synchronized (this) {
            if (closed) throw new IOException("not publishing " + target + ": the program is being stopped");
            if (steps != null) throw new IllegalStateException("the set of " + target + " is published already");
        }
        Phase.reach("staged");   // the last cancellation point: from here on the publication is completed
        List<String[]> plan = plannedSteps();
        StringBuilder text = new StringBuilder();
        for (String[] step : plan) text.append(step[0]).append(' ').append(step[1]).append('\n');
        Path partial = stage.resolve(MANIFEST + ".partial");
        try (FileChannel ch = FileChannel.open(partial, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE)) {
            ch.write(ByteBuffer.wrap(text.toString().getBytes(StandardCharsets.UTF_8)));
            ch.force(true);
        }
        synchronized (this) {
            if (closed || CommandContext.cancelled()) throw new IOException("not publishing " + target + ": the program is being stopped");
            Files.move(partial, stage.resolve(MANIFEST), StandardCopyOption.ATOMIC_MOVE);
            steps = plan;
        }
        Phase.reachInPublication("manifest");
        for (int i = 0; i < plan.size(); i++) {
            if (i > 0 && !stepKind(plan.get(i)).equals(stepKind(plan.get(i - 1)))) Phase.reachInPublication(stepKind(plan.get(i - 1)));
            synchronized (this) {
                if (next != i) return;   // the exit hook completed the publication
                apply(target, stage, plan.get(i));
                next = i + 1;
            }
        }
        if (!plan.isEmpty()) Phase.reachInPublication(stepKind(plan.get(plan.size() - 1)));
        synchronized (this) {
            if (published) return;
            published = true;
            deleteTree(stage);
        }
        Phase.reachInPublication("published");
    }

    /**
     * The publication's steps, in order: {@code clear} the old marker, {@code move} each table,
     * then each chart, {@code drop} the previous set's files this one does not have, {@code move}
     * the marker.
     */
    List<String[]> plannedSteps() throws IOException {
        List<String> files = new ArrayList<>();
        try (Stream<Path> s = Files.walk(stage)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                if (!Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) continue;
                String rel = stage.relativize(p).toString().replace(java.io.File.separatorChar, '/');
                if (!rel.startsWith(".") && !rel.contains("/.")) files.add(rel);
            }
        }
        files.sort(Comparator.comparingInt(this::rank).thenComparing(Comparator.naturalOrder()));
        Set<String> fresh = new TreeSet<>(files);
        checkMembers();
        for (String rel : files) {
            Path p = target.resolve(rel);
            if (Files.exists(p, LinkOption.NOFOLLOW_LINKS) && !Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS) && !Files.isSymbolicLink(p)) {
                throw new Refused(p + " is " + kind(p) + ", not a file this command may replace");
            }
        }
        List<String[]> plan = new ArrayList<>();
        String marker = layout.marker();
        if (marker != null && fresh.contains(marker)) plan.add(new String[] {"clear", marker});
        for (String rel : files) if (rank(rel) < 2) plan.add(new String[] {"move", rel});
        for (String rel : existingMembers()) if (!fresh.contains(rel)) plan.add(new String[] {"drop", rel});
        for (String rel : files) if (rank(rel) == 2) plan.add(new String[] {"move", rel});
        return plan;
    }

    /** The phase a step belongs to, named for {@link Phase} (the points between them). */
    private String stepKind(String[] step) {
        if (step[0].equals("clear")) return "old-marker-removed";
        if (step[0].equals("drop")) return "stale-removed";
        return new String[] {"tables-published", "charts-published", "marker-published"}[rank(step[1])];
    }

    /** 0: tables and other data; 1: charts; 2: the marker (last). */
    private int rank(String rel) {
        if (rel.equals(layout.marker())) return 2;
        return rel.endsWith(".png") || rel.endsWith(".svg") ? 1 : 0;
    }

    /** One manifest step; each can be repeated (a killed publication is completed from its start). */
    private static void apply(Path dir, Path stage, String[] step) throws IOException {
        check(dir, stage, step);
        String rel = step[1];
        Path to = dir.resolve(rel), from = stage.resolve(rel);
        switch (step[0]) {
            case "clear":   // the old marker goes first, while the new one is still to come
                if (Files.exists(from, LinkOption.NOFOLLOW_LINKS) && folderOf(dir, rel, false) != null) deleteFile(to);
                break;
            case "move":
                if (!Files.isRegularFile(from, LinkOption.NOFOLLOW_LINKS)) break;   // moved already
                folderOf(dir, rel, true);
                try {
                    Files.move(from, to, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
                } catch (AtomicMoveNotSupportedException e) {
                    Files.move(from, to, StandardCopyOption.REPLACE_EXISTING);
                }
                break;
            default:   // "drop"
                if (folderOf(dir, rel, false) != null) deleteFile(to);
                break;
        }
    }

    /**
     * Refuses a step that could act outside its folders: an unknown step, a name that is absolute
     * or has an empty, {@code .} or {@code ..} part, or one whose way in the output folder or in
     * the private folder passes through anything but a folder of its own (a symbolic link to
     * another folder, above all).
     */
    private static void check(Path dir, Path stage, String[] step) throws IOException {
        String rel = step[1];
        if (!List.of("clear", "move", "drop").contains(step[0])) {
            throw new Refused("bad manifest step " + SafeText.quote(step[0]));
        }
        boolean badPart = rel.isEmpty() || rel.startsWith("/") || rel.contains("\\") || rel.indexOf('\0') >= 0;
        for (String part : rel.split("/", -1)) badPart |= part.isEmpty() || part.equals(".") || part.equals("..");
        if (badPart) {
            throw new Refused("bad manifest entry " + SafeText.quote(rel) + ": it leads out of " + dir);
        }
        folderOf(stage, rel, false);
        folderOf(dir, rel, false);
    }

    /**
     * The folder that holds {@code rel} inside {@code root}, every folder on the way checked
     * without following links: a link (or anything but a folder) there is refused, since it could
     * lead out of {@code root}. A missing folder is made if {@code create}, else the answer is
     * null (nothing there to act on).
     */
    static Path folderOf(Path root, String rel, boolean create) throws IOException {
        Path at = root;
        String[] parts = rel.split("/");
        for (int i = 0; i < parts.length - 1; i++) {
            at = at.resolve(parts[i]);
            if (!Files.exists(at, LinkOption.NOFOLLOW_LINKS)) {
                if (!create) return null;
                try {
                    Files.createDirectory(at);
                } catch (FileAlreadyExistsException e) {
                    // made meanwhile: checked below
                }
            }
            if (!Files.isDirectory(at, LinkOption.NOFOLLOW_LINKS)) throw notAFolder(at);
        }
        return at;
    }

    private static Refused notAFolder(Path p) {
        String what = Files.isSymbolicLink(p) ? "a symbolic link" : "not a folder";
        return new Refused(p + " is " + what + ": an output set is never written through it (it could lead out of the output folder)");
    }

    /** Deletes a regular file or a link, never a folder or a device. */
    private static void deleteFile(Path p) throws IOException {
        if (Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS) || Files.isSymbolicLink(p)) Files.deleteIfExists(p);
    }

    /** The largest manifest read back (one line per file of a set: a set has tens). */
    private static final long MAX_MANIFEST_BYTES = 1 << 20;

    private static List<String[]> readManifest(Path manifest) throws IOException {
        String text;
        try {
            text = InputFile.readText(manifest, MAX_MANIFEST_BYTES, "the limit of publication manifests");
        } catch (InputFile.InputFileException e) {
            throw new Refused(e.getMessage());
        }
        List<String[]> steps = new ArrayList<>();
        for (String line : text.split("\n")) {
            if (line.isEmpty()) continue;
            int sp = line.indexOf(' ');
            steps.add(sp > 0 ? new String[] {line.substring(0, sp), line.substring(sp + 1)} : new String[] {line, ""});
        }
        return steps;
    }

    /** At SIGINT/SIGTERM: a publication under way is completed, anything else removed; then the lock is released. */
    private void stopped() {
        synchronized (this) {
            if (closed) return;
            if (steps != null && !published) {
                try {
                    for (; next < steps.size(); next++) apply(target, stage, steps.get(next));
                    published = true;
                } catch (IOException e) {
                    // left with its manifest for the next writer
                    closed = true;
                    unlock(work, lockChannel, lock);
                    return;
                }
            }
        }
        close();
    }

    /** Releases the lock; without {@link #publish()}, deletes the private folder (and the output folder if this set made it and it is empty). */
    @Override
    public void close() {
        synchronized (this) {
            if (closed) return;
            closed = true;
            if (steps == null || published) {
                try {
                    deleteTree(stage);
                } catch (IOException e) {
                    // the next writer removes it
                }
            }
            unlock(work, lockChannel, lock);
            if (!published) {
                for (Path p : created) {
                    try {
                        Files.deleteIfExists(p);
                    } catch (IOException e) {
                        break;   // not empty (someone else wrote there): leave it
                    }
                }
            }
        }
        ExitCleanup.unregister(atExit);
        release(jvmKey);
    }

    private static void deleteTree(Path dir) throws IOException {
        Folders.deleteTree(dir);
    }
}
