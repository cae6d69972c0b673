package org.handsim.server;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.SocketChannel;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** What {@code handsim server status} and {@code stop} do: find the user's servers, ask each for its state, tell them to stop. */
public final class ServerAdmin {
    private ServerAdmin() {}

    /** One server as it describes itself: its first lines as fields (pid, since, commands, state, log, home, cwd ...). */
    public record Status(Path socket, Map<String, String> fields) {
        public String field(String name) { return fields.getOrDefault(name, "?"); }
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
     * Every server that answers in the folder; sockets nobody listens on (a server killed with
     * SIGKILL) are removed when their lock shows no server holds them.
     */
    public static List<Status> servers() throws IOException {
        return servers(Client.folder());
    }

    /** As {@link #servers()}, in the folder {@code dir}. */
    public static List<Status> servers(Path dir) throws IOException {
        List<Status> found = new ArrayList<>();
        if (dir == null || !Files.isDirectory(dir) || Client.unsafe(dir, false) != null) return found;
        List<Path> sockets = new ArrayList<>();
        try (DirectoryStream<Path> s = Files.newDirectoryStream(dir, "*.sock")) {
            for (Path p : s) sockets.add(p);
        }
        sockets.sort(null);
        for (Path socket : sockets) {
            String text = ask(socket, Client.STATUS);
            if (text == null) {
                removeIfStale(dir, socket);
                continue;
            }
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

    /** Sends a request of {@code kind}; the status text, "" for an accepted stop, null if nobody answered. */
    private static String ask(Path socket, byte kind) {
        try (SocketChannel ch = SocketChannel.open(StandardProtocolFamily.UNIX)) {
            ch.connect(UnixDomainSocketAddress.of(socket));
            DataOutputStream out = new DataOutputStream(new BufferedOutputStream(Client.out(ch)));
            DataInputStream in = new DataInputStream(new BufferedInputStream(Client.in(ch)));
            out.writeInt(Client.MAGIC);
            out.writeByte(kind);
            out.flush();
            if (kind == Client.STATUS) return Client.readString(in);
            return in.read() == Client.ACCEPTED ? "" : null;
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /** Removes a socket whose lock nobody holds (its server is gone). */
    static boolean removeIfStale(Path dir, Path socket) {
        String name = socket.getFileName().toString();
        String key = name.substring(0, name.length() - ".sock".length());
        try (FileChannel ch = FileChannel.open(Client.lockFile(dir, key), StandardOpenOption.CREATE, StandardOpenOption.WRITE)) {
            FileLock lock = ch.tryLock();
            if (lock == null) return false;
            try {
                return Files.deleteIfExists(socket);
            } finally {
                lock.release();
            }
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }
}
