package org.handsim.gui;

import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import org.handsim.grasp.GraspAssessment;
import org.handsim.model.HandModel;

/**
 * The grasp of the running model, evaluated live for the window: force closure, ε, volume and the minimum hold ({@link GraspAssessment}), on a thread of
 * its own, so that neither the simulation thread nor the event dispatch thread waits for it.
 *
 * <h2>How it keeps up without holding anything back</h2>
 * <ol>
 *   <li>The simulation thread {@link #offer offers} the model at each publication. That costs
 *       one copy of what an evaluation reads ({@link GraspAssessment.Input}: a few contacts, the
 *       three fingers' frames, the clutch states) and a comparison with the last one handed on;
 *       only when the grasp changed — another model or reset, other contacts (finger, link,
 *       point, normal, bit for bit), a clutch engaging or letting go, another μ or m — is the
 *       copy put in a one-place mailbox, replacing any copy not yet taken. The simulation thread
 *       never blocks here.</li>
 *   <li>The evaluation thread takes the newest copy at most {@link #MIN_INTERVAL_NS} after the
 *       start of its previous evaluation (at most 10 evaluations per second of wall time,
 *       each about 1–15 ms), evaluates it, and publishes the result, an immutable
 *       {@link Result}, with a volatile write. The last copy offered is always evaluated (a
 *       trailing-edge throttle): when the run ends or pauses, what the panel shows is the grasp
 *       of the state shown, within ~0.1 s, evaluated at its time (a model at rest is always
 *       handed on, see {@link #offer(long, HandModel, double, int, boolean)}).</li>
 *   <li>The window reads {@link #latest()} on its timer and shows it when it is of the model
 *       generation on screen.</li>
 * </ol>
 * A failed evaluation is a result with its message ({@link Result#error()}), never an exception
 * on either thread. {@link #awaitIdle()} (scripts, tests) waits until every copy offered has
 * been evaluated.
 */
public final class LiveGrasp implements AutoCloseable {
    /** Least wall time between the starts of two evaluations, ns (at most 10 per second). */
    public static final long MIN_INTERVAL_NS = 100_000_000L;

    /**
     * One evaluation, immutable.
     *
     * @param generation the model generation it belongs to ({@link SimulationRunner.State#generation()})
     * @param assessment the grasp (null if the evaluation failed)
     * @param mu         Coulomb μ it was evaluated with
     * @param edges      friction-cone edges m
     * @param error      why the evaluation failed, or null
     * @param serial     counts results (the view knows a new one)
     */
    public record Result(long generation, GraspAssessment assessment, double mu, int edges, String error, long serial) {}

    /** A copy waiting to be evaluated. */
    private record Job(long generation, GraspAssessment.Input input, double mu, int edges) {}

    private final AtomicReference<Job> mailbox = new AtomicReference<>();
    private final Thread thread;
    private volatile Result latest;
    private volatile boolean busy, closed;
    private long serial;

    // simulation thread
    private Job lastOffered;

    LiveGrasp() {
        thread = new Thread(this::loop, "handsim-grasp");
        thread.setDaemon(true);
        thread.setPriority(Thread.NORM_PRIORITY - 1);
        thread.start();
    }

    /**
     * Offers the model's grasp as it is now (the simulation thread, which owns the model): copied
     * and handed on only if it differs from the last offer (see the class comment).
     *
     * @param generation the model's generation
     * @param mu         the scenario's friction coefficient μ
     * @param edges      the scenario's friction-cone edges m
     */
    void offer(long generation, HandModel model, double mu, int edges) {
        offer(generation, model, mu, edges, false);
    }

    /**
     * Offers the model's grasp; {@code resting} says the model stopped here (paused, finished,
     * stepped, reset, loaded): then the copy is handed on unless the last one was of this very
     * state, so that what the panel shows is evaluated at the time shown — not at whichever
     * publication first saw these contacts, which depends on how the run's steps were batched
     * (scripted runs of one script then show one readout).
     */
    void offer(long generation, HandModel model, double mu, int edges, boolean resting) {
        Job j = new Job(generation, model.graspInput(), mu, edges);
        if (lastOffered != null && sameGrasp(lastOffered, j)
            && (!resting || Double.compare(lastOffered.input().timeS(), j.input().timeS()) == 0)) {
            return;
        }
        lastOffered = j;
        mailbox.set(j);
        LockSupport.unpark(thread);
    }

    /** The newest evaluation, or null before the first. Any thread. */
    public Result latest() { return latest; }

    /**
     * Blocks until every copy offered so far has been evaluated (any thread but the simulation
     * thread; call {@link SimulationRunner#sync()} first so that the offers are made).
     */
    public void awaitIdle() throws InterruptedException {
        while (mailbox.get() != null || busy) Thread.sleep(5);
    }

    @Override
    public void close() {
        closed = true;
        thread.interrupt();
    }

    private void loop() {
        long lastStart = System.nanoTime() - MIN_INTERVAL_NS;
        while (!closed) {
            if (mailbox.get() == null) {
                LockSupport.park(this);
                if (Thread.interrupted() && closed) return;
                continue;
            }
            long wait = lastStart + MIN_INTERVAL_NS - System.nanoTime();
            if (wait > 0) {
                try {
                    Thread.sleep(wait / 1_000_000L, (int) (wait % 1_000_000L));
                } catch (InterruptedException e) {
                    if (closed) return;
                }
            }
            busy = true;   // before taking the job: awaitIdle never sees neither
            Job j = mailbox.getAndSet(null);
            try {
                if (j == null) continue;
                lastStart = System.nanoTime();
                latest = evaluate(j, ++serial);
            } finally {
                busy = false;
            }
        }
    }

    private static Result evaluate(Job j, long serial) {
        try {
            return new Result(j.generation(), GraspAssessment.of(j.input(), j.mu(), j.edges()), j.mu(), j.edges(), null, serial);
        } catch (RuntimeException e) {
            return new Result(j.generation(), null, j.mu(), j.edges(), e.getMessage() != null ? e.getMessage() : e.toString(), serial);
        }
    }

    /**
     * Whether two copies give the same evaluation: the same generation, μ, m and clutch states
     * and the same contacts (finger, link, point and normal bit for bit). The frames are not
     * compared: a link whose contacts did not move did not move (its contacts would), and a
     * contact loads only the joints of its own link's chain.
     */
    static boolean sameGrasp(Job a, Job b) {
        if (a.generation() != b.generation() || Double.compare(a.mu(), b.mu()) != 0 || a.edges() != b.edges()) return false;
        if (!Arrays.equals(a.input().clutchEngaged(), b.input().clutchEngaged())) return false;
        List<GraspAssessment.Contact> x = a.input().contacts(), y = b.input().contacts();
        if (x.size() != y.size()) return false;
        for (int i = 0; i < x.size(); i++) {
            GraspAssessment.Contact p = x.get(i), q = y.get(i);
            if (p.finger() != q.finger() || p.link() != q.link() || !Arrays.equals(p.point(), q.point()) || !Arrays.equals(p.normal(), q.normal())) {
                return false;
            }
        }
        return true;
    }
}
