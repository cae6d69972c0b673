package org.handsim.gui;

import java.util.Arrays;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import org.handsim.clutch.ClutchState;
import org.handsim.model.HandModel;
import org.handsim.scenario.Scenario;
import org.handsim.model.Simulation;
import org.handsim.model.SimulationException;
import org.handsim.model.Snapshot;

/**
 * Runs the {@link HandModel} on its own thread, as an Easy-Java-Simulations program does:
 * play (evolve step after step), pause, one step, reset (initialise), at real time times a
 * speed factor or as fast as the machine goes. The window never touches the model.
 *
 * <h2>What the other threads see</h2>
 * <ul>
 *   <li>{@link #latest()}: the newest {@link State}, an immutable value published after each
 *       batch of steps (a volatile write: readers see a complete state or the previous one);</li>
 *   <li>{@link #drainTrace}: trace rows ({@link #ROW_LENGTH} doubles: generation, t, then per
 *       finger θk2, θk3 in degrees, θ̇k2, θ̇k3 in deg/s, τk2, τk3 in N·m, the contact force
 *       in N), one every {@link #TRACE_INTERVAL_S} simulated seconds, so the charts get every
 *       sample however fast the model runs and however seldom the window looks;</li>
 *   <li>{@link #drainEvents}: every change of a finger's clutch state, with the time of the
 *       step it happened in, for the same reason;</li>
 *   <li>{@link #grasp()}: the grasp's force closure, ε, volume and minimum hold, evaluated on a
 *       thread of its own from copies offered at each publication when the contacts changed,
 *       at most 10 times a second ({@link LiveGrasp}).</li>
 * </ul>
 * Commands ({@link #load}, {@link #play}, {@link #pause}, {@link #step}, {@link #reset},
 * {@link #setSpeed}) may be called from any thread; they are queued and run in order on the
 * simulation thread.
 *
 * <h2>Pacing</h2>
 * At speed s the model's time follows s × the wall time since Play (re-anchored after each
 * pause); in each turn of the loop it steps until it has caught up, at most
 * {@link #BATCH_BUDGET_NS} of work, then publishes. At "as fast as possible" ({@code s = 0})
 * it steps for one budget and publishes. A {@link SimulationException} stops the run and is
 * reported in the state ({@link State#error()}); so is any other exception from the model.
 */
public final class SimulationRunner implements AutoCloseable {
    /** Simulated seconds between trace rows. */
    public static final double TRACE_INTERVAL_S = 0.005;
    /** Doubles per trace row. */
    public static final int ROW_LENGTH = 2 + 3 * 7;
    static final long BATCH_BUDGET_NS = 12_000_000L;
    /**
     * Most steps a model is recorded for (the trace the File menu exports; about 300 bytes a
     * step): longer runs are simulated without a trace — {@code handsim run} writes theirs.
     */
    public static final long RECORD_LIMIT = 2_000_000L;

    /** Why a generation began. */
    public enum Origin { LOADED, RESET }

    /**
     * One published state.
     *
     * @param generation    changes when the model is rebuilt or reset (the charts start over)
     * @param publication   counts publications (a view that showed a preview knows when to stop)
     * @param scenario      the scenario being simulated
     * @param snapshot      the model's state (null before the first model is built)
     * @param breakaway     per finger the breakaway time, s (NaN: none yet)
     * @param playing       true while Play is on
     * @param finished      true when the scenario's duration is reached
     * @param error         the message that stopped the run, or null
     * @param note          a remark about the model (e.g. the object is not simulated), or null
     * @param warnings      what to know before trusting the run ({@code HandModel#startWarnings}: a
     *                      finger that starts inside the object), empty if nothing
     * @param origin        whether this generation was loaded or reset
     * @param recording     whether the model keeps a trace to export ({@link #RECORD_LIMIT})
     */
    public record State(long generation, long publication, Scenario scenario, Snapshot snapshot, double[] breakaway,
                        boolean playing, boolean finished, String error, String note, java.util.List<String> warnings,
                        Origin origin, boolean recording) {
        /** Simulated time, s. */
        public double time() { return snapshot == null ? 0 : snapshot.time(); }

        /** Clutch state of finger k (1..3). */
        public ClutchState clutch(int k) { return snapshot.fingers()[k - 1].state(); }
    }

    /**
     * A change of a finger's clutch state, seen at the end of the step it happened in.
     *
     * @param generation the model's generation
     * @param time       simulated time at the end of that step, s
     * @param finger     1..3
     */
    public record Event(long generation, double time, int finger, ClutchState from, ClutchState to) {}

    private final Function<Scenario, HandModel> factory;
    private final ConcurrentLinkedQueue<Event> events = new ConcurrentLinkedQueue<>();
    private final ClutchState[] lastClutch = new ClutchState[3];
    private final Thread thread;
    private final BlockingQueue<Runnable> commands = new LinkedBlockingQueue<>();
    private final ConcurrentLinkedQueue<double[]> trace = new ConcurrentLinkedQueue<>();
    private final LiveGrasp grasp = new LiveGrasp();
    private volatile State latest;
    private volatile boolean closed, held;

