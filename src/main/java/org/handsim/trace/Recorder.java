package org.handsim.trace;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.handsim.clutch.ClutchState;
import org.handsim.files.AtomicFile;
import org.handsim.text.Decimal;

/**
 * Records one row per step and writes {@code trace.csv}. The header is a contract (README,
 * "Outputs"): {@code t_s}, then per finger k = 1, 2, 3:
 * {@code qM{k}_counts, theta{k}1_rad, theta{k}2_rad, theta{k}3_rad, dtheta{k}2_rad_s,
 * dtheta{k}3_rad_s, ddtheta{k}2_rad_s2, ddtheta{k}3_rad_s2, tau{k}2_Nm, tau{k}3_Nm, state{k},
 * contacts{k}, force{k}_N}, then {@code qM4_counts}, then {@code clutch1_Nm, clutch2_Nm,
 * clutch3_Nm} (the torque through each finger's clutch, {@link HandModel#clutchTorque}) and
 * {@code residual1_Nm, residual2_Nm, residual3_Nm} (how far each finger's contact forces are
 * from carrying its joint torques, {@link HandModel#torqueResidual}), then {@code carried11_Nm,
 * carried12_Nm, carried13_Nm, carried21_Nm, carried22_Nm, carried23_Nm, carried32_Nm,
 * carried33_Nm} (the torque each joint carries, {@link HandModel#carriedTorque}; finger 3 has no
 * joint k1), then {@code tau11_Nm, tau21_Nm, tau31_Nm} (the spread joint's torque τk1, which the
 * window's Dynamics table shows beside τk2 and τk3; 0 for finger 3, whose joint 31 is fixed, as
 * {@code theta31_rad} is 0). A run with a free object ({@link #withObject()}) appends the object's
 * columns {@link #OBJECT_COLUMNS}: its centre of mass (world, m), orientation (unit quaternion,
 * mesh frame to world), speed (m/s) and angular speed (rad/s), its number of contact points and
 * largest penetration (m), and its displacement (m) and rotation (degrees) relative to the palm
 * since the start; a fixed run's header is unchanged. Numbers are written by
 * {@link Decimal}; every column but {@code t_s} is a physical value, cleaned of rounding noise
 * ({@link Decimal#clean}); the clutch states by their names, the contact counts as integers.
 * {@link TraceLine} writes each line.
 *
 * <p>Two kinds (bounded memory):
 * <ul>
 *   <li>{@link #Recorder()} keeps every row in memory (tests, short runs; the columns double as
 *       they grow);</li>
 *   <li>{@link #bounded(Path, long)} keeps memory flat in the number of steps: each finished row
 *       is written to the trace file's temporary name at once (renamed by {@link #finish()},
 *       deleted by {@link #close()} if the run fails), and memory holds only every
 *       {@link #stride()}-th row and the last — the rows the charts draw
 *       ({@link #CHART_POINTS}); {@link #rows()}, {@link #time(int)}, {@link #get} then index
 *       the kept rows.</li>
 * </ul>
 * Appending a row allocates nothing except when the kept columns grow (doubling); writing a
 * row formats its numbers.
 */
public final class Recorder implements AutoCloseable {
    /** Most points a chart draws of a trace: a bounded recorder keeps about this many rows (up to twice). */
    public static final int CHART_POINTS = 1500;
    /** Numeric per-finger columns, in header order (state, contacts, force follow them). */
    static final String[] FINGER_COLUMNS = {
        "qM%d_counts", "theta%d1_rad", "theta%d2_rad", "theta%d3_rad", "dtheta%d2_rad_s", "dtheta%d3_rad_s",
        "ddtheta%d2_rad_s2", "ddtheta%d3_rad_s2", "tau%d2_Nm", "tau%d3_Nm"};
    /** Column indices inside a finger's numeric block. */
    public static final int Q = 0, TH1 = 1, TH2 = 2, TH3 = 3, DTH2 = 4, DTH3 = 5, DDTH2 = 6, DDTH3 = 7, TAU2 = 8, TAU3 = 9;
    private static final int NF = FINGER_COLUMNS.length;
    private static final ClutchState[] STATES = ClutchState.values();

