package org.handsim.gui;

import static org.handsim.cli.CliTesting.run;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.handsim.cli.CliTesting.Run;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Test;

/**
 * {@code handsim gui}'s refusals, which need no display: the tests run headless
 * ({@code java.awt.headless=true} in the build), exactly the case of a machine without one.
 */
class GuiCommandTest {
    static Path scenario(Path dir) throws Exception {
        Path f = dir.resolve("s.json");
        Files.writeString(f, "{\"name\":\"s\",\"dt_s\":0.001,\"duration_s\":1.0}");
        return f;
    }

    @Test
    void withoutADisplayItExits2AndSaysToUseXvfb() throws Exception {
        Path dir = Files.createTempDirectory("handsim-gui-test");
        Run r = run("gui", scenario(dir).toString());
        VrmlTesting.deleteTree(dir);
        assertEquals(2, r.code(), r.err());
        assertEquals(1, r.err().lines().count(), "one line: " + r.err());
        assertTrue(r.err().contains("no display") && r.err().contains("xvfb-run") && r.err().contains("./handsim gui"), r.err());
    }

    @Test
    void aBadScriptExits2NamingTheLineBeforeAnythingOpens() throws Exception {
        Path dir = Files.createTempDirectory("handsim-gui-test");
        Path script = dir.resolve("bad.txt");
        Files.writeString(script, "press Kinematics\nset fk3.counts 100\nfly away\n");
        Run r = run("gui", scenario(dir).toString(), "--script", script.toString());
        VrmlTesting.deleteTree(dir);
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("bad.txt:3: unknown action 'fly'"), r.err());
    }

    @Test
    void badOptionsExit2() throws Exception {
        assertEquals(2, run("gui", "--speed", "fast").code());
        assertEquals(2, run("gui", "--measure-fps", "-1").code());
    }

    @Test
    void helpDocumentsTheScriptLanguage() {
        Run r = run("gui", "--help");
        assertEquals(0, r.code(), r.err());
        for (String verb : new String[] {"press LABEL", "set NAME VALUE", "import FILE", "play T|end", "screenshot FILE",
            "assert-state", "measure-fps"}) {
            assertTrue(r.out().contains(verb), verb + " missing from --help:\n" + r.out());
        }
    }
}
