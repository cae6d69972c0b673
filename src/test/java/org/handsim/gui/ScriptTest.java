package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The script language: what parses, and errors that name the file and line. */
class ScriptTest {
    @Test
    void parsesEveryVerbAndKeepsSpacesInTheLastArgument() throws Exception {
        Script s = Script.parse("a.txt", String.join("\n",
            "# a comment", "", "press Path Planning", "set fk3.counts 5000", "set obj.file my file.wrl",
            "import vrml/objects/cube.wrl", "play 1.5", "play END", "speed max", "speed 2", "wait 100",
            "screenshot out/x.png", "show hand off", "assert-state 3 broken|STALLED", "assert-status imported cube",
            "log dynamics", "measure-fps 3", "show CONES on", "log grasp", "log Contacts", "log Kinematics"));
        List<Script.Action> a = s.actions();
        assertEquals(19, a.size());
        assertEquals("kinematics", a.get(18).arg(0));
        assertEquals(List.of("cones", "on"), a.get(15).args());
        assertEquals("grasp", a.get(16).arg(0));
        assertEquals("contacts", a.get(17).arg(0));
        assertEquals(Script.Verb.PRESS, a.get(0).verb());
        assertEquals("Path Planning", a.get(0).arg(0));
        assertEquals(3, a.get(0).line());
        assertEquals(List.of("obj.file", "my file.wrl"), a.get(2).args());
        assertEquals("end", a.get(5).arg(0));
        assertEquals(List.of("hand", "off"), a.get(10).args());
        assertEquals("BROKEN|STALLED", a.get(11).arg(1));
    }

    @Test
    void unknownActionNamesTheLine() {
        Script.ScriptException e = assertThrows(Script.ScriptException.class,
            () -> Script.parse("t.txt", "press Kinematics\n\njump 3\n"));
        assertTrue(e.getMessage().startsWith("t.txt:3: unknown action 'jump'"), e.getMessage());
    }

    @Test
    void badArgumentsNameTheLine() {
        String[][] cases = {
            {"play soon", "t.txt:1: play needs a number"},
            {"play -1", "t.txt:1: play needs a number > 0"},
            {"set fk3.counts", "t.txt:1: set needs a field name and a value"},
            {"assert-state 4 FREE", "t.txt:1: assert-state needs a finger 1..3"},
            {"assert-state 3 SLIPPING", "t.txt:1: unknown clutch state 'SLIPPING'"},
            {"show palm off", "t.txt:1: show needs hand|object|contacts"},
            {"wait 1.5", "t.txt:1: wait needs whole milliseconds"},
            {"log everything", "t.txt:1: log needs dynamics, state, events, ik, charts, grasp, contacts, kinematics, path, objects or object"},
            {"camera sideways", "t.txt:1: camera needs home, fit, front, top or side"},
            {"key ESCAPE", "t.txt:1: key needs one of SPACE, RIGHT, R, H, F, 1, 2, 3"},
            {"save-charts c.jpg", "t.txt:1: save-charts needs a .png or .svg file"},
            {"resize 800 600", "t.txt:1: resize needs WIDTH HEIGHT in pixels, at least 1024 700"},
            {"assert-contacts 1.5", "t.txt:1: assert-contacts needs a whole number"},
            {"press Play\nexpect-error x", "t.txt:2: expect-error needs an action after it"},
            {"expect-error x\nexpect-error y\npress Play", "t.txt:1: expect-error needs an action after it"},
            {"press", "t.txt:1: press needs an argument"},
        };
        for (String[] c : cases) {
            Script.ScriptException e = assertThrows(Script.ScriptException.class, () -> Script.parse("t.txt", c[0]), c[0]);
            assertTrue(e.getMessage().startsWith(c[1]), c[0] + " -> " + e.getMessage());
        }
    }
}
