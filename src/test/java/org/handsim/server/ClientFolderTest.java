package org.handsim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.handsim.cli.ChildJvm;
import org.junit.jupiter.api.Test;

/**
 * The servers' folder is used only when nobody else can reach into it, and a command line goes
 * to a server only when it is one the server may run.
 */
class ClientFolderTest {
    @Test
    void onlyAFolderOfTheUsersWithMode700IsUsed() throws Exception {
        Path dir = Files.createTempDirectory("handsim-server-folder");
        try {
            Path made = dir.resolve("a").resolve("server");
            assertNull(Client.unsafe(made, true), "made with its parents");
            assertEquals("rwx------", PosixFilePermissions.toString(Files.getPosixFilePermissions(made)));
            Path open = Files.createDirectory(dir.resolve("open"));
            Files.setPosixFilePermissions(open, PosixFilePermissions.fromString("rwxr-xr-x"));
            assertEquals(open + " has mode rwxr-xr-x, not rwx------", Client.unsafe(open, true));
            Path link = Files.createSymbolicLink(dir.resolve("link"), made);
            assertEquals(link + " is not a folder", Client.unsafe(link, true), "a link, even to a good folder");
            Path file = Files.writeString(dir.resolve("file"), "");
            assertEquals(file + " is not a folder", Client.unsafe(file, true));
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }

    /**
     * Every length of servers' folder, around the limit too, gives a socket path the JDK binds: a
     * real bind at each length from 90 to 130 bytes (a path counted against the kernel's 107
     * bytes failed at exactly 107, where the JDK refuses).
     */
    @Test
    void aSocketBindsInAFolderOfAnyDepth() throws Exception {
        Path top = Files.createTempDirectory(Path.of("/tmp"), "handsim-socket-depth");
        java.util.Set<Path> shortOnes = new java.util.HashSet<>();
        try {
            int moved = 0;
            for (int n = 90; n <= 130; n++) {
                String key = "0123456789abcdef";
                int pad = n - Client.socketFile(top.resolve("x"), key).toString().length();   // one name of pad + 1 characters
                Path configured = top.resolve("f".repeat(pad + 1));
                assertEquals(n, Client.socketFile(configured, key).toString().length());
                Path dir = Client.effective(configured);
                if (!dir.equals(configured)) {
                    moved++;
                    shortOnes.add(dir);
                }
                assertNull(Client.unsafe(dir, true), dir.toString());
                Path socket = Client.socketFile(dir, key);
                try (java.nio.channels.ServerSocketChannel l = java.nio.channels.ServerSocketChannel.open(java.net.StandardProtocolFamily.UNIX)) {
                    l.bind(java.net.UnixDomainSocketAddress.of(socket));
                } catch (java.io.IOException e) {
                    throw new AssertionError(n + " bytes: " + socket + ": " + e, e);
                } finally {
                    Files.deleteIfExists(socket);
                }
            }
            assertEquals(130 - Client.MAX_SOCKET_PATH, moved, "the paths beyond the limit, and only those, go to a short folder");
        } finally {
            ChildJvm.deleteTree(top);
            for (Path p : shortOnes) ChildJvm.deleteTree(p);
        }
    }

    @Test
    void theShortLocalCommandsAreServed() {
        org.junit.jupiter.api.Assumptions.assumeFalse("0".equals(System.getenv("HANDSIM_SERVER")), "HANDSIM_SERVER=0 serves nothing");
        String home = System.getProperty("handsim.home");
        System.setProperty("handsim.home", "/somewhere");
        try {
            assertTrue(Client.eligible(new String[] {"run"}));
            assertTrue(Client.eligible(new String[] {"plan", "mug.wrl", "--engine", "local"}));
            assertEquals(false, Client.eligible(new String[] {"plan", "mug.wrl", "--engine", "spark"}));
            assertEquals(false, Client.eligible(new String[] {"sweep", "s.json", "--engine=spark"}));
            for (String c : new String[] {"gui", "tradeoff", "server", "help", "--help"}) assertEquals(false, Client.eligible(new String[] {c}), c);
            assertEquals(false, Client.eligible(new String[0]));
        } finally {
            if (home == null) System.clearProperty("handsim.home"); else System.setProperty("handsim.home", home);
        }
    }

    @Test
    void theSocketIsNamedByTheWholeIdentity() {
        String a = Client.identity();
        assertEquals(a, Client.identity(), "the same JVM, the same identity");
        assertEquals(16, Client.key(a).length());
        assertNotEquals(Client.key(a), Client.key(a.replace("umask ", "umask 7")), "one changed line, another socket");
        assertTrue(a.contains("cwd " + System.getProperty("user.dir") + " "), a);
    }
}
