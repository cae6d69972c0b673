package org.handsim.cli;

import java.io.PrintWriter;
import java.util.function.DoubleConsumer;
import org.handsim.process.CommandContext;

/**
 * A console progress bar on standard error for runs longer than a second: silent for the first
 * second, then redrawn in place ({@code \r}) on a terminal, or one line per 10 % otherwise (logs).
 * Each report is a cancellation point ({@link CommandContext}).
 */
final class ProgressBar implements DoubleConsumer {
    private final PrintWriter err;
    private final String label;
    private final long start = System.nanoTime();
    private final boolean terminal = CommandContext.console();
    private boolean shown;
    private int lastDecile = -1;

    ProgressBar(PrintWriter err, String label) {
        this.err = err;
        this.label = label;
    }

    @Override
    public void accept(double fraction) {
        CommandContext.checkCancelled();
        double elapsed = (System.nanoTime() - start) / 1e9;
        if (elapsed < 1.0 && fraction < 1.0) return;
        if (!shown && fraction >= 1.0) return; // finished within a second: say nothing
        shown = true;
        int pct = (int) Math.round(100 * fraction);
        if (terminal) {
            int bars = pct / 4;
            String eta = fraction > 0 ? String.format(" %5.1f s left", elapsed * (1 - fraction) / fraction) : "";
            err.print("\r" + label + " [" + "#".repeat(bars) + " ".repeat(25 - bars) + "] " + pct + "%" + eta + "   ");
            if (fraction >= 1.0) err.println();
            err.flush();
        } else {
            int decile = pct / 10;
            if (decile != lastDecile) {
                lastDecile = decile;
                err.println(label + ": " + pct + "% (" + String.format("%.1f", elapsed) + " s)");
                err.flush();
            }
        }
    }
}
