package org.handsim.bench;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * {@code gradle bench [-Ponly=suite1,suite2]}: runs the benchmark suites in one JVM and prints
 * medians. Suites register in {@link #SUITES}, one line each.
 */
public final class BenchMain {
    /** A named group of measurements. */
    public interface Suite {
        void run() throws Exception;
    }

    static final Map<String, Suite> SUITES = new LinkedHashMap<>();
    static {
        SUITES.put("kinematics", new KinematicsBench());
        SUITES.put("dynamics", new DynamicsBench());
        SUITES.put("sim", new SimBench());
        SUITES.put("sim-profile", new SimProfileBench());
        // suites register here, one line each: SUITES.put("name", new SomeBench());
        SUITES.put("hold", new HoldBench());
        SUITES.put("collision", new CollisionBench(false));
        SUITES.put("collision-fcl", new CollisionBench(true));
        SUITES.put("vrml", new VrmlBench());
        SUITES.put("grasp", new GraspBench());
        SUITES.put("plan", new PlanBench());
        SUITES.put("live-grasp", new LiveGraspBench());
        SUITES.put("body-solver", new BodyBench(false));
        SUITES.put("body-proximity", new BodyBench(true));
        SUITES.put("body-step", new BodyStepBench());
        SUITES.put("mug-lift-step", BodyStepBench::mugLift);
    }

    public static void main(String[] args) throws Exception {
        System.out.println("# HandSim benchmarks  java " + System.getProperty("java.version") + ", "
            + Runtime.getRuntime().availableProcessors() + " cores, " + java.time.LocalDate.now());
        java.util.Set<String> only = new java.util.HashSet<>(java.util.Arrays.asList(args));
        for (Map.Entry<String, Suite> e : SUITES.entrySet()) {
            if (!only.isEmpty() && !only.contains(e.getKey())) continue;
            System.out.println("\n## " + e.getKey());
            e.getValue().run();
        }
    }
}
