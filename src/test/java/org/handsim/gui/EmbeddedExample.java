package org.handsim.gui;

import java.awt.BorderLayout;
import java.awt.Rectangle;
import java.awt.Robot;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import javax.imageio.ImageIO;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.SwingUtilities;
import org.handsim.scenario.Home;
import org.handsim.scenario.Scenario;

/**
 * The README's example of the embeddable simulator: another Swing program puts
 * {@link HandSimPanel} in its own frame with its own buttons and a label that a step listener
 * keeps up to date. Compiled with the tests so the README's code cannot rot;
 * {@code EmbeddedExampleTest} runs it.
 *
 * <p>{@code java ... org.handsim.gui.EmbeddedExample [SCENARIO] [--screenshot OUT.png]}: with a
 * screenshot it plays to t = 2.5 s, saves the frame and exits.
 */
public final class EmbeddedExample {
    private EmbeddedExample() {}

    public static void main(String[] args) throws Exception {
        Path scenarioFile = args.length > 0 && !args[0].startsWith("--") ? Path.of(args[0]) : Home.paperScenario();
        Path shot = args.length > 1 && args[args.length - 2].equals("--screenshot") ? Path.of(args[args.length - 1]) : null;

        // --- the README's example -------------------------------------------------------
        HandSimPanel sim = HandSimPanel.create(Scenario.load(scenarioFile));   // reads the hand's meshes: not on the EDT
        JLabel readout = new JLabel("t = 0.000 s");
        SwingUtilities.invokeLater(() -> {
            JFrame f = new JFrame("My grasp experiment (HandSimPanel embedded)");
            JPanel buttons = new JPanel();
            JButton play = new JButton("Play"), pause = new JButton("Pause"), step = new JButton("Step"), reset = new JButton("Reset");
            play.addActionListener(e -> sim.play());
            pause.addActionListener(e -> sim.pause());
            step.addActionListener(e -> sim.step());
            reset.addActionListener(e -> sim.reset());
            for (JButton b : new JButton[] {play, pause, step, reset}) buttons.add(b);
            buttons.add(readout);
            sim.addStepListener(s -> readout.setText(s.snapshot() == null ? "building the model ..." : String.format(Locale.ROOT,
                "t = %.3f s, finger 3 %s, %.1f N", s.time(), s.clutch(3), s.snapshot().fingers()[2].forceSum())));
            f.add(sim, BorderLayout.CENTER);
            f.add(buttons, BorderLayout.SOUTH);
            f.setSize(720, 600);
            f.setDefaultCloseOperation(JFrame.DISPOSE_ON_CLOSE);
            f.addWindowListener(new java.awt.event.WindowAdapter() {
                @Override
                public void windowClosed(java.awt.event.WindowEvent e) {
                    sim.dispose();
                }
            });
            f.setVisible(true);
        });
        // ---------------------------------------------------------------------------------
        if (shot == null) return;
        long deadline = System.currentTimeMillis() + 120_000;
        while (sim.view().framesRendered() == 0 && System.currentTimeMillis() < deadline) Thread.sleep(10);
        System.out.println("embedded: first frame");
        System.out.flush();
        CountDownLatch played = new CountDownLatch(1);
        sim.addStepListener(s -> { if (s.time() >= 2.5 - 1e-9 && !s.playing()) played.countDown(); });
        SwingUtilities.invokeAndWait(() -> {
            sim.setSpeed(0);
            sim.playUntil(2.5);
        });
        played.await();
        Thread.sleep(500);
        JFrame[] frame = new JFrame[1];
        String[] text = new String[1];
        SwingUtilities.invokeAndWait(() -> {
            frame[0] = (JFrame) SwingUtilities.getWindowAncestor(sim);
            text[0] = readout.getText();
        });
        Rectangle r = new Rectangle(frame[0].getLocationOnScreen(), frame[0].getSize());
        ImageIO.write(new Robot().createScreenCapture(r), "png", shot.toFile());
        System.out.println("embedded: " + text[0]);
        SwingUtilities.invokeAndWait(() -> {
            frame[0].dispose();
            sim.dispose();
        });
        X11Exit.closeDisplays();
        System.exit(0);
    }
}
