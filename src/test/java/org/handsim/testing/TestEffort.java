package org.handsim.testing;

/**
 * How many seeded random cases a test draws. {@code ./test --all} (CI, {@code gradle test -Pall})
 * and any run outside the build (an IDE) draw every case; the quick {@code ./test} draws the
 * first quarter of the same seeded sequence — the same checks on fewer cases, so a defect the
 * full run finds in case 3 is found by both, and the quick run stays under two minutes.
 */
public final class TestEffort {
    private TestEffort() {}

    /** The build's switch: "true" with -Pall, "false" in the quick run, absent outside the build. */
    private static final String PROPERTY = "handsim.tests.all";

    /** True when every case runs: ./test --all, CI, or outside the build. */
    public static boolean all() {
        return !"false".equals(System.getProperty(PROPERTY));
    }

    /** {@code all} cases in a full run, a quarter of them (at least one) in the quick run. */
    public static int cases(int all) {
        return all() ? all : Math.max(1, all / 4);
    }
}
