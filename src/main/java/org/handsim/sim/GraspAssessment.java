package org.handsim.sim;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.handsim.grasp.FrictionCone;
import org.handsim.grasp.GraspQuality;
import org.handsim.grasp.GraspWrenches;
import org.handsim.grasp.WrenchSpace;

/**
 * An evaluation of the model's current grasp (issue 12): the contacts with their forces, the
 * quality of the grasp wrench space (force closure, ε, volume) and how much load the grasp
 * holds in each of the six world directions.
 *
 * @param timeS    simulated time of the evaluation, s
 * @param quality  force closure, ε and volume of the L1 grasp wrench space ({@link WrenchSpace#quality})
 * @param holdN    the largest disturbance force through the object's centroid the grasp holds,
 *                 newtons, in the order of {@link #DIRECTIONS}: +x, −x, +y, −y, +z, −z (world)
 * @param holdMinN the smallest of {@code holdN}
 * @param contacts every contact of the three fingers, finger by finger
 */
public record GraspAssessment(double timeS, GraspQuality quality, double[] holdN, double holdMinN, List<Contact> contacts) {
    /** The disturbance directions of {@link #holdN()}, as the JSON keys of {@code hold_N}. */
    public static final List<String> DIRECTIONS = List.of("+x", "-x", "+y", "-y", "+z", "-z");

    /**
     * One contact of the grasp, world frame.
     *
     * @param finger 1..3
     * @param link   1..3
     * @param point  contact point, m
     * @param normal unit normal pointing into the object (the direction the finger pushes;
     *               the friction cone's axis, {@link FrictionCone})
     * @param forceN the contact force the finger applies to the object, N (the simulator's
     *               choice among those that carry the joint torques, DESIGN.md)
     */
    public record Contact(int finger, int link, double[] point, double[] normal, double[] forceN) {}

    /**
     * Evaluates the grasp of {@code model} as it is now.
     *
     * @param mu    Coulomb friction coefficient of the contacts (≥ 0)
     * @param edges edges of the linearised friction cones (≥ 1)
     */
    public static GraspAssessment of(HandModel model, double mu, int edges) {
        FrictionCone.checkMu(mu);
        FrictionCone.checkEdges(edges);
        List<Contact> contacts = new ArrayList<>();
        for (int k = 1; k <= 3; k++) {
            ContactSet cs = model.contacts(k);
            for (int i = 0; i < cs.size(); i++) {
                double[] n = cs.normal(i);
                contacts.add(new Contact(k, cs.link(i), cs.point(i), new double[] {-n[0], -n[1], -n[2]}, new double[3]));
            }
        }
        int n = contacts.size();
        double[] points = new double[3 * n], normals = new double[3 * n];
        for (int i = 0; i < n; i++) {
            System.arraycopy(contacts.get(i).point(), 0, points, 3 * i, 3);
            System.arraycopy(contacts.get(i).normal(), 0, normals, 3 * i, 3);
        }
        double[] cr = model.objectCentroidAndRadius();
        GraspQuality q = n == 0 || cr == null ? GraspQuality.none(n, n * edges)
            : WrenchSpace.quality(GraspWrenches.of(n, points, normals, mu, edges, new double[] {cr[0], cr[1], cr[2]}, cr[3]), n * edges, n);
        return new GraspAssessment(model.time(), q, new double[6], 0, List.copyOf(contacts));
    }

    /**
     * The JSON object of {@code handsim grasp} (and {@code "grasp"} in summary.json): keys
     * {@code time_s, contacts[{finger, link, point, normal, force_N}], force_closure, epsilon,
     * volume, hold_N{+x, −x, +y, −y, +z, −z}, hold_min_N}.
     */
    public Map<String, Object> toJson() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("time_s", timeS);
        List<Object> cs = new ArrayList<>();
        for (Contact c : contacts) {
            Map<String, Object> o = new LinkedHashMap<>();
            o.put("finger", c.finger());
            o.put("link", c.link());
            o.put("point", c.point());
            o.put("normal", c.normal());
            o.put("force_N", c.forceN());
            cs.add(o);
        }
        m.put("contacts", cs);
        m.put("force_closure", quality.forceClosure());
        m.put("epsilon", quality.epsilon());
        m.put("volume", quality.volume());
        Map<String, Object> h = new LinkedHashMap<>();
        for (int d = 0; d < 6; d++) h.put(DIRECTIONS.get(d), holdN[d]);
        m.put("hold_N", h);
        m.put("hold_min_N", holdMinN);
        return m;
    }
}
