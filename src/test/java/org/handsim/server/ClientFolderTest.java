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
