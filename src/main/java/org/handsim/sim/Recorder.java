package org.handsim.sim;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.handsim.util.AtomicFile;

/**
 * Records one row per step in primitive columns and writes {@code trace.csv}. The header is a
 * contract (README, "Outputs"): {@code t_s}, then per finger k = 1, 2, 3:
 * {@code qM{k}_counts, theta{k}1_rad, theta{k}2_rad, theta{k}3_rad, dtheta{k}2_rad_s,
 * dtheta{k}3_rad_s, ddtheta{k}2_rad_s2, ddtheta{k}3_rad_s2, tau{k}2_Nm, tau{k}3_Nm, state{k},
 * contacts{k}, force{k}_N}, then {@code qM4_counts}.
 *
 * <p>Appending a row allocates nothing except when the columns grow (doubling).
 */
public final class Recorder {
    /** Numeric per-finger columns, in header order (state, contacts, force follow them). */
    static final String[] FINGER_COLUMNS = {
        "qM%d_counts", "theta%d1_rad", "theta%d2_rad", "theta%d3_rad", "dtheta%d2_rad_s", "dtheta%d3_rad_s",
        "ddtheta%d2_rad_s2", "ddtheta%d3_rad_s2", "tau%d2_Nm", "tau%d3_Nm"};
    /** Column indices inside a finger's numeric block. */
    public static final int Q = 0, TH1 = 1, TH2 = 2, TH3 = 3, DTH2 = 4, DTH3 = 5, DDTH2 = 6, DDTH3 = 7, TAU2 = 8, TAU3 = 9;
    private static final int NF = FINGER_COLUMNS.length;

    private int rows;
    private double[] time = new double[1024];
    private double[][] num = new double[3 * NF][1024];
    private byte[][] state = new byte[3][1024];
    private int[][] contacts = new int[3][1024];
    private double[][] force = new double[3][1024];
    private double[] spread = new double[1024];

    /** The header line of trace.csv (without newline). */
    public static String header() {
        List<String> h = new ArrayList<>();
        h.add("t_s");
        for (int k = 1; k <= 3; k++) {
            for (String c : FINGER_COLUMNS) h.add(String.format(c, k));
            h.add("state" + k);
            h.add("contacts" + k);
            h.add("force" + k + "_N");
        }
        h.add("qM4_counts");
        return String.join(",", h);
    }

    /** Starts a new row at time t (seconds); fill it with the setters. */
    public void beginRow(double t) {
        if (rows == time.length) grow();
        time[rows] = t;
        rows++;
    }

    private void grow() {
        int n = time.length * 2;
        time = Arrays.copyOf(time, n);
        spread = Arrays.copyOf(spread, n);
        for (int i = 0; i < num.length; i++) num[i] = Arrays.copyOf(num[i], n);
        for (int k = 0; k < 3; k++) {
            state[k] = Arrays.copyOf(state[k], n);
            contacts[k] = Arrays.copyOf(contacts[k], n);
            force[k] = Arrays.copyOf(force[k], n);
        }
    }

    /** Sets numeric column c (Q .. TAU3) of finger k (1..3) in the current row. */
    public void set(int k, int c, double v) { num[(k - 1) * NF + c][rows - 1] = v; }

    public void setState(int k, ClutchState s) { state[k - 1][rows - 1] = (byte) s.ordinal(); }

    public void setContacts(int k, int n, double forceSum) {
        contacts[k - 1][rows - 1] = n;
        force[k - 1][rows - 1] = forceSum;
    }

    public void setSpread(double q4) { spread[rows - 1] = q4; }

    public int rows() { return rows; }
    public double time(int row) { return time[row]; }
    public double get(int k, int c, int row) { return num[(k - 1) * NF + c][row]; }
    public ClutchState state(int k, int row) { return ClutchState.values()[state[k - 1][row]]; }
    public int contacts(int k, int row) { return contacts[k - 1][row]; }
    public double force(int k, int row) { return force[k - 1][row]; }
    public double spread(int row) { return spread[row]; }

    /** A copy of column c of finger k over all rows. */
    public double[] column(int k, int c) { return Arrays.copyOf(num[(k - 1) * NF + c], rows); }
    public double[] times() { return Arrays.copyOf(time, rows); }
    public double[] forces(int k) { return Arrays.copyOf(force[k - 1], rows); }

    /** Clears all rows (keeps capacity). */
    public void clear() { rows = 0; }

    /** Writes trace.csv atomically (nothing appears under the name unless complete). */
    public void writeCsv(Path file) throws IOException {
        try (AtomicFile f = new AtomicFile(file)) {
            Writer w = f.writer();
            w.write(header());
            w.write('\n');
            StringBuilder sb = new StringBuilder(512);
            ClutchState[] states = ClutchState.values();
            for (int r = 0; r < rows; r++) {
                sb.setLength(0);
                sb.append(time[r]);
                for (int k = 0; k < 3; k++) {
                    for (int c = 0; c < NF; c++) sb.append(',').append(num[k * NF + c][r]);
                    sb.append(',').append(states[state[k][r]].name());
                    sb.append(',').append(contacts[k][r]);
                    sb.append(',').append(force[k][r]);
                }
                sb.append(',').append(spread[r]).append('\n');
                w.append(sb);
            }
            f.commit();
        }
    }
}
