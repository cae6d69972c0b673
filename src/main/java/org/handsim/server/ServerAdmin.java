package org.handsim.server;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.SocketChannel;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** What {@code handsim server status} and {@code stop} do: find the user's servers, ask each for its state, tell them to stop. */
public final class ServerAdmin {
    private ServerAdmin() {}

    /** One server as it describes itself: its first lines as fields (pid, since, commands, state, used, memory, log, home, cwd ...). */
    public record Status(Path socket, Map<String, String> fields) {
        public String field(String name) { return fields.getOrDefault(name, "?"); }

        /** When it last ran a command (or started), milliseconds since 1970; 0 if it did not say. */
        public long used() {
            try {
                return Long.parseLong(field("used"));
            } catch (NumberFormatException e) {
                return 0;
            }
        }
    }

    /**
     * Why the last command that could have been served ran in its own JVM (a time, the outcome
     * and the reason: a path naming the client's own descriptors, another environment, a server
     * that did not answer ...), or null.
     */
    public static String lastNotServed() {
        return lastNotServed(Client.configuredFolder());
    }

    /** As {@link #lastNotServed()}, for the servers' folder {@code configured}. */
    public static String lastNotServed(Path configured) {
        if (configured == null) return null;
        Path dir = Client.effective(configured);
        try {
            String t = Files.readString(dir.resolve(Client.NOT_SERVED), java.nio.charset.StandardCharsets.UTF_8).trim();
            int sp = t.indexOf(' ');
            return java.time.Instant.ofEpochMilli(Long.parseLong(t.substring(0, sp))) + " " + t.substring(sp + 1);
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /** The servers folder ({@link Client#folder()}), or null. */
    public static Path folder() {
        return Client.folder();
    }

    /** Null if the servers folder is fit for use, else why not. */
    public static String unsafe() {
        Path dir = Client.folder();
        return dir == null ? "no cache folder (no home directory)" : Files.isDirectory(dir) ? Client.unsafe(dir, false) : null;
    }

    /**
     * Every server that answers in the folder (each within {@link Client#ANSWER_MS}); what servers
     * that are gone left (a server killed with SIGKILL) is removed when their locks show no
     * server holds them ({@link ServerFiles#removeStale}).
     */
    public static List<Status> servers() throws IOException {
        return servers(Client.folder());
    }

    /** As {@link #servers()}, in the folder {@code dir} (or its short stand-in, {@link Client#effective}). */
    public static List<Status> servers(Path dir) throws IOException {
        return servers(dir, null);
    }

    /** As {@link #servers(Path)}, without asking the server of socket {@code except} (a server about to serve, asking about the others). */
    private static List<Status> servers(Path dir, Path except) throws IOException {
        dir = Client.effective(dir);
        List<Status> found = new ArrayList<>();
        if (dir == null || !Files.isDirectory(dir) || Client.unsafe(dir, false) != null) return found;
        ServerFiles.removeStale(dir);
        List<Path> sockets = new ArrayList<>();
        try (DirectoryStream<Path> s = Files.newDirectoryStream(dir, "*.sock")) {
            for (Path p : s) sockets.add(p);
        }
        sockets.sort(null);
        for (Path socket : sockets) {
            if (except != null && socket.getFileName().equals(except.getFileName())) continue;   // the same folder
            String text = ask(socket, Client.STATUS);
            if (text == null) continue;
            Map<String, String> fields = new LinkedHashMap<>();
            for (String line : text.split("\n")) {
                int sp = line.indexOf(' ');
                if (sp > 0) fields.putIfAbsent(line.substring(0, sp), line.substring(sp + 1));
            }
            found.add(new Status(socket, fields));
        }
        return found;
    }

    /** Tells the server of {@code socket} to stop (after its running command, if any); whether it said yes. */
    public static boolean stop(Path socket) {
        return ask(socket, Client.STOP) != null;
    }

    /**
     * Keeps at most {@code max} servers in {@code dir}: the least recently used others are told
     * to stop (a busy one after its command). The server of {@code self} is never one of them.
     */
    static void keepAtMost(Path dir, int max, Path self) {
        List<Status> all;
        try {
            // not asking itself: it answers only once it accepts, after this, so its own status
            // request would wait out the whole answer time, and so would its first client
            all = servers(dir, self);
        } catch (IOException e) {
            return;
        }
        all.sort(java.util.Comparator.comparingLong(Status::used));
        for (int i = 0; i < all.size() - (max - 1); i++) stop(all.get(i).socket());
    }

    /** Sends a request of {@code kind}; the status text, "" for an accepted stop, null if nobody answered. */
    private static String ask(Path socket, byte kind) {
        try (SocketChannel ch = SocketChannel.open(StandardProtocolFamily.UNIX)) {
            Watchdog dog = new Watchdog(ch, Client.answerMs());   // a stopped server must not hold up status or stop
            try {
                ch.connect(UnixDomainSocketAddress.of(socket));
                DataOutputStream out = new DataOutputStream(new BufferedOutputStream(Client.out(ch)));
                DataInputStream in = new DataInputStream(new BufferedInputStream(Client.in(ch)));
                out.writeInt(Client.MAGIC);
                out.writeByte(kind);
                out.flush();
                if (kind == Client.STATUS) return Client.readString(in);
                return in.read() == Client.ACCEPTED ? "" : null;
            } finally {
                dog.disarm();
            }
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }
}
