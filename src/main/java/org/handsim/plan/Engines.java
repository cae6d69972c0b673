package org.handsim.plan;

import java.util.ServiceLoader;

/** Finds an engine by its {@code --engine} name: {@code local} built in, others through {@link ServiceLoader}. */
public final class Engines {
    private Engines() {}

    /**
     * @throws IllegalArgumentException naming the engine if it is unknown or not on the class
     *                                  path (the Spark engine is only there when HandSim runs
     *                                  from the {@code spark/} build, as {@code ./handsim ... --engine spark} does)
     */
    public static TrialEngine find(String name) {
        if (name.equals("local")) return new LocalEngine();
        for (TrialEngine e : ServiceLoader.load(TrialEngine.class)) {
            if (e.name().equals(name)) return e;
        }
        if (name.equals("spark")) {
            throw new IllegalArgumentException("--engine spark: the Spark engine is not on the class path; run through ./handsim,"
                + " which builds spark/ on first use (or use build of 'gradle :spark:installDist')");
        }
        throw new IllegalArgumentException("--engine must be local or spark, got '" + name + "'");
    }
}
