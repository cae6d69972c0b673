package org.handsim.plan;

import java.io.IOException;
import java.io.ObjectInputStream;

/**
 * The trials of a plan as an {@link IndexedJob}: a {@link TrialRunner} per thread, rebuilt
 * from the {@link PlanSpec} wherever the job is deserialised (the meshes and trees are cached
 * per JVM, so that costs one load per executor). A trial takes no lock here: the runners'
 * {@link ThreadLocal} is made with the job (and again when it is deserialised).
 */
public final class PlanJob implements IndexedJob<TrialResult> {
    private static final long serialVersionUID = 1L;
    private final PlanSpec spec;
    private transient ThreadLocal<TrialRunner> runners;

    public PlanJob(PlanSpec spec) {
        this.spec = spec;
        this.runners = runners(spec);
    }

    private static ThreadLocal<TrialRunner> runners(PlanSpec spec) {
        return ThreadLocal.withInitial(() -> new TrialRunner(spec));
    }

    private void readObject(ObjectInputStream in) throws IOException, ClassNotFoundException {
        in.defaultReadObject();
        runners = runners(spec);
    }

    public PlanSpec spec() { return spec; }

    @Override
    public TrialResult run(int index) {
        return runners.get().run(index);
    }
}
