package org.handsim.server;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.Charset;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Instant;
import java.util.HashMap;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import org.handsim.cli.HandSim;
import org.handsim.process.CommandContext;
import org.handsim.process.ExitCleanup;

/**
 * The resident HandSim JVM: it runs the short commands {@link Client}s hand it, one at a time,
 * so that they start on loaded, compiled code (as Gradle's and Kotlin's daemons, Bazel's server
 * and Nailgun do). One server serves one install, one working directory, one build and one
 * environment (the {@link Client#identity() identity}; relative paths resolve against the JVM's
 * working directory, which cannot change per command): its socket is named by a hash of the
 * identity and it refuses a client of another. It ends after {@link #IDLE_S} seconds without a
 * command (property {@code handsim.server.idle}), when its build changes (a class-path entry's
 * size or time) or its working directory is replaced, after a command that failed unexpectedly
 * (exit 1) or left threads running, and on {@code handsim server stop}.
 *
 * <p><b>A command</b> runs as in its own JVM: {@link HandSim#execute} on a thread with the
 * launcher's 16 MB stack, {@code System.out} and {@code System.err} sent to the client (in its
 * encodings; the progress bar sees the client's terminal, {@link CommandContext#console()}),
 * system properties restored afterwards, and what the JVM's exit would have undone
 * ({@link ExitCleanup}) undone when it returns. A second client meanwhile is told {@link
 * Client#BUSY} and runs in its own JVM.
 *
 * <p><b>Stopping a command.</b> A client that gets SIGINT or SIGTERM sends {@link Client#CANCEL};
 * one that dies closes the socket; both cancel the command ({@link CommandContext#cancel}), which
 * stops at its next cancellation point and removes its unpublished outputs on its normal close
 * path (a publication under way is completed). If it has not ended {@link #CANCEL_GRACE_MS} ms
 * later, the server exits as a stopped JVM does: its shutdown hook ({@link ExitCleanup}) removes
 * or completes the command's outputs.
 */
public final class Server {
    /** Seconds without a command after which the server exits. */
    static final long IDLE_S = 600;
    /** How long a cancelled command has to stop before the server exits to stop it. */
    static final long CANCEL_GRACE_MS = 10_000;
    /** How long the threads a command started have to end after it returns. */
    static final long THREADS_GRACE_MS = 5_000;
    /** How often the server looks at its build, working directory and install (a change ends it within this, warming or not). */
    static final long WATCH_MS = 250;
    /** The largest output frame sent: a command's larger writes go as several. */
    static final int FRAME_BYTES = 1 << 16;
    /** Servers a user may have at once by default (property {@code handsim.server.max}, variable {@code HANDSIM_SERVER_MAX}). */
    static final int MAX_SERVERS = 2;
    private static final int STACK_BYTES = 16 << 20;

    private final String identity;
    private final Path dir, socket;
    private final String key;
    private final PrintStream log, logOut;
    private final long idleMs;
    private final long started = System.currentTimeMillis();
    private final String build, cwdKey, homeKey;
    private ServerSocketChannel listener;
    private Object socketKey;
    private boolean busy, stopping, warming, clientCame;
    private volatile long warmUpCancelledAt;
    private long lastActivity = System.currentTimeMillis();
    private int served;

    Server(String identity, Path dir, String key, long idleMs) {
        this.identity = identity;
        this.dir = dir;
        this.key = key;
        this.socket = Client.socketFile(dir, key);
        this.idleMs = idleMs;
        this.log = System.err;
        this.logOut = System.out;
        this.build = Client.build();
        this.cwdKey = Client.fileKey(Path.of("."));
        this.homeKey = Client.fileKey(home());
    }

    /** The install this server serves ({@code handsim.home}). */
    private static Path home() {
        String h = System.getProperty("handsim.home");
        return Path.of(h != null ? h : ".");
    }

    public static void main(String[] args) throws Exception {
        Path dir = Client.folder();
        String unsafe = dir == null ? "no cache folder" : Client.unsafe(dir, true);
        if (unsafe != null) {
            System.err.println(Instant.now() + " handsim server: not starting: " + unsafe);
            System.exit(0);
        }
        String identity = Client.identity();
        String key = Client.key(identity);
        long idle = Long.getLong("handsim.server.idle", IDLE_S) * 1000;
        System.exit(new Server(identity, dir, key, idle).serve());
    }

    private void say(String what) {
        log.println(Instant.now() + " handsim server " + ProcessHandle.current().pid() + ": " + what);
        log.flush();
    }

