package org.handsim.sim;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.handsim.grasp.GraspQuality;

/**
 * STUB (branch plan): the API of the grasp evaluation being built on branch grasp-use, so the
 * planner compiles until that branch is merged. Always "no force closure". Replaced by the merge.
 */
public record GraspAssessment(double timeS, GraspQuality quality, double[] holdN, double holdMinN, List<Map<String, Object>> contacts) {
    public static GraspAssessment of(HandModel model, double mu, int edges) {
        int n = 0;
        for (int k = 1; k <= 3; k++) n += model.contacts(k).size();
        return new GraspAssessment(model.time(), GraspQuality.none(n, n * edges), new double[6], 0, List.of());
    }

    public Map<String, Object> toJson() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("time_s", timeS);
        m.put("force_closure", quality.forceClosure());
        m.put("epsilon", quality.epsilon());
        m.put("volume", quality.volume());
        m.put("hold_min_N", holdMinN);
        return m;
    }
}
