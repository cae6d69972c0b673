package org.handsim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import org.handsim.chart.ChartSet;
import org.handsim.text.SafeText;

/**
 * How a command ends its {@link ChartSet}: when the charts cannot be drawn it prints the one
 * warning (cause and remedy) and gives the reason for the JSON key {@value #MISSING_KEY}; the
 * command writes its tables and summary either way and exits 0.
 */
final class Charts {
    /** Key of summary.json, plan.json and tradeoff.json when the charts are missing (README, "Outputs"). */
    static final String MISSING_KEY = "charts_missing";

    private Charts() {}

    /** Writes the set's charts; null if written, else the reason (the warning is printed). */
    static String finish(ChartSet set, PrintWriter err) throws IOException {
        String reason = set.finish();
        if (reason == null) return null;
        String remedy = ChartSet.remedy(set.failure());
        String log = remedy.startsWith("this is a bug") ? HandSim.writeLog(set.failure()) : null;
        err.println(SafeText.line("handsim: warning: charts not drawn (" + reason + "): " + remedy
            + (log != null ? " (stack trace in " + log + ")" : "") + "; every table and summary is written, with \"" + MISSING_KEY + "\""));
        err.flush();
        return reason;
    }
}
