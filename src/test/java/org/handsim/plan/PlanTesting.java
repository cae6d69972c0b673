package org.handsim.plan;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;
import org.handsim.TestPaths;

/** Shared by the planner's tests: the mug, a small plan, plan.csv rows without their timing column. */
public final class PlanTesting {
    private PlanTesting() {}

    public static final Path MUG = TestPaths.root().resolve("vrml/objects/mug.wrl");

    /** The column of plan.csv that is a wall time (compared nowhere). */
    public static final int WALL_COLUMN = 17;

    public static PlanSpec mugPlan(int trials, long seed) {
        return PlanSpec.forTarget(MUG, trials, seed, 0.5, 8);
    }

    /** plan.csv lines with the wall_s column blanked (it is the only field that depends on timing). */
    public static List<String> withoutTiming(List<String> lines) {
        List<String> out = new ArrayList<>();
        for (String l : lines) {
            String[] f = l.split(",", -1);
            if (f.length > WALL_COLUMN && !l.startsWith("trial,")) f[WALL_COLUMN] = "";
            out.add(String.join(",", f));
        }
        return out;
    }

    public static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir)) return;
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) s.sorted(Comparator.reverseOrder())::iterator) Files.delete(p);
        }
    }
}
