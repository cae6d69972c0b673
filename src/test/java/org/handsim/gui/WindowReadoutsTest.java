package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Component;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.swing.JTable;
import javax.swing.table.DefaultTableModel;
import org.handsim.TestPaths;
import org.handsim.clutch.ClutchState;
import org.handsim.cli.CliTesting;
import org.handsim.model.HandModel;
import org.handsim.scenario.Scenario;
import org.handsim.model.Simulation;
import org.handsim.model.Snapshot;
import org.handsim.vrml.VrmlTesting;
import org.junit.jupiter.api.Test;

/** Readouts of the window that need no window: the time label and the Dynamics table's columns. */
class WindowReadoutsTest {
    /**
     * Every time the window shows of the paper's run is the one {@code handsim run} prints, to its
     * last printed digit: the time label and the Events box's header say the run's length (8.947 s
     * at the paper's end, not the trajectories' 8.9464 written as 8.946), the Events list and the
     * Dynamics table's breakaway column the breakaway time of finger 3.
     */
    @Test
    void everyTimeTheWindowShowsIsTheCommandLinesToThePrintedDigit() throws Exception {
        Path paper = TestPaths.root().resolve("scenarios/paper-breakaway.json");
        Path dir = Files.createTempDirectory("handsim-time-label");
        CliTesting.Run r = CliTesting.run("run", paper.toString(), "--out", dir.toString(), "--no-charts");
        assertEquals(0, r.code(), r.err());
        Matcher m = Pattern.compile("paper-breakaway: ([0-9.]+) s simulated in (\\d+) steps").matcher(r.out());
        assertTrue(m.find(), r.out());
        Scenario s = Scenario.load(paper);
        assertTrue(s.duration() < 8.9465, "the paper's trajectories end before the last step: " + s.duration());
        HandModel end = Simulation.model(s, false);
        end.run(null);
        assertEquals(Long.parseLong(m.group(2)), end.stepIndex());
        assertEquals(HandModel.endTime(s), end.time(), "endTime is the time of the last step");
        assertEquals("t = " + m.group(1) + " s / " + m.group(1) + " s", HandSimWindow.timeText(state(s, end.snapshot())));
        assertEquals("t = 0.000 s / " + m.group(1) + " s", HandSimWindow.timeText(state(s, null)));
        assertEquals("Run of paper-breakaway with cube.wrl, " + m.group(1) + " s:" + String.format("%n"), DynamicsPanel.eventsHeader(state(s, null)));
        Matcher b = Pattern.compile("finger 3: breakaway at t = ([0-9.]+) s").matcher(r.out());
        assertTrue(b.find(), r.out());
        // the window's event carries the model's breakaway time, located inside its step (SimulationRunner)
        SimulationRunner.Event e = new SimulationRunner.Event(1, end.breakawayTime(3), 3, ClutchState.BLOCKED, ClutchState.BROKEN);
        assertTrue(DynamicsPanel.line(e).startsWith("t = " + b.group(1) + " s  finger 3: BLOCKED → BROKEN"), DynamicsPanel.line(e));
        Object[] row = new Object[8];
        DynamicsPanel.row(3, end.snapshot().fingers()[2], end.breakawayTime(3), row);
        assertEquals(b.group(1), row[7], "the Dynamics table's breakaway column");
        VrmlTesting.deleteTree(dir);
    }

    private static SimulationRunner.State state(Scenario s, Snapshot snap) {
        return new SimulationRunner.State(1, 1, s, snap, new double[3], false, snap != null, null, null, List.of(),
            SimulationRunner.Origin.LOADED, false);
    }

    /**
     * Every value the Dynamics table shows fits its column whole (no "-0.0…"): the widest
     * samples and the values of the mug grasp, as the table's own renderer draws them.
     */
    @Test
    void theDynamicsTableShowsEveryValueWhole() {
        Scenario s = Scenario.load(TestPaths.root().resolve("scenarios/mug-grasp.json"));
        HandModel m = Simulation.model(s, false);
        DefaultTableModel model = new DefaultTableModel(new Object[] {"k", "clutch", "τk1", "τk2", "τk3", "cont.", "force", "break"}, 0);
        model.addRow(new Object[] {3, "BLOCKED", "-9.999", "-9.999", "-9.999", 99, "999.99", "10.0000"});
        while (m.running()) {
            m.step();
            if (m.stepIndex() % 50 != 0) continue;
            for (int k = 1; k <= 3; k++) {
                double[] tau = m.torques(k);
                double b = m.breakawayTime(k);
                model.addRow(new Object[] {k, m.state(k), Widgets.fmt(tau[0], 3), Widgets.fmt(tau[1], 3), Widgets.fmt(tau[2], 3),
                    m.contacts(k).size(), Widgets.fmt(m.contacts(k).forceSum(), 2), Double.isNaN(b) ? "–" : Widgets.fmt(b, 4)});
            }
        }
        JTable t = new JTable(model);
        t.setFont(Widgets.small());
        t.getTableHeader().setFont(Widgets.small());
        DynamicsPanel.sizeColumns(t);
        int negative = 0;
        for (int r = 0; r < model.getRowCount(); r++) {
            for (int c = 0; c < model.getColumnCount(); c++) {
                Component cell = t.prepareRenderer(t.getCellRenderer(r, c), r, c);
                int need = cell.getPreferredSize().width, have = t.getColumnModel().getColumn(c).getMinWidth();
                assertTrue(need <= have, "row " + r + " column " + c + ": '" + model.getValueAt(r, c) + "' needs " + need + " px, the column has " + have);
                String v = String.valueOf(model.getValueAt(r, c));
                assertTrue(!v.matches("-0(\\.0*)?"), "no -0: " + v);
                if (v.startsWith("-")) negative++;
            }
        }
        assertTrue(negative > 0, "the run shows negative torques, whose minus sign must fit too");
    }
}
