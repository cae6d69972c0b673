package org.handsim.server;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.File;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.PosixFileAttributes;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * The {@code handsim} command's entry point as the launcher starts it: a short command (run,
 * sweep, plan with the local engine, mesh, collide, fk, ik, id, swing, grasp, quality) is handed
 * to a resident server JVM ({@link Server}) of this install, working directory, build and
 * environment when one is running and free, so that it runs on code that is already loaded and
 * compiled; otherwise — no server, a busy one, anything doubtful, another command, or
 * {@code HANDSIM_SERVER=0} — it runs here, in this JVM, exactly as {@code cli.HandSim} does, and
 * then starts a server in the background for the next command.
 *
 * <p>Deliberately small: on the served path this class uses the JDK alone (no picocli, no other
 * class of the project), so the JVM that runs it starts in a few tens of milliseconds.
 *
 * <p><b>Protocol</b> (a Unix-domain socket in a folder only the user can use, {@link #folder()}):
 * the client sends {@link #MAGIC}, {@link #RUN}, its identity ({@link #identity()}), whether its
 * standard streams are a terminal, their encodings and the arguments; the server answers
 * {@link #ACCEPTED}, {@link #BUSY} or {@link #REFUSED} and a reason; once accepted it sends the
 * command's standard output and error as frames ({@link #OUT}, {@link #ERR}: type, length,
 * bytes) and ends with {@link #EXIT} and the exit code. The client sends {@link #CANCEL} when
 * SIGINT or SIGTERM stops it and exits, as a stopped JVM does (130, 143), only once the server
 * has answered that the command has stopped (its outputs left whole, the old set or the new);
 * a client that dies (SIGKILL) closes the socket, which cancels the command the same way.
 */
public final class Client {
    static final int MAGIC = 0x48534331;   // "HSC1"
    static final byte RUN = 'R', STATUS = 'S', STOP = 'Q';
    static final byte ACCEPTED = 'A', BUSY = 'B', REFUSED = 'N', WAIT = 'W';
    static final byte OUT = 'O', ERR = 'E', EXIT = 'X', CANCEL = 'C';

    /** The commands a server runs: short ones of the local engine (not gui, not tradeoff, not Spark). */
    static final Set<String> SERVED = Set.of("run", "sweep", "plan", "mesh", "collide", "fk", "ik", "id", "swing", "grasp", "quality");

    /** Environment variables that change what a command does or how its JVM runs: a server serves only clients with the same. */
    private static final Set<String> ENVIRONMENT = Set.of("HOME", "USER", "LANG", "LANGUAGE", "TZ", "LD_LIBRARY_PATH", "LD_PRELOAD",
        "JAVA_TOOL_OPTIONS", "_JAVA_OPTIONS", "JDK_JAVA_OPTIONS", "JAVA_HOME", "FONTCONFIG_FILE", "FONTCONFIG_PATH");
    private static final String[] ENVIRONMENT_PREFIXES = {"HANDSIM_", "XDG_", "LC_"};
    /** System properties that do the same (those not set on the command line have the same defaults in both JVMs). */
    private static final String[] PROPERTIES = {"java.io.tmpdir", "file.encoding", "sun.jnu.encoding", "user.home", "user.name",
        "user.language", "user.country", "user.variant", "user.timezone", "java.awt.headless", "j3d.rend"};

    /** How long a stopped client waits for the server to end the command (the server gives it 10 s, then exits). */
    private static final long CANCEL_WAIT_MS = 40_000;

    /**
     * Longest socket path this JDK binds: sun_path has 108 bytes, but the JDK keeps two for
     * itself and refuses 107 ("Unix domain path too long"; measured with JDK 17: 106 binds,
     * 107 does not), so a path counted against the kernel's 107 would reach a bind that fails.
     */
    static final int MAX_SOCKET_PATH = 106;

    private Client() {}

    public static void main(String[] args) {
        Client.Outcome served = Outcome.NOT_TRIED;
        String why = null;
        String identity = null;
        if (eligible(args)) {
            Opener opener = new Opener();
            opener.start();
            why = notServable(args);
            if (why != null) {
                served = Outcome.HERE;
                opener.discard();
            } else {
                try {
                    identity = identity();   // before the command runs: it sets system properties of its own
                    Connection c = connect(identity, args, opener);
                    served = c.outcome;
                    why = c.reason;
                    if (served == Outcome.ACCEPTED) System.exit(c.stream());
                } catch (IOException | RuntimeException e) {
                    opener.discard();
                    served = Outcome.FAILED;
                    why = String.valueOf(e);
                }
            }
            if (served == Outcome.TIMEOUT || served == Outcome.FAILED) {   // a server that is there but does not serve: say so, once
                System.err.println("handsim: the resident server did not serve this command (" + why + "); running it here");
                System.err.flush();
            }
            if (served != Outcome.NO_SERVER || why != null) remember(served, why);
        }
        report("in-process (" + served.name().toLowerCase(java.util.Locale.ROOT) + (why != null ? ": " + why : "") + ")");
        boolean training = System.getProperty(TRAINING) != null;
        if (training) loadServedPathClasses();
        int code = org.handsim.cli.HandSim.execute(java.util.List.of(ServerCommand.class), args);
        if (served == Outcome.NO_SERVER && !training) startServer(identity);
        System.exit(code);
    }

    /**
     * System property of the launcher's class-data archive training run (a command run in-process
     * that also loads what a served command loads, and starts no server).
     */
    static final String TRAINING = "handsim.server.training";

    /**
     * Loads the classes a served command's client uses — the socket channel and its streams,
     * which the JDK builds with lambdas of its own — so that the training run puts them in the
     * class-data archive: without them a client spun those classes at every start (tens of
     * milliseconds of a command that the server answers in a few).
     */
    private static void loadServedPathClasses() {
        Path nowhere = Path.of(System.getProperty("java.io.tmpdir"), "handsim-cds-" + ProcessHandle.current().pid() + ".socket");
        try (SocketChannel ch = openChannel()) {
            new DataInputStream(new java.io.BufferedInputStream(in(ch)));
            new DataOutputStream(new java.io.BufferedOutputStream(out(ch)));
            new Watchdog(ch, answerMs()).disarm();
            ch.connect(UnixDomainSocketAddress.of(nowhere));   // nobody there: refused, as a stale socket is
        } catch (IOException | RuntimeException expected) {
            // what was to be loaded is loaded
        }
    }

    /**
     * What became of the attempt to hand the command to a server: not tried (not a served command,
     * or {@code HANDSIM_SERVER=0}); here (the command names something only this process has, see
     * {@link #notServable}); no server; busy; refused; timeout (no answer within {@link #ANSWER_MS});
     * failed (the connection broke); accepted.
     */
    enum Outcome { NOT_TRIED, HERE, NO_SERVER, BUSY, REFUSED, TIMEOUT, FAILED, ACCEPTED }

    /**
     * How long a client waits for a server to connect, take the request and start answering
     * (property {@code handsim.server.answerMs}): a server that accepts and then says nothing (stopped
     * with SIGSTOP, swapped out, wedged) costs a command this much, never more.
     */
    static final long ANSWER_MS = 2000;

    /** {@link #ANSWER_MS}, or the property {@code handsim.server.answerMs}. */
    static long answerMs() {
        return Long.getLong("handsim.server.answerMs", ANSWER_MS);
    }

    /**
     * How long a client waits, once its server has answered {@link #WAIT} (it is ending a warm-up
     * run at the run's next cancellation point), for it to accept or refuse: a cold warm-up run on a
     * loaded machine can take seconds to reach one, but not this long.
     */
    static final long WARM_UP_WAIT_MS = 20_000;

    /**
     * The longest frame or text either side takes (a server's output frames are at most
     * {@link Server#FRAME_BYTES}): anything longer is a broken or foreign peer, never a reason to
     * allocate what it asks for.
     */
    static final int MAX_FRAME = 1 << 20;

    /**
     * Why this command line must run in this process, or null: an argument that names this
     * process's own descriptors, files or terminal — {@code /dev/stdout}, {@code /dev/stderr},
     * {@code /dev/stdin}, {@code /dev/fd/N}, {@code /dev/tty}, anything under {@code /proc/} — as
     * given, relative to the working directory, or through a link (a server would open its own:
     * {@code --obj /dev/stdout} wrote into the server's log); or an argument that is not the
     * text its bytes are (U+FFFD: {@code cli.ArgumentBytes} names the byte, from this process's
     * own command line). Each argument costs a string test, and a look at the file only when it
     * exists and is a link. {@code /dev/null} is the same file in any process.
     */
    static String notServable(String[] args) {
        Path cwd = null;
        for (String a : args) {
            if (a.indexOf('\ufffd') >= 0) return "an argument is not UTF-8 text";
            int eq = a.startsWith("-") ? a.indexOf('=') : -1;
            String v = eq > 0 ? a.substring(eq + 1) : a;
            if (v.isEmpty() || v.indexOf('\0') >= 0) continue;
            String why = ownFile(v, v);
            if (why != null) return why;
            Path p;
            try {
                p = Path.of(v);
                if (!p.isAbsolute()) {
                    if (cwd == null) cwd = Path.of("").toAbsolutePath();
                    p = cwd.resolve(p);
                }
                p = p.normalize();
            } catch (RuntimeException e) {
                continue;   // not a path
            }
            why = ownFile(p.toString(), v);
            if (why != null) return why;
            if (!Files.exists(p, LinkOption.NOFOLLOW_LINKS)) continue;
            try {
                why = ownFile(p.toRealPath().toString(), v);
            } catch (IOException | RuntimeException e) {
                why = "'" + v + "' leads to something that is not a file";   // a link into /proc/self/fd: a pipe, a socket
            }
            if (why != null) return why;
        }
        return null;
    }

    /** Why {@code path} names this process's own descriptors, files or terminal (or another device), or null. */
    private static String ownFile(String path, String given) {
        if (path.equals("/dev/null")) return null;
        if (path.startsWith("/dev/") || path.equals("/dev") || path.startsWith("/proc/") || path.equals("/proc")) {
            return "'" + given + "' names a device or this process's own files";
        }
        return null;
    }

    /**
     * Notes in the servers' folder why the last command that could have been served was not
     * ({@code handsim server status} shows it); nothing if the folder is not fit.
     */
    static void remember(Outcome how, String why) {
        Path dir = folder();
        if (dir == null || unsafe(dir, false) != null) return;
        String text = System.currentTimeMillis() + " " + how.name().toLowerCase(java.util.Locale.ROOT) + (why != null ? ": " + why : "") + "\n";
        try {
            Path tmp = dir.resolve(".not-served." + ProcessHandle.current().pid());
            Files.write(tmp, text.getBytes(StandardCharsets.UTF_8));
            Files.move(tmp, dir.resolve(NOT_SERVED), java.nio.file.StandardCopyOption.REPLACE_EXISTING, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
        } catch (IOException | RuntimeException e) {
            // a note only
        }
    }

    /** The note {@link #remember} writes. */
    static final String NOT_SERVED = "not-served";

    /** Whether a server may run this command line. */
    static boolean eligible(String[] args) {
        if ("0".equals(System.getenv("HANDSIM_SERVER"))) return false;
        if (System.getProperty("handsim.home") == null || args.length == 0 || !SERVED.contains(args[0])) return false;
        String prev = "";
        for (String a : args) {
            if (a.equals("--engine=spark") || prev.equals("--engine") && a.equals("spark")) return false;
            prev = a;
        }
        return true;
    }

    /** One line on standard error saying how the command ran, when the tests ask for it ({@code handsim.server.report}). */
    static void report(String how) {
        if (System.getProperty("handsim.server.report") != null) {
            System.err.println("handsim-server " + how);
            System.err.flush();
        }
    }

    /** A connection to this command's server, or why there is none. */
    static final class Connection {
        Outcome outcome;
        String reason;
        SocketChannel channel;
        Path log;
        DataInputStream in;
        DataOutputStream out;
        private volatile boolean stopped;
        private final CountDownLatch done = new CountDownLatch(1);

        /**
         * Relays the command's output until its exit code, which it returns. SIGINT or SIGTERM
         * meanwhile: the command is cancelled, its further output dropped, and the JVM exits
         * with the signal's status once the server says the command has ended.
         */
        int stream() throws IOException {
            // an inner class, not a method reference: the client's start-up spins no lambda classes
            Thread hook = new Thread("handsim-client-stop") {
                @Override
                public void run() {
                    cancelAndWait();
                }
            };
            Runtime.getRuntime().addShutdownHook(hook);
            return relay(new FileOutputStream(FileDescriptor.out), new FileOutputStream(FileDescriptor.err));
        }

        /** Relays the command's output to these streams until its exit code, which it returns. */
        int relay(OutputStream stdout, OutputStream stderr) throws IOException {
            byte[] buf = new byte[8192];
            try {
                while (true) {
                    int type = in.read();
                    if (type == EXIT) {
                        int code = in.readInt();
                        done.countDown();
                        return code;
                    }
                    if (type != OUT && type != ERR) throw new EOFException();
                    int n = in.readInt();
                    if (n < 0 || n > MAX_FRAME) {
                        done.countDown();
                        stderr.write(("handsim: the resident server sent a frame of " + n + " bytes (at most " + MAX_FRAME
                            + "): not a server of this build; its outputs are the old set or a whole new one: run the command again with"
                            + " HANDSIM_SERVER=0\n").getBytes(StandardCharsets.UTF_8));
                        return 1;
                    }
                    if (buf.length < n) buf = new byte[n];
                    in.readFully(buf, 0, n);
                    if (stopped) continue;   // a stopped command's last words are not shown: a stopped JVM says nothing either
                    try {
                        (type == OUT ? stdout : stderr).write(buf, 0, n);
                    } catch (IOException e) {
                        // a closed pipe (handsim run | head): the command goes on, as System.out ignores it too
                    }
                }
            } catch (IOException e) {
                done.countDown();
                if (stopped) return 1;   // the exit status is the signal's
                String log = String.valueOf(this.log);
                stderr.write(("handsim: the resident server ended during the command (its log: " + log + "); its outputs are"
                    + " the old set or a whole new one: run it again, or with HANDSIM_SERVER=0\n").getBytes(StandardCharsets.UTF_8));
                return 1;
            }
        }

        /** The shutdown hook: nothing after a normal end; after SIGINT/SIGTERM, cancel the command and wait for the server to end it. */
        private void cancelAndWait() {
            if (done.getCount() == 0) return;
            stopped = true;
            try {
                synchronized (this) {
                    out.writeByte(CANCEL);
                    out.flush();
                }
            } catch (IOException e) {
                return;   // the server is gone: nothing to wait for
            }
            try {
                done.await(CANCEL_WAIT_MS, TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** Connects to the server of this client's identity and asks it to run {@code args}. */
    static Connection connect(String identity, String[] args) throws IOException {
        Opener opener = new Opener();
        opener.start();
        return connect(identity, args, opener);
    }

    /** {@link #connect(String, String[])} on the channel that {@code opener} opens (discarded when there is no server). */
    static Connection connect(String identity, String[] args, Opener opener) throws IOException {
        Connection c = new Connection();
        Path dir = folder();
        String unsafe = dir == null ? "no cache folder" : unsafe(dir, true);
        if (unsafe != null) {
            opener.discard();
            c.outcome = Outcome.REFUSED;
            c.reason = unsafe;
            return c;
        }
        String key = key(identity);
        Path socket = socketFile(dir, key);
        if (!Files.exists(socket, LinkOption.NOFOLLOW_LINKS)) {
            opener.discard();
            c.outcome = Outcome.NO_SERVER;
            return c;
        }
        SocketChannel ch = opener.channel();
        Watchdog dog = new Watchdog(ch, answerMs());
        try {
            try {
                ch.connect(UnixDomainSocketAddress.of(socket));
            } catch (IOException e) {
                ch.close();
                if (dog.fired) return timedOut(c, dog);
                c.outcome = Outcome.NO_SERVER;   // nobody listens: a server killed without removing its socket
                c.reason = "stale socket";
                return c;
            }
            c.channel = ch;
            c.log = logFile(dir, key);
            c.in = new DataInputStream(new java.io.BufferedInputStream(in(ch)));
            c.out = new DataOutputStream(new java.io.BufferedOutputStream(out(ch)));
            int answer;
            try {
                c.out.writeInt(MAGIC);
                c.out.writeByte(RUN);
                writeString(c.out, identity);
                c.out.writeBoolean(System.console() != null);
                writeString(c.out, System.getProperty("sun.stdout.encoding", ""));
                writeString(c.out, System.getProperty("sun.stderr.encoding", ""));
                c.out.writeInt(args.length);
                for (String a : args) writeString(c.out, a);
                c.out.flush();
                answer = c.in.read();
                if (answer == WAIT && dog.extend(WARM_UP_WAIT_MS)) answer = c.in.read();
            } catch (IOException e) {
                ch.close();
                if (dog.fired) return timedOut(c, dog);
                throw e;
            }
            if (!dog.disarm()) {
                ch.close();
                return timedOut(c, dog);
            }
            if (answer == ACCEPTED) {
                c.outcome = Outcome.ACCEPTED;
                report("served");
                return c;
            }
            c.outcome = answer == BUSY ? Outcome.BUSY : Outcome.REFUSED;
            c.reason = answer == REFUSED ? readString(c.in) : answer == BUSY ? "busy" : "no answer";
            ch.close();
            return c;
        } finally {
            dog.disarm();
        }
    }

    /**
     * Opens the client's socket channel on a thread of its own while the main thread checks the
     * arguments and works out the identity: the JDK's first Unix-domain channel sets up its
     * selector provider, the security providers (for its random names) and its lambdas, some
     * tens of milliseconds of interpreted code that need not wait for the rest. An inner class,
     * not a lambda: the client's start-up spins no lambda classes of its own.
     */
    static final class Opener extends Thread {
        private SocketChannel channel;
        private IOException failure;
        private boolean discarded;

        Opener() {
            super("handsim-client-open");
            setDaemon(true);
        }

        @Override
        public void run() {
            SocketChannel ch = null;
            IOException f = null;
            try {
                ch = openChannel();
            } catch (IOException e) {
                f = e;
            } catch (RuntimeException e) {
                f = new IOException(e);
            }
            synchronized (this) {
                channel = ch;
                failure = f;
                if (!discarded) return;
            }
            close(ch);
        }

        /** The opened channel, once it is open. */
        SocketChannel channel() throws IOException {
            try {
                join();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while opening the socket", e);
            }
            synchronized (this) {
                if (failure != null) throw failure;
                return channel;
            }
        }

        /** No channel is wanted: it is closed when open (this thread does not wait for it). */
        void discard() {
            SocketChannel ch;
            synchronized (this) {
                discarded = true;
                ch = channel;
                channel = null;
            }
            close(ch);
        }

        private static void close(SocketChannel ch) {
            if (ch == null) return;
            try {
                ch.close();
            } catch (IOException e) {
                // nothing was sent on it
            }
        }
    }

    /** The system property that names the JDK's selector provider class ({@link java.nio.channels.spi.SelectorProvider#provider()}). */
    static final String SELECTOR_PROVIDER = "java.nio.channels.spi.SelectorProvider";
    /** The JDK's own provider on Linux, the one {@code SelectorProvider.provider()} returns there when no other is named. */
    static final String EPOLL_PROVIDER = "sun.nio.ch.EPollSelectorProvider";

    /**
     * A Unix-domain socket channel, its provider named first when nothing else names one. Without
     * a name the JDK looks for a provider as a service: it opens every jar of the class path and
     * reads its directory (some 6 900 entries in ours), a sixth of a served command's
     * client processor time (perf's task-clock over alternating runs: 134 → 108 ms). The name is
     * that of the provider the JDK uses on Linux anyway, set only if this JDK has it with a
     * public constructor; a JDK that still cannot make it fails here with an error, and the
     * command then runs in this process (no command here uses a selector).
     */
    static SocketChannel openChannel() throws IOException {
        if (System.getProperty(SELECTOR_PROVIDER) == null) {
            try {
                Class<?> c = Class.forName(EPOLL_PROVIDER, false, null);
                if (java.nio.channels.spi.SelectorProvider.class.isAssignableFrom(c)
                    && java.lang.reflect.Modifier.isPublic(c.getModifiers())
                    && java.lang.reflect.Modifier.isPublic(c.getConstructor().getModifiers())) {
                    System.setProperty(SELECTOR_PROVIDER, EPOLL_PROVIDER);
                }
            } catch (ReflectiveOperationException | LinkageError | RuntimeException e) {
                // another platform or JDK: the JDK finds its provider itself
            }
        }
        try {
            return SocketChannel.open(StandardProtocolFamily.UNIX);
        } catch (java.util.ServiceConfigurationError | LinkageError e) {
            throw new IOException("no socket channel: " + e, e);
        }
    }

    private static Connection timedOut(Connection c, Watchdog dog) {
        c.outcome = Outcome.TIMEOUT;
        c.reason = "no answer within " + dog.ms + " ms";
        return c;
    }

    /**
     * The folder of the servers' sockets, locks and logs: system property
     * {@code handsim.server.dir}, else {@code $XDG_CACHE_HOME/handsim/server} (an absolute
     * XDG_CACHE_HOME), else {@code ~/.cache/handsim/server}; null without a home. When a socket
     * there would pass {@link #MAX_SOCKET_PATH} bytes (a deep home or checkout), a short folder
     * {@code /tmp/handsim-HASH} instead, HASH of the user and the long folder: checked as any
     * ({@link #unsafe}: the user's, mode 700, not a link), so another user's folder of that name
     * means no server, never a shared one.
     */
    static Path folder() {
        return effective(configuredFolder());
    }

    /** The folder used for the configured folder {@code f}: itself, or its short stand-in when a socket in it would be too long. */
    static Path effective(Path f) {
        if (f == null || fits(socketFile(f, "0000000000000000"))) return f;
        // too long for a socket's name: a short private folder of its own, named by the long one
        return Path.of("/tmp", "handsim-" + key(System.getProperty("user.name") + "\n" + f).substring(0, 12));
    }

    /** Whether the JDK binds a socket at {@code socket} (its bytes in UTF-8, never fewer than in the platform's encoding for a path it can name). */
    static boolean fits(Path socket) {
        return socket.toString().getBytes(StandardCharsets.UTF_8).length <= MAX_SOCKET_PATH;
    }

    /** The folder as configured (property, XDG, home), whatever its length. */
    static Path configuredFolder() {
        String p = System.getProperty("handsim.server.dir");
        if (p != null && !p.isEmpty()) return Path.of(p);
        String xdg = System.getenv("XDG_CACHE_HOME");
        if (xdg != null && !xdg.isEmpty() && Path.of(xdg).isAbsolute()) return Path.of(xdg, "handsim", "server");
        String home = System.getProperty("user.home");
        if (home == null || home.isEmpty() || home.equals("?")) return null;
        return Path.of(home, ".cache", "handsim", "server");
    }

    private static final Set<PosixFilePermission> OWNER_ONLY = EnumSet.of(PosixFilePermission.OWNER_READ,
        PosixFilePermission.OWNER_WRITE, PosixFilePermission.OWNER_EXECUTE);

    /**
     * Null if {@code dir} is a folder (not a link) of this user with mode 700 — made so if
     * missing and {@code create} — else what is wrong with it: a server's socket is used only
     * there, where nobody else can connect to it, replace it or read the logs.
     */
    static String unsafe(Path dir, boolean create) {
        try {
            if (create && !Files.exists(dir, LinkOption.NOFOLLOW_LINKS)) {
                Path parent = dir.getParent();
                if (parent != null && !Files.isDirectory(parent)) {
                    Files.createDirectories(parent, PosixFilePermissions.asFileAttribute(OWNER_ONLY));
                }
                try {
                    Files.createDirectory(dir, PosixFilePermissions.asFileAttribute(OWNER_ONLY));
                } catch (java.nio.file.FileAlreadyExistsException e) {
                    // made by another command meanwhile: checked below
                }
            }
            PosixFileAttributes a = Files.readAttributes(dir, PosixFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
            if (!a.isDirectory()) return dir + " is not a folder";
            if (!a.permissions().equals(OWNER_ONLY)) return dir + " has mode " + PosixFilePermissions.toString(a.permissions()) + ", not rwx------";
            if (!a.owner().getName().equals(System.getProperty("user.name"))) return dir + " belongs to " + a.owner().getName();
            return null;
        } catch (IOException | RuntimeException e) {
            return dir + ": " + e;
        }
    }

    /**
     * Everything a command's result may depend on besides its arguments and its input files: the
     * install, the working directory (its path and the folder itself), the JVM and its options
     * for the server, the build (every class-path entry's path, size and time), the umask, the
     * environment variables and system properties that matter. A server serves only clients of
     * its own identity; the socket's name is a hash of it ({@link #key}).
     */
    static String identity() {
        StringBuilder sb = new StringBuilder("handsim server 1\n");
        sb.append("home ").append(System.getProperty("handsim.home")).append('\n');
        String cwd = System.getProperty("user.dir");
        sb.append("cwd ").append(cwd).append(' ').append(fileKey(Path.of("."))).append('\n');
        sb.append("java ").append(System.getProperty("java.home")).append(' ').append(System.getProperty("java.vm.version")).append('\n');
        sb.append("server-jvm ").append(System.getProperty("handsim.server.jvm")).append('\n');
        sb.append(build());
        sb.append("umask ").append(umask()).append('\n');
        sb.append(processContext());
        Map<String, String> env = new TreeMap<>();
        for (Map.Entry<String, String> e : System.getenv().entrySet()) {
            String k = e.getKey();
            boolean keep = ENVIRONMENT.contains(k);
            for (String p : ENVIRONMENT_PREFIXES) keep |= k.startsWith(p);
            if (keep && !k.equals("HANDSIM_SERVER")) env.put(k, e.getValue());
        }
        for (Map.Entry<String, String> e : env.entrySet()) sb.append("env ").append(e.getKey()).append('=').append(e.getValue()).append('\n');
        Map<String, String> props = new TreeMap<>();
        for (String k : System.getProperties().stringPropertyNames()) {
            if (k.startsWith("handsim.") && !k.equals("handsim.server.report")) props.put(k, System.getProperty(k));
        }
        for (String k : PROPERTIES) props.put(k, String.valueOf(System.getProperty(k)));
        for (Map.Entry<String, String> e : props.entrySet()) sb.append("property ").append(e.getKey()).append('=').append(e.getValue()).append('\n');
        return sb.toString();
    }

    /** The build: each class-path entry's path, size and modification time, one line each. */
    static String build() {
        StringBuilder sb = new StringBuilder();
        for (String e : System.getProperty("java.class.path", "").split(File.pathSeparator)) {
            File f = new File(e);
            sb.append("class-path ").append(e).append(' ').append(f.length()).append(' ').append(f.lastModified()).append('\n');
        }
        return sb.toString();
    }

    /** The file system's identity of a file (device and inode on Linux), "?" if unknown. */
    static String fileKey(Path p) {
        try {
            return String.valueOf(Files.readAttributes(p, BasicFileAttributes.class).fileKey());
        } catch (IOException | RuntimeException e) {
            return "?";
        }
    }

    /**
     * What else of this process a command's effect depends on (Linux): its mount namespace (which
     * files a path names), its resource limits (a file size limit makes a write fail), its nice
     * level. A server started by a client inherits them, so it serves exactly the clients that
     * have the same.
     */
    static String processContext() {
        StringBuilder sb = new StringBuilder();
        try {
            sb.append("mount-namespace ").append(Files.readSymbolicLink(Path.of("/proc/self/ns/mnt"))).append('\n');
        } catch (IOException | RuntimeException e) {
            sb.append("mount-namespace ?\n");
        }
        try {
            for (String l : Files.readAllLines(Path.of("/proc/self/limits"), StandardCharsets.ISO_8859_1)) {
                if (l.startsWith("Max ")) sb.append("limit ").append(squeezed(l)).append('\n');
            }
        } catch (IOException | RuntimeException e) {
            sb.append("limit ?\n");
        }
        try {
            String stat = Files.readString(Path.of("/proc/self/stat"), StandardCharsets.ISO_8859_1);
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            sb.append("nice ").append(f[16]).append('\n');   // field 19 of stat; the fields after the name start at 3
        } catch (IOException | RuntimeException e) {
            sb.append("nice ?\n");
        }
        return sb.toString();
    }

    /**
     * The line with each run of spaces made one, trimmed: by hand, since a regular expression
     * would make the client's JVM spin the method-handle classes it uses (about 30 ms).
     */
    private static String squeezed(String l) {
        StringBuilder sb = new StringBuilder(l.length());
        for (int i = 0; i < l.length(); i++) {
            char c = l.charAt(i);
            if (c != ' ' && c != '\t') sb.append(c);
            else if (sb.length() > 0 && sb.charAt(sb.length() - 1) != ' ') sb.append(' ');
        }
        int n = sb.length();
        return n > 0 && sb.charAt(n - 1) == ' ' ? sb.substring(0, n - 1) : sb.toString();
    }

    /** This process's umask (Linux: /proc/self/status), "?" if unknown. */
    static String umask() {
        try {
            for (String l : Files.readAllLines(Path.of("/proc/self/status"), StandardCharsets.ISO_8859_1)) {
                if (l.startsWith("Umask:")) return l.substring(6).trim();
            }
        } catch (IOException | RuntimeException e) {
            return "?";
        }
        return "?";
    }

    /** A hash of the identity as 16 hexadecimal digits (FNV-1a, 64 bits): the socket's name; the server checks the whole identity. */
    static String key(String identity) {
        long h = 0xcbf29ce484222325L;
        for (byte b : identity.getBytes(StandardCharsets.UTF_8)) {
            h ^= b & 0xff;
            h *= 0x100000001b3L;
        }
        String hex = Long.toHexString(h);   // not String.format: the client's start-up loads no Formatter
        return "0000000000000000".substring(hex.length()) + hex;
    }

    static Path socketFile(Path dir, String key) { return dir.resolve(key + ".sock"); }
    static Path lockFile(Path dir, String key) { return dir.resolve(key + ".lock"); }
    /** The log file of the server of {@code key}. */
    static Path logFile(Path dir, String key) { return dir.resolve(key + ".log"); }
    /** The private folder the server of {@code key} warms up in. */
    static Path warmFolder(Path dir, String key) { return dir.resolve(key + ".warm-up"); }

    /**
     * Starts a server for this client's identity in the background, for the next command: in a
     * session of its own (so the terminal's Ctrl-C does not reach it), its output to its log
     * file. Nothing if the launcher gave no server options ({@code handsim.server.jvm}), if there
     * is no {@code setsid}, or if a server holds the lock already (starting, or serving).
     */
    static void startServer(String identity) {
        String jvm = System.getProperty("handsim.server.jvm");
        Path dir = folder();
        if (jvm == null || dir == null || unsafe(dir, true) != null) return;
        String setsid = null;
        for (String s : new String[] {"/usr/bin/setsid", "/bin/setsid"}) if (new File(s).canExecute()) setsid = s;
        if (setsid == null) return;
        String key = key(identity);
        try {
            ServerFiles.Lock lock = ServerFiles.Lock.take(lockFile(dir, key));
            if (lock == null) return;   // a server has it
            Files.deleteIfExists(socketFile(dir, key));   // what a killed server left: nobody listens there
            lock.releaseAndDelete();
            List<String> cmd = new ArrayList<>();
            cmd.add(setsid);
            cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
            for (String o : jvm.trim().split("\\s+")) if (!o.isEmpty()) cmd.add(o);
            cmd.add("-Dhandsim.server.jvm=" + jvm);
            cmd.add("-cp");
            cmd.add(System.getProperty("java.class.path"));
            cmd.add(Server.class.getName());
            File log = logFile(dir, key).toFile();
            new ProcessBuilder(cmd).redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")))
                .redirectOutput(ProcessBuilder.Redirect.to(log)).redirectErrorStream(true).start();
        } catch (IOException | RuntimeException e) {
            // no server this time: the next command runs in-process again
        }
    }

    static void writeString(DataOutputStream out, String s) throws IOException {
        byte[] b = s.getBytes(StandardCharsets.UTF_8);
        out.writeInt(b.length);
        out.write(b);
    }

    static String readString(DataInputStream in) throws IOException {
        int n = in.readInt();
        if (n < 0 || n > MAX_FRAME) throw new IOException("bad string length " + n);
        byte[] b = new byte[n];
        in.readFully(b);
        return new String(b, StandardCharsets.UTF_8);
    }

    /**
     * A stream that reads the channel directly: the JDK's channel streams take the channel's
     * blocking lock for a read, which would hold up a write (the cancellation) for as long as
     * the read waits.
     */
    static InputStream in(SocketChannel ch) {
        return new InputStream() {
            @Override
            public int read() throws IOException {
                byte[] one = new byte[1];
                return read(one, 0, 1) < 0 ? -1 : one[0] & 0xff;
            }

            @Override
            public int read(byte[] b, int off, int len) throws IOException {
                if (len == 0) return 0;
                return ch.read(ByteBuffer.wrap(b, off, len));
            }
        };
    }

    /** A stream that writes the channel directly (see {@link #in}). */
    static OutputStream out(SocketChannel ch) {
        return new OutputStream() {
            @Override
            public void write(int b) throws IOException {
                write(new byte[] {(byte) b}, 0, 1);
            }

            @Override
            public void write(byte[] b, int off, int len) throws IOException {
                ByteBuffer bb = ByteBuffer.wrap(b, off, len);
                while (bb.hasRemaining()) ch.write(bb);
            }
        };
    }
}