    private int rows;                 // rows in memory; the last one is the row being filled
    private long total;               // rows begun
    private final long stride;        // a finished row r stays in memory when r % stride == 0
    private final Path target;        // null: memory only
    private RowWriter writer;         // started when the first row is finished
    private int buffered = 2;         // rows the writer may lag behind
    private boolean finished;
    private final boolean[] moved = new boolean[3];
    private final double[] firstQ = new double[3];
    private double[] time = new double[1024];
    private double[][] num = new double[3 * NF][1024];
    private byte[][] state = new byte[3][1024];
    private int[][] contacts = new int[3][1024];
    private double[][] force = new double[3][1024];
    private double[] spread = new double[1024];
    private double[][] clutch = new double[3][1024], residual = new double[3][1024];
    private double[][] carried = new double[CARRIED][1024];
    /** The carried-torque columns: joints 11, 12, 13, 21, 22, 23, 32, 33. */
    static final int CARRIED = 8;
    /** The spread joints' torque columns τ11, τ21, τ31. */
    static final int SPREAD_TAU = 3;
    private double[][] spreadTau = new double[SPREAD_TAU][1024];
    /** The free object's columns, appended after {@code tau31_Nm} when the run has one. */
    public static final String[] OBJECT_COLUMNS = {"obj_x_m", "obj_y_m", "obj_z_m", "obj_qw", "obj_qx", "obj_qy", "obj_qz",
        "obj_speed_m_s", "obj_spin_rad_s", "obj_contacts", "obj_penetration_m", "obj_disp_m", "obj_rot_deg"};
    /** Indices of the object's columns ({@link #setObject}, {@link #object}). */
    public static final int OBJ_X = 0, OBJ_Y = 1, OBJ_Z = 2, OBJ_QW = 3, OBJ_QX = 4, OBJ_QY = 5, OBJ_QZ = 6, OBJ_SPEED = 7, OBJ_SPIN = 8,
        OBJ_CONTACTS = 9, OBJ_PENETRATION = 10, OBJ_DISP = 11, OBJ_ROT = 12;
    private static final int NO = OBJECT_COLUMNS.length;
    private boolean object;
    private double[][] obj = new double[0][];
    private int width = WIDTH;

    /** A recorder that keeps every row in memory. */
    public Recorder() {
        this.stride = 1;
        this.target = null;
    }

    private Recorder(Path trace, long expectedRows) {
        this.stride = Math.max(1, expectedRows / CHART_POINTS);
        this.target = trace;
        this.buffered = (int) Math.max(2, Math.min(expectedRows + 1, RowWriter.MAX_BUFFERED));
    }

    /**
     * A recorder whose memory does not grow with the run: rows stream to {@code trace}'s
     * temporary file (none if {@code trace} is null) and memory keeps every
     * {@code expectedRows / }{@value #CHART_POINTS}-th row and the last.
     *
     * @param trace        trace.csv to write, or null for the chart rows only
     * @param expectedRows rows the run will record (steps + 1), which sets the stride
     */
    public static Recorder bounded(Path trace, long expectedRows) {
        return new Recorder(trace, expectedRows);
    }

    /**
     * Adds the free object's columns ({@link #OBJECT_COLUMNS}) to every row; before the first
     * row only. Returns this.
     */
    public Recorder withObject() {
        if (total > 0) throw new IllegalStateException("the object's columns must be added before the first row");
        if (!object) {
            object = true;
            obj = new double[NO][time.length];
            width = WIDTH + NO;
        }
        return this;
    }

    /** Whether rows carry the free object's columns. */
    public boolean objectColumns() { return object; }

    /** Sets the free object's column c ({@link #OBJ_X} … {@link #OBJ_ROT}) in the current row. */
    public void setObject(int c, double v) { obj[c][rows - 1] = v; }

    /** The free object's column c in a row in memory. */
    public double object(int c, int row) { return obj[c][row]; }

    /** A copy of the free object's column c over the rows in memory. */
    public double[] objectColumn(int c) { return Arrays.copyOf(obj[c], rows); }

    /** The header line of this recorder's trace.csv (without newline): {@link #header()}, then the object's columns if it has them. */
    public String headerLine() {
        return object ? header() + "," + String.join(",", OBJECT_COLUMNS) : header();
    }

