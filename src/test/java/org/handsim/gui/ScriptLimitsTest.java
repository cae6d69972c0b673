package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.handsim.TestPaths;
import org.handsim.cli.CliTesting;
import org.handsim.files.SpecialFiles;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The window script's numbers and text: {@code measure-fps 1e9} ran until killed, {@code wait 1e12}
 * failed with a raw NumberFormatException (exit 1, not 2), {@code 0d} was a number, a byte-order
 * mark was an unknown action, an error printed raw ESC bytes and a 1 MB line gave a 2 000 065
 * character message, and {@code set fk3.counts 1e308} reported success while the window refused
 * the value. In the window (needs a display): the refused value fails the action, and a template
 * with a rotation of 1e300 or a FIFO fails to open with our message, not Java3D's or a hang.
 */
class ScriptLimitsTest {
    static String error(String text) {
        return assertThrows(Script.ScriptException.class, () -> Script.parse("t.txt", text)).getMessage();
    }

    @Test
    void numbersAreBoundedWhereTheScriptIsRead() throws Exception {
        assertEquals("t.txt:1: wait needs whole milliseconds in [0, 3600000] (an hour), got '1e12'", error("wait 1e12"));
        assertEquals("t.txt:1: measure-fps needs seconds in (0, 3600], got '1e9'", error("measure-fps 1e9"));
        assertEquals("t.txt:1: wait needs a number, got '0d'", error("wait 0d"));
        assertEquals("t.txt:1: play needs a number, got 'NaN'", error("play NaN"));
        assertEquals("t.txt:1: assert-contacts needs a whole number in [0, 1000000], got '1e300'", error("assert-contacts 1e300"));
        Script s = Script.parse("t.txt", "wait 1e3\nassert-contacts 2.0\nmeasure-fps 3600");
        assertEquals("1000", s.actions().get(0).arg(0), "what the runner reads back as a long");
        assertEquals("2", s.actions().get(1).arg(0));
    }

    @Test
    void aByteOrderMarkIsDroppedAndQuotedTextIsEscapedAndShort() throws Exception {
        assertEquals(Script.Verb.PRESS, Script.parse("t.txt", "\uFEFFpress Kinematics").actions().get(0).verb());
        String esc = error("ju\u001b[2J\u001b[31mmp 3");
        assertFalse(esc.contains("\u001b"), esc);
        assertTrue(esc.startsWith("t.txt:1: unknown action 'ju\\u001b[2J\\u001b[31mmp'"), esc);
        String huge = error("x".repeat(1 << 20));
        assertTrue(huge.length() < 400, huge.length() + " characters");
        assertTrue(huge.startsWith("t.txt:1: unknown action 'xxxx") && huge.contains("..."), huge);
    }

    /** Through the command: the script is read (UTF-8, BOM dropped, regular files only) and parsed before any window. */
    @Test
    void theCommandRefusesABadScriptWithExitTwo() throws Exception {
        Path dir = Files.createTempDirectory("handsim-script");
        try {
            Path wait = Files.writeString(dir.resolve("wait.txt"), "press Kinematics\nwait 1e12\n");
            CliTesting.Run r = CliTesting.run("gui", "--script", wait.toString());
            assertEquals(2, r.code(), r.err());
            assertEquals("handsim: " + wait + ":2: wait needs whole milliseconds in [0, 3600000] (an hour), got '1e12'", r.err());
            Path latin = Files.write(dir.resolve("latin.txt"), "press Kinematics\nset obj.file caf\u00e9.wrl\n".getBytes(StandardCharsets.ISO_8859_1));
            CliTesting.Run l = CliTesting.run("gui", "--script", latin.toString());
            assertEquals(3, l.code(), l.err());
            assertEquals("handsim: " + latin + ":2:17: not UTF-8: byte 0xe9 at offset 33 is not part of a UTF-8 character (save the file as UTF-8)",
                l.err());
        } finally {
            org.handsim.cli.ChildJvm.deleteTree(dir);
        }
    }

    /** In the window: a value the panel refuses fails the action (exit 1), and opening what is not a scenario says why. */
    @Tag("slow")
    @Test
    void theWindowSaysWhatItRefused() throws Exception {
        GuiWindowTest.needDisplay();
        Path dir = Files.createTempDirectory("handsim-script-window");
        try (SpecialFiles sf = new SpecialFiles()) {
            String paper = Files.readString(TestPaths.root().resolve("scenarios/paper-breakaway.json"))
                .replaceFirst("\"file\": *\"[^\"]*\"", "\"file\": \"" + TestPaths.root().resolve("vrml/objects/cube.wrl") + "\"");
            Path spun = Files.writeString(dir.resolve("spun.json"), paper.replaceFirst("\"rotation_rad\": *\\[[^\\]]*\\]",
                "\"rotation_rad\": [1e300, 0, 0]"));
            StringBuilder script = new StringBuilder(String.join("\n",
                "press Kinematics",
                "expect-error the window refused it",
                "set fk3.counts 1e308",
                "set fk3.counts 5000",
                "expect-error must be within +-1000 rad",
                "open " + spun));
            if (sf.fifo() != null) {
                script.append("\nexpect-error is not a regular file (a FIFO)\nopen ").append(sf.fifo());
                script.append("\nexpect-error is not a regular file (a FIFO)\nimport ").append(sf.fifo());
            }
            Path ok = Files.writeString(dir.resolve("refused.txt"), script.append('\n'));
            GuiWindowTest.Child c = GuiWindowTest.runGui(dir, "--script", ok.toString());
            assertEquals(0, c.code(), c.log());
            assertTrue(c.log().contains("gui: expected error: set fk3.counts 1e308: the window refused it: finger 3 counts must be in [0, 17500]"),
                c.log());
            assertFalse(c.log().contains("TransformGroup") || c.log().contains("non-affine"), c.log());
            Path bad = Files.writeString(dir.resolve("unexpected.txt"), "press Kinematics\nset fk3.counts 1e308\n");
            GuiWindowTest.Child f = GuiWindowTest.runGui(dir, "--script", bad.toString());
            assertEquals(1, f.code(), f.log());
            assertTrue(f.log().contains("handsim gui: " + bad + ":2: set fk3.counts 1e308: set fk3.counts 1e308: the window refused it"), f.log());
        } finally {
            org.handsim.cli.ChildJvm.deleteTree(dir);
        }
    }
}