    /** Holds the lock, listens, serves until told or timed out; returns the exit code. */
    int serve() throws IOException {
        ServerFiles.Lock lock = ServerFiles.Lock.take(Client.lockFile(dir, key));
        if (lock == null) {
            say("another server has " + key + "; exiting");
            return 0;
        }
        try {
            Files.deleteIfExists(socket);   // a killed server's: the lock says nobody serves it
            ServerFiles.removeStale(dir);
            listener = ServerSocketChannel.open(StandardProtocolFamily.UNIX);
            listener.bind(UnixDomainSocketAddress.of(socket));
            Files.setPosixFilePermissions(socket, PosixFilePermissions.fromString("rw-------"));
            socketKey = Files.readAttributes(socket, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS).fileKey();
            say("serving " + System.getProperty("user.dir") + " for " + System.getProperty("handsim.home") + " on " + socket
                + " (idle timeout " + idleMs / 1000 + " s)");
            ServerAdmin.keepAtMost(dir, maxServers(), socket);
            Thread watch = new Thread(this::watch, "handsim-server-watch");
            watch.setDaemon(true);
            watch.start();
            if (!"0".equals(System.getProperty("handsim.server.warmup"))) {
                Thread warm = new Thread(this::warmUp, "handsim-server-warm-up");
                warm.setDaemon(true);
                warm.start();
            }
            try {
                while (true) {
                    SocketChannel c;
                    try {
                        c = listener.accept();
                    } catch (IOException e) {   // closed by shutDown
                        break;
                    }
                    Thread t = new Thread(() -> handle(c), "handsim-server-connection");
                    t.setDaemon(true);
                    t.start();
                }
            } finally {
                removeSocket();
            }
            say("exiting after " + served + " commands");
            return 0;
        } finally {
            endWarmUp();
            ServerFiles.deleteQuietly(Client.warmFolder(dir, key));
            ServerFiles.deleteQuietly(Client.logFile(dir, key));   // removed with its server (a killed server's: by the next, ServerFiles.removeStale)
            lock.releaseAndDelete();
            ServerFiles.removeIfEmptyShort(dir);
        }
    }

    /** The most servers of this user at once: property, environment variable, or {@link #MAX_SERVERS}. */
    static int maxServers() {
        String v = System.getProperty("handsim.server.max", System.getenv("HANDSIM_SERVER_MAX"));
        try {
            return v == null ? MAX_SERVERS : Math.max(1, Integer.parseInt(v.trim()));
        } catch (NumberFormatException e) {
            return MAX_SERVERS;
        }
    }

    /** Stops a warm-up under way and waits a little for it (its files are in this server's warm-up folder, removed next). */
    private void endWarmUp() {
        synchronized (this) {
            clientCame = true;
            if (!warming) return;
            warmUpCancelledAt = System.nanoTime();
            CommandContext.cancel();
            long end = System.currentTimeMillis() + 300;
            while (warming && System.currentTimeMillis() < end) {
                try {
                    wait(Math.max(1, end - System.currentTimeMillis()));
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    return;
                }
            }
        }
    }

    /** Removes the socket if it is still this server's (not one a later server made at the same path). */
    private void removeSocket() {
        try {
            Object now = Files.readAttributes(socket, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS).fileKey();
            if (now != null && now.equals(socketKey)) Files.deleteIfExists(socket);
        } catch (IOException e) {
            // gone already
        }
    }

    /**
     * Stops listening: the accept loop ends and the server exits — at once when idle or warming
     * up (the warm-up is cancelled), after its command when a client's command is running (its
     * end calls this again).
     */
    private synchronized void shutDown(String why) {
        if (!stopping) say("stopping: " + why);
        stopping = true;
        if (busy && !warming) return;   // a client's command: its end calls again
        removeSocket();     // no new client finds it from now on
        try {
            listener.close();
        } catch (IOException e) {
            // closed already
        }
    }

    /**
     * Every {@link #WATCH_MS} ms: the idle timeout, a changed build, a replaced or vanished working
     * directory or install. Once it has told the server to stop it keeps looking, so a server
     * that finishes a client's command then stops.
     */
    private void watch() {
        String told = null;
        while (true) {
            try {
                Thread.sleep(WATCH_MS);
            } catch (InterruptedException e) {
                return;
            }
            String why = null;
            synchronized (this) {
                if (!busy && System.currentTimeMillis() - lastActivity > idleMs) why = "idle for " + idleMs / 1000 + " s";
            }
            if (why == null && !Client.build().equals(build)) why = "the build changed";
            if (why == null && !Client.fileKey(Path.of(System.getProperty("user.dir"))).equals(cwdKey)) why = "the working directory was replaced";
            if (why == null && !Client.fileKey(home()).equals(homeKey)) why = "the install " + home() + " was moved or removed";
            if (why != null && told == null) told = why;
            if (told != null) shutDown(told);
        }
    }

