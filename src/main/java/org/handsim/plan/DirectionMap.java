package org.handsim.plan;

/**
 * ε over the approach directions in bounded memory: the sphere of approach directions a cut into
 * cells of equal area, as many as give each about {@value #TRIALS_PER_CELL} trials, each keeping
 * the best ε of its trials and how many fell in it.
 *
 * <p>The cells are a grid in azimuth φ = atan2(a_y, a_x) ∈ [−180°, 180°) and z = a_z = sin(elevation)
 * ∈ [−1, 1]: Lambert's cylindrical projection preserves area, so equal steps in φ and z are equal
 * areas on the sphere (Archimedes' hat-box theorem), and the planner's Fibonacci directions,
 * spread evenly over the sphere, put nearly the same number of trials in every cell. A grid of
 * 10° × 10° in elevation instead had cells near the poles 60 times smaller than at the equator
 * and, for 500 trials over its 648 cells, most of it empty or holding one trial. The cells are as
 * square as the projection allows (equal sides in radians of φ and in z).
 */
public final class DirectionMap {
    /** Trials a cell is sized for. With a quarter of trials in force closure (the mug), 8 trials
     *  leave about one cell in ten without a force-closure grasp to show. */
    public static final int TRIALS_PER_CELL = 8;

    private final int azCells, zCells;
    private final double[][] best;
    private final int[][] count;

    /** A map sized for {@code trials} trials (at least one cell). */
    public DirectionMap(int trials) {
        double cells = Math.max(1.0, trials / (double) TRIALS_PER_CELL);
        // square cells: (2π / s) · (2 / s) = cells
        double side = Math.sqrt(4 * Math.PI / cells);
        zCells = Math.max(1, (int) Math.round(2 / side));
        azCells = Math.max(1, (int) Math.round(cells / zCells));
        best = new double[azCells][zCells];
        count = new int[azCells][zCells];
    }

    /** Adds a trial: its approach (unit vector, world) and ε (0 without force closure). */
    public void add(double[] a, double epsilon) {
        int i = azimuthCell(a), j = zCell(a);
        count[i][j]++;
        if (epsilon > best[i][j]) best[i][j] = epsilon;
    }

    int azimuthCell(double[] a) {
        double az = Math.atan2(a[1], a[0]);   // [−π, π]
        return Math.min(azCells - 1, Math.max(0, (int) Math.floor((az + Math.PI) / (2 * Math.PI) * azCells)));
    }

    int zCell(double[] a) {
        double z = Math.max(-1, Math.min(1, a[2]));
        return Math.min(zCells - 1, Math.max(0, (int) Math.floor((z + 1) / 2 * zCells)));
    }

    /** Cells in azimuth (each 360° / this wide). */
    public int azimuthCells() { return azCells; }

    /** Cells in z = sin(elevation) (each 2 / this high). */
    public int zCells() { return zCells; }

    /** Best ε per cell [azimuth][z] (a copy). */
    public double[][] best() {
        double[][] c = new double[azCells][];
        for (int i = 0; i < azCells; i++) c[i] = best[i].clone();
        return c;
    }

    /** Trials per cell [azimuth][z] (a copy). */
    public int[][] count() {
        int[][] c = new int[azCells][];
        for (int i = 0; i < azCells; i++) c[i] = count[i].clone();
        return c;
    }
}