    // simulation-thread state
    private Scenario scenario;
    private HandModel model;
    private long generation, publication;
    private boolean playing;
    private double speed = 1.0;
    private double stopAt = Double.POSITIVE_INFINITY;
    private double anchorSim;
    private long anchorWall;
    private String error, note;
    private java.util.List<String> warnings = java.util.List.of();
    private Origin origin = Origin.LOADED;
    private double nextTraceTime;

    /**
     * A runner building models with {@link Simulation#model}, recording their trace (for the
     * export) up to {@link #RECORD_LIMIT} steps.
     */
    public SimulationRunner() {
        this(s -> Simulation.model(s, Math.ceil(s.duration() / s.dt()) <= RECORD_LIMIT));
    }

    /** A runner building models with the given factory (tests may supply their own). */
    public SimulationRunner(Function<Scenario, HandModel> factory) {
        this.factory = factory;
        this.latest = new State(0, 0, null, null, nanArray(), false, false, null, null, java.util.List.of(), Origin.LOADED, false);
        this.thread = new Thread(this::loop, "handsim-simulation");
        this.thread.setDaemon(true);
        this.thread.start();
    }

    // ------------------------------------------------------------------ commands (any thread)
    /** Builds a new model for the scenario (paused at t = 0). */
    public void load(Scenario s) { commands.add(() -> build(s)); }

    /** Plays from where the model is. */
    public void play() { commands.add(() -> startPlaying(Double.POSITIVE_INFINITY)); }

    /** Plays until the simulated time reaches {@code t} seconds (or the end), then pauses. */
    public void playUntil(double t) { commands.add(() -> startPlaying(t)); }

    public void pause() { commands.add(() -> { playing = false; publish(); }); }

    /** One step of dt (pauses first). */
    public void step() {
        commands.add(() -> {
            playing = false;
            if (model != null && model.running() && error == null) advance();
            publish();
        });
    }

    /** Back to t = 0 of the same scenario (paused). */
    public void reset() {
        commands.add(() -> {
            playing = false;
            error = null;
            if (model != null) {
                model.initialise();
                origin = Origin.RESET;
                generation++;
                nextTraceTime = 0;
                traceRow();
                rememberClutch();
            }
            publish();
        });
    }

    /** Speed factor: 1 = real time, 0 = as fast as possible. */
    public void setSpeed(double factor) {
        if (!(factor >= 0) || Double.isInfinite(factor)) throw new IllegalArgumentException("speed must be >= 0 and finite, got " + factor);
        commands.add(() -> {
            speed = factor;
            anchor();
        });
    }

    /**
     * Holds a playing model where it is ({@code true}) or lets it go on ({@code false}); commands
     * still run (load, reset, step, play's target). A scripted window holds its model between
     * actions so that it moves only while the script plays or waits: a button that starts a run
     * (Path Planning's Run) then cannot carry the model past the time the next {@code play T}
     * names, however slow the machine — one script, one state. Any thread.
     */
    public void hold(boolean on) {
        held = on;
        if (!on) commands.add(this::anchor);   // real-time pacing starts again from here, not from before the hold
    }

    /** Whether the model is held ({@link #hold}). */
    public boolean held() { return held; }

    /** The newest published state (never null). */
    public State latest() { return latest; }

    /** The live evaluation of the model's grasp ({@link LiveGrasp#latest()}: the newest result). */
    public LiveGrasp grasp() { return grasp; }

    /** Moves every trace row published so far into {@code sink}; returns how many. */
    public int drainTrace(java.util.function.Consumer<double[]> sink) {
        int n = 0;
        for (double[] row; (row = trace.poll()) != null; n++) sink.accept(row);
        return n;
    }


    /** Moves every clutch event published so far into {@code sink}; returns how many. */
    public int drainEvents(java.util.function.Consumer<Event> sink) {
        int n = 0;
        for (Event e; (e = events.poll()) != null; n++) sink.accept(e);
        return n;
    }

    /**
     * Writes the current model's trace — every step simulated so far, in the trace.csv contract
     * of {@code handsim run} (the same writer, {@code trace.Recorder}) — on the simulation thread,
     * between steps. The future completes with the number of rows, or exceptionally (no model,
     * not recorded, an I/O error).
     */
    public java.util.concurrent.CompletableFuture<Integer> exportTrace(java.nio.file.Path file) {
        java.util.concurrent.CompletableFuture<Integer> done = new java.util.concurrent.CompletableFuture<>();
        commands.add(() -> {
            try {
                if (model == null) throw new IllegalStateException("no model to export");
                if (model.recorder() == null) {
                    throw new IllegalStateException("this run is not recorded (more than " + RECORD_LIMIT + " steps): use handsim run on the saved scenario");
                }
                model.recorder().writeCsv(file);
                done.complete(model.recorder().rows());
            } catch (java.io.IOException | RuntimeException e) {
                done.completeExceptionally(e);
            }
        });
        return done;
    }

    /** Blocks until every command queued before this call has run. */
    public void sync() throws InterruptedException {
        java.util.concurrent.CountDownLatch done = new java.util.concurrent.CountDownLatch(1);
        commands.add(done::countDown);
        done.await();
    }

