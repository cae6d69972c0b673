package org.handsim.gui;

import static org.handsim.gui.GuiWindowTest.needDisplay;
import static org.handsim.gui.GuiWindowTest.runGui;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.handsim.TestPaths;
import org.handsim.text.Json;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The window says what the model does: Pause stops the simulated time and Play goes on from it,
 * the status bar saying so; the Objects panel shows the unit its object is read in — what Save
 * scenario writes — whatever the units list holds for the next import. The window under a
 * script (a child JVM on the test display, as {@link GuiWindowTest}).
 */
@Tag("slow")   // a child JVM with the window: ./test --all (CI) runs it, the quick ./test does not
class WindowShowsWhatRunsTest {
    private static final Pattern STATE = Pattern.compile("gui: state: t = ([0-9.]+) s, (\\w+)");

    /**
     * The paper's run played at real speed: while it plays, wall time moves the model (the
     * control: the same waits with the model playing advance it); after Pause (the button, then
     * Space) the time stays to the printed digit through a wait of 0.8 s, the run state and the
     * status bar say paused; Play and Space go on from that time, not from 0.
     */
    @Test
    void pauseHoldsTheTimeAndPlayGoesOnFromIt() throws Exception {
        needDisplay();
        Path dir = Files.createTempDirectory("handsim-pause").toRealPath();
        Path script = dir.resolve("pause.txt");
        Files.writeString(script, String.join("\n",
            "speed 1",
            "press Play",
            "assert-runstate running",
            "wait 500",
            "log state",          // 0: playing
            "press Pause",
            "assert-runstate paused",
            "assert-status paused",
            "log state",          // 1: paused
            "wait 800",
            "log state",          // 2: still paused, same time
            "press Play",
            "assert-runstate running",
            "wait 500",
            "log state",          // 3: went on
            "key SPACE",
            "assert-runstate paused",
            "assert-status paused",
            "log state",          // 4: paused by Space
            "wait 800",
            "log state",          // 5: same time
            "key SPACE",
            "wait 500",
            "log state",          // 6: went on
            ""));
        GuiWindowTest.Child c = runGui(dir, "--script", script.toString());
        assertEquals(0, c.code(), c.log());
        List<Double> t = new ArrayList<>();
        List<String> words = new ArrayList<>();
        Matcher m = STATE.matcher(c.log());
        while (m.find()) {
            t.add(Double.parseDouble(m.group(1)));
            words.add(m.group(2));
        }
        assertEquals(7, t.size(), "each line once (stdout and stderr are one log here):\n" + c.log());
        assertEquals(2, c.log().split("gui: pressed Play\\R", -1).length - 1, "each line once:\n" + c.log());
        assertEquals(List.of("running", "paused", "paused", "running", "paused", "paused", "running"), words, c.log());
        double[] s = t.stream().mapToDouble(Double::doubleValue).toArray();
        // a 1 ms step at real speed: 0.5 s of wall time is well over 10 steps even on a loaded machine
        assertTrue(s[0] > 0.01, "playing, the model moved: " + s[0]);
        assertTrue(s[1] >= s[0], "Pause stops where the model is: " + s[1] + " after " + s[0]);
        assertEquals(s[1], s[2], "0.8 s of wall time paused: the simulated time stays");
        assertTrue(s[3] > s[2] + 0.01, "Play goes on from the paused time: " + s[3] + " after " + s[2]);
        assertTrue(s[3] < s[2] + 2, "not from a restart, and at most real speed: " + s[3] + " after " + s[2]);
        assertTrue(s[4] >= s[3]);
        assertEquals(s[4], s[5], "paused by Space: the simulated time stays");
        assertTrue(s[6] > s[5] + 0.01, "Space goes on: " + s[6] + " after " + s[5]);
        VrmlTesting.deleteTree(dir);
    }

    /**
     * The Objects panel's units line says the unit the object is read in, which is what Save
     * scenario writes as {@code object.units}: the paper's "m"; a scenario's "cm"; a scenario that
     * leaves it to the file's size, mm for the mug in millimetres, said so. The units list stays
     * the choice for the next import (auto): opening a scenario in cm and then importing the mug
     * twice reads it in mm both times (the second import must not take the unit shown); chosen
     * mm in the list, the import says mm without "judged".
     */
    @Test
    void theObjectsPanelShowsTheUnitsUsedApartFromTheImportChoice() throws Exception {
        needDisplay();
        Path dir = Files.createTempDirectory("handsim-units").toRealPath();
        Path mug = TestPaths.root().resolve("vrml/objects/mug_mm.stl");
        Path cube = TestPaths.root().resolve("vrml/objects/cube.wrl");
        String scenario = "{\"name\":\"%s\",\"object\":{\"file\":\"%s\",\"position_m\":[0,0,0.3]%s},\"dt_s\":0.001,\"duration_s\":0.01}";
        Path inCm = dir.resolve("cube-cm.json"), bySize = dir.resolve("mug-by-size.json");
        Files.writeString(inCm, String.format(scenario, "cube-cm", cube, ",\"units\":\"cm\""));
        Files.writeString(bySize, String.format(scenario, "mug-by-size", mug, ""));
        Path[] saved = new Path[6];
        for (int i = 0; i < saved.length; i++) saved[i] = dir.resolve("saved" + i + ".json");
        Path script = dir.resolve("units.txt");
        Files.writeString(script, String.join("\n",
            "press Objects",
            "log objects",                       // 0: the paper's cube, "m"
            "save-scenario " + saved[0],
            "open " + inCm,
            "log objects",                       // 1: cm
            "save-scenario " + saved[1],
            "open " + bySize,
            "log objects",                       // 2: mm judged
            "save-scenario " + saved[2],
            "open " + inCm,
            "import " + mug,
            "log objects",                       // 3: the list's auto: mm judged, not the cm shown before
            "save-scenario " + saved[3],
            "import " + mug,
            "log objects",                       // 4: the second import alike
            "save-scenario " + saved[4],
            "press obj.remove",
            "set obj.units mm",
            "import " + mug,
            "log objects",                       // 5: chosen mm
            "save-scenario " + saved[5],
            ""));
        GuiWindowTest.Child c = runGui(dir, "--script", script.toString());
        assertEquals(0, c.code(), c.log());
        List<String> units = new ArrayList<>();
        for (String l : c.log().split("\\R")) if (l.startsWith("gui: objects: units used: ")) units.add(l.substring("gui: objects: ".length()));
        assertEquals(List.of("units used: m", "units used: cm", "units used: mm (judged by the file's size)",
            "units used: mm (judged by the file's size)", "units used: mm (judged by the file's size)", "units used: mm"), units, c.log());
        String[] written = {"m", "cm", "mm", "mm", "mm", "mm"};
        for (int i = 0; i < saved.length; i++) {
            @SuppressWarnings("unchecked")
            Map<String, Object> j = (Map<String, Object>) Json.parse(saved[i].toString(), Files.readString(saved[i]));
            @SuppressWarnings("unchecked")
            Map<String, Object> o = (Map<String, Object>) j.get("object");
            assertEquals(written[i], o.get("units"), "Save scenario " + i + " writes the unit shown");
            assertTrue(units.get(i).startsWith("units used: " + o.get("units")), units.get(i));
        }
        VrmlTesting.deleteTree(dir);
    }
}