    private void handle(SocketChannel c) {
        try (c) {
            DataInputStream in = new DataInputStream(new BufferedInputStream(Client.in(c)));
            DataOutputStream out = new DataOutputStream(new BufferedOutputStream(Client.out(c)));
            if (in.readInt() != Client.MAGIC) return;
            int kind = in.read();
            if (kind == Client.STATUS) {
                Client.writeString(out, status());
                out.flush();
                return;
            }
            if (kind == Client.STOP) {
                out.writeByte(Client.ACCEPTED);
                out.flush();
                shutDown("asked to stop");
                return;
            }
            if (kind != Client.RUN) return;
            String theirs = Client.readString(in);
            boolean console = in.readBoolean();
            String outEncoding = Client.readString(in), errEncoding = Client.readString(in);
            int n = in.readInt();
            if (n < 0 || n > 100_000) return;
            String[] args = new String[n];
            for (int i = 0; i < n; i++) args[i] = Client.readString(in);
            String refused = refusal(theirs);
            if (refused != null) {
                out.writeByte(Client.REFUSED);
                Client.writeString(out, refused);
                out.flush();
                shutDown("refused a client: " + refused);   // whatever differs, a fresh server is the sure way
                return;
            }
            synchronized (this) {
                clientCame = true;   // no more warming up
                if (warming) {       // a warm-up run: it stops at its next cancellation point, and the client is served
                    out.writeByte(Client.WAIT);   // alive: the client waits longer than for a first answer
                    out.flush();
                    warmUpCancelledAt = System.nanoTime();
                    CommandContext.cancel();
                    while (warming) {
                        try {
                            wait();
                        } catch (InterruptedException e) {
                            Thread.currentThread().interrupt();
                            return;
                        }
                    }
                }
                if (busy || stopping) {
                    out.writeByte(Client.BUSY);
                    out.flush();
                    return;
                }
                busy = true;
            }
            boolean keep = false;
            try {
                out.writeByte(Client.ACCEPTED);
                out.flush();
                keep = run(args, console, charset(outEncoding), charset(errEncoding), in, out);
            } finally {
                synchronized (this) {
                    busy = false;
                    served++;
                    lastActivity = System.currentTimeMillis();
                }
                if (!keep) shutDown("the last command left this JVM in doubt");
                else if (stopping) shutDown("as asked");
            }
        } catch (IOException | RuntimeException e) {
            say("connection: " + e);
        }
    }

    /** Why a client of identity {@code theirs} is not served here, or null. */
    private String refusal(String theirs) {
        if (!theirs.equals(identity)) {
            String[] a = theirs.split("\n"), b = identity.split("\n");
            for (int i = 0; i < Math.max(a.length, b.length); i++) {
                String x = i < a.length ? a[i] : "(none)", y = i < b.length ? b[i] : "(none)";
                if (!x.equals(y)) return "another identity: the client's '" + x + "', the server's '" + y + "'";
            }
        }
        if (!Client.build().equals(build)) return "the build changed since the server started";
        String cwdNow = Client.fileKey(Path.of(System.getProperty("user.dir")));
        if (!cwdNow.equals(cwdKey) || !Client.fileKey(Path.of(".")).equals(cwdKey)) return "the working directory was replaced";
        return null;
    }

    private static Charset charset(String name) {
        try {
            return name.isEmpty() ? Charset.defaultCharset() : Charset.forName(name);
        } catch (RuntimeException e) {
            return Charset.defaultCharset();
        }
    }

    private synchronized String status() {
        return "pid " + ProcessHandle.current().pid() + "\n"
            + "since " + Instant.ofEpochMilli(started) + "\n"
            + "commands " + served + "\n"
            + "state " + (warming ? "warming" : busy ? "busy" : stopping ? "stopping" : "idle") + "\n"
            + "used " + lastActivity + "\n"
            + "memory " + ServerFiles.residentBytes() + "\n"
            + "log " + Client.logFile(dir, key) + "\n"
            + identity;
    }

    /** The frames of one of the command's streams: each write is one frame to the client; a client gone cancels the command. */
    private static final class Frames extends OutputStream {
        private final DataOutputStream out;
        private final byte type;
        private final Runnable gone;

