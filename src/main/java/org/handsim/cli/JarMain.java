package org.handsim.cli;

import java.awt.GraphicsEnvironment;

/**
 * The runnable jar's entry point ({@code java -jar handsim-VERSION-all.jar}, built by
 * {@code gradle fatJar}), in the manner of the paper's Easy-Java-Simulations programs: one file
 * that runs by itself. Without arguments it opens the window (on a desktop; without a display it
 * says how to run the commands instead); with arguments it is the {@code handsim} command, e.g.
 * {@code java -jar handsim-0.1.0-all.jar run --out DIR} runs the paper's experiment headless.
 * The command runs on a thread with a 16 MB stack, what the {@code ./handsim} launcher gives the
 * JVM with {@code -Xss16m} (deeply nested VRML files are parsed recursively).
 */
public final class JarMain {
    private JarMain() {}

    /** Stack of the command's thread, bytes. */
    static final long STACK_BYTES = 16L << 20;

    public static void main(String[] args) throws InterruptedException {
        String[] a = args;
        if (a.length == 0) {
            if (GraphicsEnvironment.isHeadless() || System.getenv("DISPLAY") == null && isX11()) {
                System.err.println(noDisplay(jarName()));
                System.exit(CliError.USAGE);
            }
            a = new String[] {"gui"};
        }
        String[] command = a;
        int[] code = {1};
        Thread t = new Thread(null, () -> code[0] = HandSim.execute(command), "main-16m", STACK_BYTES);
        t.start();
        t.join();
        System.exit(code[0]);
    }

    /** What to do without a display, with the jar's own file name in the example commands. */
    static String noDisplay(String jar) {
        String run = "  java -jar " + jar + " run --out out/paper", help = "  java -jar " + jar + " --help";
        int w = Math.max(run.length(), help.length()) + 4;
        return "handsim: no display for the window; the commands work without one, e.g.\n"
            + String.format("%-" + w + "s%s%n%-" + w + "s%s", run, "the paper's experiment", help, "every command");
    }

    /** The running jar's file name (what the user typed after -jar), or the built name when it cannot be told. */
    static String jarName() {
        try {
            java.nio.file.Path p = java.nio.file.Path.of(JarMain.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            if (p.getFileName() != null && p.getFileName().toString().endsWith(".jar")) return p.getFileName().toString();
        } catch (java.net.URISyntaxException | RuntimeException e) {
            // fall through: the name gradle fatJar gives it
        }
        String v = JarMain.class.getPackage() != null ? JarMain.class.getPackage().getImplementationVersion() : null;
        return "handsim-" + (v != null ? v : "VERSION") + "-all.jar";
    }

    private static boolean isX11() {
        String os = System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT);
        return !os.contains("win") && !os.contains("mac");
    }
}