    /** The header line of trace.csv of a run without a free object (without newline). */
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
        for (int k = 1; k <= 3; k++) h.add("clutch" + k + "_Nm");
        for (int k = 1; k <= 3; k++) h.add("residual" + k + "_Nm");
        for (int c = 0; c < CARRIED; c++) h.add("carried" + carriedFinger(c) + carriedJoint(c) + "_Nm");
        for (int k = 1; k <= SPREAD_TAU; k++) h.add("tau" + k + "1_Nm");
        return String.join(",", h);
    }

    /** Starts a new row at time t (seconds); fill it with the setters. */
    public void beginRow(double t) {
        if (finished) throw new IllegalStateException("the trace is finished");
        if (rows > 0 && !finishRow()) rows--;   // written, not kept: its slot takes the new row
        if (rows == time.length) grow();
        time[rows] = t;
        rows++;
        total++;
    }

    /** Writes the row being filled (when streaming) and says whether memory keeps it. */
    private boolean finishRow() {
        int r = rows - 1;
        long index = total - 1;
        for (int k = 0; k < 3; k++) {
            double q = num[k * NF + Q][r];
            if (index == 0) firstQ[k] = q;
            else if (q != firstQ[k]) moved[k] = true;
        }
        if (target != null) {
            if (writer == null) writer = new RowWriter(target, buffered, width, object, headerLine());   // the folder and the temporary file appear now
            writer.put(this, r);
        }
        return index % stride == 0;
    }

    /** Row r as {@link #WIDTH} numbers in trace.csv's column order (state as its ordinal), into {@code to} from {@code at}. */
    private void copyRow(int r, double[] to, int at) {
        int i = at;
        to[i++] = time[r];
        for (int k = 0; k < 3; k++) {
            for (int c = 0; c < NF; c++) to[i++] = num[k * NF + c][r];
            to[i++] = state[k][r];
            to[i++] = contacts[k][r];
            to[i++] = force[k][r];
        }
        to[i++] = spread[r];
        for (int k = 0; k < 3; k++) to[i++] = clutch[k][r];
        for (int k = 0; k < 3; k++) to[i++] = residual[k][r];
        for (int c = 0; c < CARRIED; c++) to[i++] = carried[c][r];
        for (int k = 0; k < SPREAD_TAU; k++) to[i++] = spreadTau[k][r];
        if (object) for (int c = 0; c < NO; c++) to[i++] = obj[c][r];
    }

    /** Finger of carried-torque column c (0..7). */
    private static int carriedFinger(int c) { return c < 6 ? 1 + c / 3 : 3; }

    /** Joint (1..3) of carried-torque column c (0..7). */
    private static int carriedJoint(int c) { return c < 6 ? 1 + c % 3 : c - 4; }

    /** Column of finger k's joint j (finger 3: j = 2, 3). */
    private static int carriedColumn(int k, int j) {
        if (k == 3 && j == 1) throw new IllegalArgumentException("finger 3 has no joint 31");
        return k < 3 ? 3 * (k - 1) + j - 1 : 4 + j;
    }

    /**
     * Width of a row of numbers: t, per finger 10 numbers, state, contacts, force, then the
     * spread, then per finger the clutch torque, then per finger the residual, then the carried
     * torques, then the spread joints' torques.
     */
    static final int WIDTH = 1 + 3 * (NF + 3) + 1 + 6 + CARRIED + SPREAD_TAU;

    /**
     * Formats and writes rows on its own thread (the run goes on on the other core). The
     * stepping thread copies each finished row into a chunk of {@value #CHUNK} rows taken from
     * a fixed pool and hands full chunks over (one hand-over per {@value #CHUNK} rows, so the
     * threads rarely wake each other); it allocates nothing and waits only when the writer is a
     * whole pool behind. The pool holds the whole run up to {@value #MAX_BUFFERED} rows
     * (25 MB), so a run of that length never waits for its trace.
     */
    private static final class RowWriter extends Thread {
        static final int CHUNK = 256;
        static final int MAX_BUFFERED = 65_536;
        private static final double[] END = new double[0];
        private final int chunks;
        private final java.util.concurrent.ArrayBlockingQueue<double[]> free;
        private final java.util.concurrent.ArrayBlockingQueue<double[]> full;
        private final java.util.concurrent.ArrayBlockingQueue<Integer> counts;
        private final AtomicFile file;
        private double[] current;
        private int inCurrent;
        private volatile Throwable failure;
        private volatile long nanos;
        private final int width;
        private final boolean object;
        private final String header;

        RowWriter(Path target, int buffered, int width, boolean object, String header) {
            super("trace-writer");
            this.width = width;
            this.object = object;
            this.header = header;
            this.chunks = Math.max(2, (buffered + CHUNK - 1) / CHUNK);
            this.free = new java.util.concurrent.ArrayBlockingQueue<>(chunks);
            this.full = new java.util.concurrent.ArrayBlockingQueue<>(chunks + 1);
            this.counts = new java.util.concurrent.ArrayBlockingQueue<>(chunks + 1);
            setDaemon(true);
            for (int i = 0; i < chunks; i++) free.add(new double[CHUNK * width]);   // before the file: nothing to clean up if this fails
            try {
                file = new AtomicFile(target);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
            start();
        }

        /** Copies row r of the recorder into the current chunk; hands the chunk over when full. */
        void put(Recorder rec, int r) {
            check();
            if (current == null) {
                try {
                    current = free.take();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new IllegalStateException("interrupted while writing the trace", e);
                }
                inCurrent = 0;
            }
            rec.copyRow(r, current, inCurrent * width);
            if (++inCurrent == CHUNK) handOver();
        }

        private void handOver() {
            counts.add(inCurrent);
            full.add(current);
            current = null;
        }

        private void check() {
            Throwable f = failure;
            if (f instanceof IOException) throw new UncheckedIOException((IOException) f);
            if (f != null) throw new IllegalStateException("writing the trace failed: " + f, f);
        }

        @Override
        public void run() {
            StringBuilder sb = new StringBuilder(512);
            double[] row = new double[width];
            try {
                AsciiOut w = new AsciiOut(file.stream());
                TraceLine line = new TraceLine(object);
                long t0 = System.nanoTime();
                sb.append(header).append('\n');
                w.append(sb);
                nanos += System.nanoTime() - t0;
                while (true) {
                    double[] chunk = full.take();
                    if (chunk == END) break;
                    int n = counts.take();
                    t0 = System.nanoTime();
                    for (int i = 0; i < n; i++) {
                        System.arraycopy(chunk, i * width, row, 0, width);
                        w.write(line.bytes(), line.encode(row));   // the line's text: TraceLine
                    }
                    nanos += System.nanoTime() - t0;
                    free.add(chunk);
                }
                w.flush();
            } catch (Throwable t) {
                failure = t;
                free.clear();
                for (int i = 0; i < chunks; i++) free.offer(new double[CHUNK * width]);   // never leave the stepping thread waiting
            }
        }

        /** Hands over the last rows, waits for all of them, then renames the file onto its name. */
        void finish() throws IOException {
            if (current != null && inCurrent > 0) handOver();
            full.add(END);
            try {
                join();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while finishing the trace", e);
            }
            if (failure instanceof IOException) throw (IOException) failure;
            check();
            long t0 = System.nanoTime();
            file.commit();
            nanos += System.nanoTime() - t0;
        }

        /** Stops the thread and deletes the temporary file. */
        void abort() throws IOException {
            full.offer(END);
            try {
                join(10_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            file.close();
        }
    }

    /**
     * trace.csv's bytes: its text is ASCII (numbers, state names, commas), so each character is
     * one byte, copied into a buffer — a third of the writer thread's time went to a
     * {@code Writer}'s UTF-8 encoder and its copies.
     */
    private static final class AsciiOut {
        private final java.io.OutputStream out;
        private final byte[] buf = new byte[1 << 16];
        private int n;

        AsciiOut(java.io.OutputStream out) { this.out = out; }

        void append(CharSequence s) throws IOException {
            int len = s.length();
            if (n + len > buf.length) flushBuffer();
            if (len > buf.length) throw new IOException("a trace line longer than " + buf.length + " characters");
            for (int i = 0; i < len; i++) {
                char c = s.charAt(i);
                if (c >= 0x80) throw new IOException("a trace line that is not ASCII");
                buf[n++] = (byte) c;
            }
        }

        /** Appends the first {@code len} bytes of {@code b} (ASCII already). */
        void write(byte[] b, int len) throws IOException {
            if (n + len > buf.length) flushBuffer();
            if (len > buf.length) throw new IOException("a trace line longer than " + buf.length + " characters");
            System.arraycopy(b, 0, buf, n, len);
            n += len;
        }

        private void flushBuffer() throws IOException {
            out.write(buf, 0, n);
            n = 0;
        }

        void flush() throws IOException {
            flushBuffer();
            out.flush();
        }
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
            clutch[k] = Arrays.copyOf(clutch[k], n);
            residual[k] = Arrays.copyOf(residual[k], n);
        }
        for (int c = 0; c < CARRIED; c++) carried[c] = Arrays.copyOf(carried[c], n);
        for (int k = 0; k < SPREAD_TAU; k++) spreadTau[k] = Arrays.copyOf(spreadTau[k], n);
        for (int c = 0; c < obj.length; c++) obj[c] = Arrays.copyOf(obj[c], n);
    }

    /** Sets numeric column c (Q .. TAU3) of finger k (1..3) in the current row. */
    public void set(int k, int c, double v) { num[(k - 1) * NF + c][rows - 1] = v; }

    public void setState(int k, ClutchState s) { state[k - 1][rows - 1] = (byte) s.ordinal(); }

    public void setContacts(int k, int n, double forceSum) {
        contacts[k - 1][rows - 1] = n;
        force[k - 1][rows - 1] = forceSum;
    }

    public void setSpread(double q4) { spread[rows - 1] = q4; }

    /** Finger k's clutch torque and contact-force residual (N·m) in the current row. */
    public void setClutchAndResidual(int k, double clutchNm, double residualNm) {
        clutch[k - 1][rows - 1] = clutchNm;
        residual[k - 1][rows - 1] = residualNm;
    }

    /** The torque finger k's joint j carries (N·m) in the current row (finger 3: j = 2, 3). */
    public void setCarried(int k, int j, double nm) { carried[carriedColumn(k, j)][rows - 1] = nm; }

    /** The spread joint's torque τk1 of finger k (N·m) in the current row. */
    public void setSpreadTorque(int k, double nm) { spreadTau[k - 1][rows - 1] = nm; }

    /** Rows in memory: all rows, or for a bounded recorder every {@link #stride()}-th and the last. */
    public int rows() { return rows; }
    /** Rows recorded in all (the rows of trace.csv). */
    public long totalRows() { return total; }
    /** Of the recorded rows, memory keeps those whose index is a multiple of this, and the last. */
    public long stride() { return stride; }
    public double time(int row) { return time[row]; }
    public double get(int k, int c, int row) { return num[(k - 1) * NF + c][row]; }
    public ClutchState state(int k, int row) { return STATES[state[k - 1][row]]; }
    public int contacts(int k, int row) { return contacts[k - 1][row]; }
    public double force(int k, int row) { return force[k - 1][row]; }
    public double spread(int row) { return spread[row]; }
    /** Finger k's clutch torque in a row in memory, N·m. */
    public double clutch(int k, int row) { return clutch[k - 1][row]; }
    /** Finger k's contact-force residual in a row in memory, N·m. */
    public double residual(int k, int row) { return residual[k - 1][row]; }
    /** The torque finger k's joint j carries in a row in memory, N·m (finger 3: j = 2, 3). */
    public double carried(int k, int j, int row) { return carried[carriedColumn(k, j)][row]; }
    /** The spread joint's torque τk1 of finger k in a row in memory, N·m. */
    public double spreadTorque(int k, int row) { return spreadTau[k - 1][row]; }
    /** Whether finger k's motor count ever differed from its first row's (over every row recorded). */
    public boolean moved(int k) {
        if (rows == 0) return false;
        double q = num[(k - 1) * NF + Q][rows - 1];
        return moved[k - 1] || (total > 1 && q != firstQ[k - 1]);
    }
    /** Seconds the trace writer spent formatting and writing rows (on its own thread). */
    public double writeSeconds() { return writer == null ? 0 : writer.nanos / 1e9; }

    /** A copy of column c of finger k over the rows in memory. */
    public double[] column(int k, int c) { return Arrays.copyOf(num[(k - 1) * NF + c], rows); }
    public double[] times() { return Arrays.copyOf(time, rows); }
    public double[] forces(int k) { return Arrays.copyOf(force[k - 1], rows); }

    /** Clears all rows (keeps capacity); a streaming recorder can only be cleared before its first row is written. */
    public void clear() {
        if (writer != null) throw new IllegalStateException("a streamed trace cannot be restarted");
        rows = 0;
        total = 0;
        Arrays.fill(moved, false);
    }

    /**
     * Ends a bounded recorder's trace: writes the last row and renames the file onto its name
     * (nothing to do for a memory-only recorder).
     */
    public void finish() throws IOException {
        if (finished) return;
        if (rows > 0) finishRow();
        finished = true;
        if (writer != null) writer.finish();
    }

    /** Deletes the temporary trace file unless {@link #finish()} committed it. */
    @Override
    public void close() throws IOException {
        finished = true;
        if (writer != null && writer.isAlive()) writer.abort();
        else if (writer != null) writer.file.close();
    }

    /** Writes all rows in memory as trace.csv atomically (nothing appears under the name unless complete). */
    public void writeCsv(Path target) throws IOException {
        try (AtomicFile f = new AtomicFile(target)) {
            AsciiOut w = new AsciiOut(f.stream());
            w.append(headerLine() + "\n");
            double[] row = new double[width];
            TraceLine line = new TraceLine(object);
            for (int r = 0; r < rows; r++) {
                copyRow(r, row, 0);
                w.write(line.bytes(), line.encode(row));
            }
            w.flush();
            f.commit();
        }
    }
}
