package org.handsim.plan;

/**
 * ε over the approach directions in bounded memory: a grid of {@link #CELL_DEG}° cells in
 * azimuth atan2(a_y, a_x) ∈ [−180°, 180°) and elevation asin(a_z) ∈ [−90°, 90°] of the approach
 * a, each keeping the best ε of its trials and how many fell in it.
 */
public final class DirectionMap {
    /** Cell size, degrees. */
    public static final int CELL_DEG = 10;
    public static final int AZ_CELLS = 360 / CELL_DEG, EL_CELLS = 180 / CELL_DEG;
    private final double[][] best = new double[AZ_CELLS][EL_CELLS];
    private final int[][] count = new int[AZ_CELLS][EL_CELLS];

    /** Adds a trial: its approach (unit vector, world) and ε (0 without force closure). */
    public void add(double[] a, double epsilon) {
        int i = azimuthCell(a), j = elevationCell(a);
        count[i][j]++;
        if (epsilon > best[i][j]) best[i][j] = epsilon;
    }

    static int azimuthCell(double[] a) {
        double az = Math.toDegrees(Math.atan2(a[1], a[0]));
        return Math.min(AZ_CELLS - 1, Math.max(0, (int) Math.floor((az + 180) / CELL_DEG)));
    }

    static int elevationCell(double[] a) {
        double el = Math.toDegrees(Math.asin(Math.max(-1, Math.min(1, a[2]))));
        return Math.min(EL_CELLS - 1, Math.max(0, (int) Math.floor((el + 90) / CELL_DEG)));
    }

    /** Best ε per cell [azimuth][elevation] (a copy). */
    public double[][] best() {
        double[][] c = new double[AZ_CELLS][];
        for (int i = 0; i < AZ_CELLS; i++) c[i] = best[i].clone();
        return c;
    }

    /** Trials per cell [azimuth][elevation] (a copy). */
    public int[][] count() {
        int[][] c = new int[AZ_CELLS][];
        for (int i = 0; i < AZ_CELLS; i++) c[i] = count[i].clone();
        return c;
    }
}
