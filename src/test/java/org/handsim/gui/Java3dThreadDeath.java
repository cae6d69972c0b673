package org.handsim.gui;

import java.util.Arrays;
import org.handsim.cli.HandSim;

/**
 * A child JVM's program for {@link DeadJava3dThreadTest}: {@code handsim gui ARGS} (from
 * {@code args[1]} on) while one of Java3D's threads dies. After the first frame ({@code gui:
 * first frame} on standard output), the thread whose name starts with {@code args[0]} is
 * stopped ({@code Thread.stop}: a {@code ThreadDeath} thrown where it is, as the
 * NullPointerException that can end Java3D's rendering-attributes thread is thrown in its work)
 * at a moment it is running, not waiting. Prints {@code death: stopped NAME} (or, on a JDK
 * whose {@code Thread.stop} only throws, 20 and later, {@code death: this JDK cannot stop a
 * thread}) and exits with {@code handsim gui}'s exit code.
 */
final class Java3dThreadDeath {
    private Java3dThreadDeath() {}

    @SuppressWarnings({"deprecation", "removal"})
    public static void main(String[] args) throws Exception {
        String name = args[0];
        java.util.concurrent.CountDownLatch firstFrame = new java.util.concurrent.CountDownLatch(1);
        java.io.PrintStream console = System.out;
        System.setOut(new java.io.PrintStream(new java.io.OutputStream() {
            private final StringBuilder line = new StringBuilder();

            @Override
            public void write(int b) {
                console.write(b);
                if (b == '\n') {
                    if (line.indexOf("gui: first frame") >= 0) firstFrame.countDown();
                    line.setLength(0);
                } else {
                    line.append((char) b);
                }
            }
        }, true, java.nio.charset.StandardCharsets.UTF_8));
        Thread killer = new Thread(() -> {
            try {
                firstFrame.await();
                Thread target = find(name);
                while (target.getState() != Thread.State.RUNNABLE) Thread.onSpinWait();
                try {
                    target.stop();
                } catch (UnsupportedOperationException e) {
                    System.out.println("death: this JDK cannot stop a thread (Thread.stop: " + e + ")");
                    System.out.flush();
                    return;
                }
                System.out.println("death: stopped " + name);
                System.out.flush();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "killer");
        killer.setDaemon(true);
        killer.start();
        System.exit(HandSim.execute(Arrays.copyOfRange(args, 1, args.length)));
    }

    private static Thread find(String prefix) {
        for (Thread t : Thread.getAllStackTraces().keySet()) if (t.getName().startsWith(prefix) && t.isAlive()) return t;
        return null;
    }
}
