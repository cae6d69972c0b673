package org.handsim.plan;

/**
 * The trials of a plan as an {@link IndexedJob}: a {@link TrialRunner} per thread, rebuilt
 * from the {@link PlanSpec} wherever the job is deserialised (the meshes and trees are cached
 * per JVM, so that costs one load per executor).
 */
public final class PlanJob implements IndexedJob<TrialResult> {
    private static final long serialVersionUID = 1L;
    private final PlanSpec spec;
    private transient ThreadLocal<TrialRunner> runners;

    public PlanJob(PlanSpec spec) {
        this.spec = spec;
    }

    public PlanSpec spec() { return spec; }

    @Override
    public TrialResult run(int index) {
        ThreadLocal<TrialRunner> r;
        synchronized (this) {
            if (runners == null) runners = ThreadLocal.withInitial(() -> new TrialRunner(spec));
            r = runners;
        }
        return r.get().run(index);
    }
}
