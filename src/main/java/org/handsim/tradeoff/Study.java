package org.handsim.tradeoff;

import java.util.function.DoubleConsumer;
import org.handsim.chart.StudyTable;

/** One speed-against-accuracy study: runs its settings and returns the table behind its chart. */
public interface Study {
    /** File base name of its outputs, e.g. {@code 1-dt}. */
    String id();

    /**
     * Runs every setting.
     *
     * @param quick    fewer settings and timing runs (tests, smoke runs); the full run is the default
     * @param progress told the fraction done now and then (may be null)
     */
    StudyTable run(boolean quick, DoubleConsumer progress);
}
