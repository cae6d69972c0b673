package org.handsim.gui;

import java.io.PrintWriter;
import java.util.concurrent.CountDownLatch;
import javax.swing.SwingUtilities;

/**
 * A child JVM's program for {@link BoundedCloseTest}: what {@code handsim gui} does at its end
 * when Java3D's threads are stuck. The event dispatch thread is blocked for ever (as by a
 * {@code SimpleUniverse.cleanup()} that waits for a dead Java3D thread) and a shutdown hook
 * never returns (as JOGL's can, waiting for such a thread); closing the window times out after
 * {@code args[1]} ms, and the program leaves as {@link GuiLauncher} does: exit code
 * {@code args[0]} from {@code System.exit}, halted with that code {@code args[2]} ms later.
 */
final class StuckWindowExit {
    private StuckWindowExit() {}

    public static void main(String[] args) throws Exception {
        int code = Integer.parseInt(args[0]);
        long closeMs = Long.parseLong(args[1]), graceMs = Long.parseLong(args[2]);
        CountDownLatch blocked = new CountDownLatch(1);
        SwingUtilities.invokeLater(() -> {
            blocked.countDown();
            while (true) {
                try {
                    Thread.sleep(Long.MAX_VALUE);
                } catch (InterruptedException ignored) {
                    // stays blocked
                }
            }
        });
        blocked.await();
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            System.out.println("stuck: shutdown hook waits for ever");
            System.out.flush();
            while (true) {
                try {
                    Thread.sleep(Long.MAX_VALUE);
                } catch (InterruptedException ignored) {
                    // stays blocked
                }
            }
        }));
        PrintWriter err = new PrintWriter(System.out, true);
        if (!GuiLauncher.close(() -> System.out.println("stuck: the window closed (it should not)"), closeMs, err)) {
            GuiLauncher.haltAfter(code, graceMs);
        }
        System.out.println("stuck: exit " + code);
        System.out.flush();
        System.exit(code);
    }
}