        Frames(DataOutputStream out, byte type, Runnable gone) {
            this.out = out;
            this.type = type;
            this.gone = gone;
        }

        @Override
        public void write(int b) throws IOException {
            write(new byte[] {(byte) b}, 0, 1);
        }

        @Override
        public void write(byte[] b, int off, int len) {
            synchronized (out) {
                try {
                    for (int at = 0; at < len; at += FRAME_BYTES) {   // bounded frames: a client takes none longer
                        int n = Math.min(FRAME_BYTES, len - at);
                        out.writeByte(type);
                        out.writeInt(n);
                        out.write(b, off + at, n);
                    }
                    out.flush();
                } catch (IOException e) {
                    gone.run();   // the client is gone: as SIGKILL of a JVM, the command stops
                }
            }
        }
    }

    /**
     * Runs one command for the client; returns whether the JVM is still fit for the next (false
     * after an unexpected failure or threads left running).
     */
    private boolean run(String[] args, boolean console, Charset outCs, Charset errCs, DataInputStream in, DataOutputStream out) {
        long t0 = System.nanoTime();
        boolean[] cancelled = {false}, finished = {false};
        long[] cancelledAt = {0};
        Object command = new Object();
        Runnable cancel = () -> {
            synchronized (command) {   // a client that goes away after the end cancels nothing (the next command least of all)
                if (cancelled[0] || finished[0]) return;
                cancelled[0] = true;
                cancelledAt[0] = System.nanoTime();
                CommandContext.cancel();
            }
        };
        Thread reader = new Thread(() -> {
            try {
                while (true) {
                    int b = in.read();
                    if (b == Client.CANCEL || b < 0) {
                        cancel.run();
                        return;
                    }
                }
            } catch (IOException e) {
                cancel.run();
            }
        }, "handsim-server-client");
        reader.setDaemon(true);

        PrintStream cmdOut = new PrintStream(new BufferedOutputStream(new Frames(out, Client.OUT, cancel), 8192), true, outCs);
        PrintStream cmdErr = new PrintStream(new BufferedOutputStream(new Frames(out, Client.ERR, cancel), 8192), true, errCs);
        reader.start();
        int[] code = {1};
        boolean fit = execute(args, console, cmdOut, cmdErr, code, () -> {
            synchronized (command) {
                return cancelled[0] ? cancelledAt[0] : 0;
            }
        }, () -> {
            synchronized (command) {
                finished[0] = true;
                CommandContext.end();
            }
        });
        boolean wasCancelled;
        synchronized (command) {
            wasCancelled = cancelled[0];
        }
        if (CommandContext.inDoubt() != null && !wasCancelled) {   // out of memory, an internal error: start afresh
            say("the command left this JVM in doubt: " + CommandContext.inDoubt());
            fit = false;
        }
        try {
            synchronized (out) {
                out.writeByte(Client.EXIT);
                out.writeInt(code[0]);
                out.flush();
            }
        } catch (IOException e) {
            // the client is gone
        }
        say(String.join(" ", args) + ": exit " + code[0] + (wasCancelled ? " (cancelled)" : "") + " in "
            + String.format(java.util.Locale.ROOT, "%.3f", (System.nanoTime() - t0) / 1e9) + " s");
        return fit;
    }

    /** Warm-up runs after the start: the paper's run and the mug grasp, each this many times. */
    static final int WARM_UP_ROUNDS = 8;

