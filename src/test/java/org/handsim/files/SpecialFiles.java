package org.handsim.files;

import java.io.IOException;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.ServerSocketChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * A folder holding one of each kind of file that is not a regular file — a FIFO, a directory, a
 * socket — and the character device {@code /dev/null}: what every input of HandSim must refuse
 * at once with "is not a regular file" (files.InputFile). Opening the FIFO for reading would block
 * until a writer came: a test that hangs on it has found the bug.
 */
public final class SpecialFiles implements AutoCloseable {
    /** The folder. */
    public final Path dir;
    private final ServerSocketChannel socket;
    /** Name ("FIFO", "directory", "socket", "character device") → path, the kinds this machine could make. */
    public final Map<String, Path> all = new LinkedHashMap<>();

    public SpecialFiles() throws IOException, InterruptedException {
        dir = Files.createTempDirectory("handsim-special");
        Path fifo = dir.resolve("fifo.json");
        Process p = new ProcessBuilder("mkfifo", fifo.toString()).redirectErrorStream(true).start();
        if (p.waitFor(10, TimeUnit.SECONDS) && p.exitValue() == 0) all.put("a FIFO", fifo);
        Path folder = Files.createDirectory(dir.resolve("folder.wrl"));
        all.put("a directory", folder);
        Path sock = dir.resolve("socket.stl");
        ServerSocketChannel s = null;
        try {
            s = ServerSocketChannel.open(StandardProtocolFamily.UNIX);
            s.bind(UnixDomainSocketAddress.of(sock));
            all.put("a socket", sock);
        } catch (IOException | UnsupportedOperationException e) {
            if (s != null) s.close();
            s = null;
        }
        socket = s;
        if (Files.exists(Path.of("/dev/null"))) all.put("a character device", Path.of("/dev/null"));
    }

    /** The FIFO (null if mkfifo is missing). */
    public Path fifo() { return all.get("a FIFO"); }

    @Override
    public void close() throws IOException {
        if (socket != null) socket.close();
        try (var s = Files.walk(dir)) {
            s.sorted(java.util.Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
        }
    }
}