    @Override
    public void close() {
        closed = true;
        thread.interrupt();
        grasp.close();
    }

    // ------------------------------------------------------------------ the loop (simulation thread)
    private void loop() {
        try {
            while (!closed) {
                Runnable c = playing && !held ? commands.poll() : commands.poll(100, TimeUnit.MILLISECONDS);
                while (c != null) {
                    c.run();
                    c = commands.poll();
                }
                if (playing && !held) turn();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void build(Scenario s) {
        playing = false;
        error = null;
        note = null;
        scenario = s;
        model = null;
        try {
            model = factory.apply(s);
        } catch (RuntimeException e) {
            if (s.object() != null) {
                // keep the hand working: simulate without the object and say so
                note = "object shown but not simulated: " + e.getMessage();
                try {
                    model = factory.apply(s.withObject(null));
                } catch (RuntimeException e2) {
                    error = "cannot build the model: " + e2.getMessage();
                }
            } else {
                error = "cannot build the model: " + e.getMessage();
            }
        }
        origin = Origin.LOADED;
        warnings = model != null ? model.startWarnings() : java.util.List.of();
        generation++;
        nextTraceTime = 0;
        if (model != null) {
            traceRow();
            rememberClutch();
        }
        publish();
    }

    private void rememberClutch() {
        for (int k = 1; k <= 3; k++) lastClutch[k - 1] = model.state(k);
    }

    private void startPlaying(double until) {
        if (model == null || error != null) { publish(); return; }
        stopAt = until;
        playing = model.running() && model.time() < until;
        anchor();
        publish();
    }

    private void anchor() {
        anchorWall = System.nanoTime();
        anchorSim = model == null ? 0 : model.time();
    }

    /** One turn of the loop while playing: catch up with the wall clock (or one budget), publish. */
    private void turn() throws InterruptedException {
        long start = System.nanoTime();
        double target = speed == 0 ? Double.POSITIVE_INFINITY : anchorSim + speed * (start - anchorWall) / 1e9;
        target = Math.min(target, stopAt);
        int steps = 0;
        while (model.running() && model.time() + 0.5 * model.scenario().dt() < target) {
            if (!advance()) break;
            steps++;
            if ((steps & 15) == 0 && System.nanoTime() - start > BATCH_BUDGET_NS) break;
        }
        if (!model.running() || model.time() + 0.5 * model.scenario().dt() >= stopAt || error != null) playing = false;
        if (steps > 0 || !playing) publish();
        if (playing && speed != 0 && steps == 0) Thread.sleep(2);
    }

    /** One step, recording a trace row when one is due and clutch events; false if the run stopped with an error. */
    private boolean advance() {
        try {
            model.step();
            if (model.time() >= nextTraceTime - 1e-12) traceRow();
            for (int k = 1; k <= 3; k++) {
                ClutchState c = model.state(k);
                if (c != lastClutch[k - 1]) {
                    // the breakaway is located inside the step (HandModel): give its time, not the step's end
                    double at = c == ClutchState.BROKEN && lastClutch[k - 1] == ClutchState.BLOCKED && !Double.isNaN(model.breakawayTime(k))
                        ? model.breakawayTime(k) : model.time();
                    events.add(new Event(generation, at, k, lastClutch[k - 1], c));
                    lastClutch[k - 1] = c;
                }
            }
            return true;
        } catch (SimulationException e) {
            error = "simulation stopped: " + e.getMessage();
        } catch (RuntimeException e) {
            error = "simulation failed: " + e;
        }
        playing = false;
        return false;
    }

    private void traceRow() {
        double[] row = new double[ROW_LENGTH];
        row[0] = generation;
        row[1] = model.time();
        for (int k = 1; k <= 3; k++) {
            int o = 2 + 7 * (k - 1);
            double[] q = model.joints(k), qd = model.velocities(k), tau = model.torques(k);
            row[o] = Math.toDegrees(q[1]);
            row[o + 1] = Math.toDegrees(q[2]);
            row[o + 2] = Math.toDegrees(qd[1]);
            row[o + 3] = Math.toDegrees(qd[2]);
            row[o + 4] = tau[1];
            row[o + 5] = tau[2];
            row[o + 6] = model.contacts(k).forceSum();
        }
        trace.add(row);
        nextTraceTime = model.time() + TRACE_INTERVAL_S;
    }

    private void publish() {
        publication++;
        double[] br = nanArray();
        Snapshot snap = null;
        boolean finished = false;
        if (model != null) {
            snap = model.snapshot();
            for (int k = 1; k <= 3; k++) br[k - 1] = model.breakawayTime(k);
            finished = !model.running();
            // before the state: whoever sees this state and then awaits the grasp gets its grasp
            grasp.offer(generation, model, model.scenario().friction(), model.scenario().coneEdges(), !playing);
        }
        latest = new State(generation, publication, scenario, snap, br, playing, finished, error, note, warnings, origin,
            model != null && model.recorder() != null);
    }

    private static double[] nanArray() {
        double[] a = new double[3];
        Arrays.fill(a, Double.NaN);
        return a;
    }
}