    /**
     * Runs the paper's experiment and the mug grasp a few times into a private temporary folder,
     * their output thrown away, so that the next command finds the code they share compiled (a
     * fresh server's first commands run partly interpreted). Ends at the first client, which
     * cancels a run under way (it stops at its next cancellation point) and is served at once;
     * never runs again after one. Property {@code handsim.server.warmup=0}: no warm-up.
     */
    private void warmUp() {
        Path tmp = null;
        try {
            tmp = Client.warmFolder(dir, key);   // beside the lock: removed with the server, or as stale by the next
            ServerFiles.deleteQuietly(tmp);
            Files.createDirectory(tmp, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
            Path mug = org.handsim.scenario.Home.dir().resolve("scenarios").resolve("mug-grasp.json");
            PrintStream nowhere = new PrintStream(OutputStream.nullOutputStream(), true, Charset.defaultCharset());
            for (int round = 0; round < WARM_UP_ROUNDS; round++) {
                for (String[] args : new String[][] {
                    {"run", "--out", tmp.resolve("paper").toString()},
                    {"run", mug.toString(), "--out", tmp.resolve("mug").toString()}}) {
                    synchronized (this) {
                        if (clientCame || busy || stopping) return;
                        busy = true;
                        warming = true;
                        warmUpCancelledAt = 0;
                    }
                    boolean fit = true;
                    try {
                        fit = execute(args, false, nowhere, nowhere, new int[1], () -> warmUpCancelledAt, CommandContext::end);
                    } finally {
                        synchronized (this) {
                            busy = false;
                            warming = false;
                            lastActivity = System.currentTimeMillis();
                            notifyAll();
                        }
                    }
                    if (!fit && !stopping) {
                        shutDown("the warm-up left this JVM in doubt");
                        return;
                    }
                }
            }
            say("warmed up");
        } catch (IOException | RuntimeException e) {
            say("warm-up: " + e);
        } finally {
            if (tmp != null) ServerFiles.deleteQuietly(tmp);
            synchronized (this) {
                if (stopping) shutDown("as asked");   // a stop that came while warming up
            }
        }
    }

    /**
     * Runs {@code args} as in a JVM of its own: {@link HandSim#execute} on a 16 MB thread with
     * {@code System.out}/{@code err} set to the given streams, then waits for the threads it
     * started, undoes what the JVM's exit would have undone, restores the streams and the system
     * properties, and calls {@code end} (which must end the {@link CommandContext} command).
     * {@code cancelledAt} tells when the command was cancelled (0: not): one that has not stopped
     * {@link #CANCEL_GRACE_MS} later makes the server exit as SIGTERM would. Returns whether the
     * JVM is still fit for the next command.
     */
    private boolean execute(String[] args, boolean console, PrintStream cmdOut, PrintStream cmdErr, int[] code,
                            java.util.function.LongSupplier cancelledAt, Runnable end) {
        Properties saved = new Properties();
        saved.putAll(System.getProperties());
        Set<Runnable> registered = ExitCleanup.registered();
        ThreadGroup group = new ThreadGroup("handsim-command");
        CommandContext.begin(console);
        System.setOut(cmdOut);
        System.setErr(cmdErr);
        Thread main = new Thread(group, () -> code[0] = HandSim.execute(args), "main", STACK_BYTES);
        boolean fit = true;
        try {
            main.start();
            while (main.isAlive()) {
                try {
                    main.join(100);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    break;
                }
                long at = cancelledAt.getAsLong();
                if (at != 0 && main.isAlive() && System.nanoTime() - at > CANCEL_GRACE_MS * 1_000_000) {
                    say("the cancelled command " + String.join(" ", args) + " did not stop within " + CANCEL_GRACE_MS
                        + " ms: exiting (the exit hook removes or completes its outputs)");
                    removeSocket();
                    System.exit(143);   // as SIGTERM: the exit hook (ExitCleanup) removes or completes the outputs
                }
            }
            String left = waitForThreads(group);
            if (left != null) {
                say("the command " + String.join(" ", args) + " left threads running: " + left);
                fit = false;
            }
            int undone = ExitCleanup.runAllBut(registered);
            if (undone > 0) say("undid " + undone + " exit actions the command left");
            cmdOut.flush();
            cmdErr.flush();
        } finally {
            System.setOut(logOut);
            System.setErr(log);
            restore(saved);
            end.run();
        }
        return fit;
    }

    /** Waits for the threads the command started; null once all ended, else their names. */
    private static String waitForThreads(ThreadGroup group) {
        long end = System.currentTimeMillis() + THREADS_GRACE_MS;
        while (true) {
            Thread[] ts = new Thread[group.activeCount() + 8];
            int n = group.enumerate(ts, true);
            StringBuilder names = new StringBuilder();
            for (int i = 0; i < n; i++) {
                Thread t = ts[i];
                if (!t.isAlive()) continue;
                long wait = end - System.currentTimeMillis();
                if (wait > 0) {
                    try {
                        t.join(wait);
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                        return "interrupted";
                    }
                }
                if (t.isAlive()) names.append(names.length() > 0 ? ", " : "").append(t.getName());
            }
            if (names.length() == 0) return null;
            if (System.currentTimeMillis() >= end) return names.toString();
        }
    }

    /** Puts the system properties back as they were before the command. */
    private static void restore(Properties saved) {
        Map<Object, Object> now = new HashMap<>(System.getProperties());
        for (Object k : now.keySet()) if (!saved.containsKey(k)) System.getProperties().remove(k);
        for (Map.Entry<Object, Object> e : saved.entrySet()) {
            if (!e.getValue().equals(now.get(e.getKey()))) System.getProperties().put(e.getKey(), e.getValue());
        }
    }
}
