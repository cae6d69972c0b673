package org.handsim.grasp;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.handsim.hand.HandDescription;
import org.handsim.text.Decimal;

/**
 * An evaluation of a grasp as the simulation left it: the contacts with their forces, the
 * quality of the grasp wrench space (force closure, ε, volume) and how much load the grasp
 * holds in each of the six world directions.
 *
 * @param timeS    simulated time of the evaluation, s
 * @param quality  force closure, ε and volume of the L1 grasp wrench space ({@link WrenchSpace#qualityWithoutFacets}:
 *                 its facet count is −1, not computed)
 * @param holdN    the largest disturbance force through the object's centroid the grasp holds,
 *                 newtons, in the order of {@link #DIRECTIONS}: +x, −x, +y, −y, +z, −z (world);
 *                 at most the hand's rated load ({@link HandDescription#handRatingN()}, 58.84 N),
 *                 which it equals when the joints' limits allow that much or more
 * @param holdMinN the smallest of {@code holdN}
 * @param jointLimitsNm the limits the hold used, per finger (index 0..2) and joint (k1, k2, k3),
 *                 N·m ({@link #jointLimit}); NaN where none is known (and for finger 3's k1,
 *                 which does not exist)
 * @param holdCapN the largest hold reported, N: the hand's rated load, 58.84 N (a ceiling of the
 *                 report, not a limit of a joint)
 * @param contacts every contact of the three fingers, finger by finger
 * @param torqueResidualNm per finger (index 0..2) how far its contact forces are from carrying
 *                 its joint torques, N·m (the model's torque residual): 0 up to rounding
 *                 when the forces are a static equilibrium of the finger's state
 * @param centerM  the wrenches' torque origin c, world frame, m (the object's centroid)
 * @param radiusM  the length R the torques are divided by, m (the object's largest centroid-to-vertex distance)
 * @param friction the Coulomb μ of the cones
 * @param coneEdges the cones' edges m
 * @param jointTorquesNm per finger (index 0..2) and joint (k1, k2, k3) the torque the joint carries,
 *                 N·m (the model's carried torque: the drive's, or the reaction of the worm or
 *                 motor that holds it; 0 for finger 3's missing k1)
 */
public record GraspAssessment(double timeS, GraspQuality quality, double[] holdN, double holdMinN, double[][] jointLimitsNm,
                              double holdCapN, List<Contact> contacts, double[] torqueResidualNm, double[] centerM, double radiusM,
                              double friction, int coneEdges, double[][] jointTorquesNm) {
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
     * What an evaluation reads of a model, copied by the model ({@code HandModel.graspInput()}):
     * an immutable value that another thread may evaluate while the model steps on (the window's
     * live grasp: the simulation thread copies, a worker evaluates). Arrays are fresh copies; treat them as read-only.
     *
     * @param timeS             simulated time, s
     * @param contacts          every contact of the three fingers, finger by finger (world frame)
     * @param framesWorld       per finger (index 0..2) the frames {k0}..{k3} in the world, 4 × 12 row-major
     * @param clutchEngaged     per finger whether its clutch couples the inner link to the motor
     *                          (its clutch state: FREE or BLOCKED)
     * @param hand              the hand's description (joint limits)
     * @param centroidAndRadius the object's centroid and R {cx, cy, cz, R}, m, or null when the
     *                          scene has no object geometry
     * @param torqueResidualNm  per finger the contact forces' torque residual, N·m
     * @param jointTorquesNm    per finger and joint (k1, k2, k3) the torque the joint carries, N·m
     */
    public record Input(double timeS, List<Contact> contacts, double[][] framesWorld, boolean[] clutchEngaged,
                        HandDescription hand, double[] centroidAndRadius, double[] torqueResidualNm, double[][] jointTorquesNm) {}

    /**
     * Evaluates a grasp copied from a model, on any thread: its contacts (world frame) with the
     * forces the simulation gave them; the quality of the grasp wrench space with the torque
     * origin c = the object's centroid and R = its largest centroid-to-vertex distance
     * ({@link Input#centroidAndRadius}; for a back end without object geometry, the mean of the
     * contact points and their largest distance from it); and the hold in the six world
     * directions ({@link HoldCapacity}, DESIGN.md decision 6) with each joint's limit in its
     * clutch state ({@link #jointLimit}), capped at the hand's rating.
     *
     * @param mu    Coulomb friction coefficient of the contacts (≥ 0)
     * @param edges edges of the linearised friction cones (≥ 1)
     */
    public static GraspAssessment of(Input in, double mu, int edges) {
        FrictionCone.checkMu(mu);
        FrictionCone.checkEdges(edges);
        List<Contact> contacts = in.contacts();
        int n = contacts.size();
        double[] cr0 = in.centroidAndRadius();
        if (n == 0) {
            double[] c0 = cr0 == null ? new double[3] : new double[] {cr0[0], cr0[1], cr0[2]};
            return new GraspAssessment(in.timeS(), GraspQuality.none(0, 0), new double[6], 0, jointLimits(in), in.hand().handRatingN(),
                List.of(), in.torqueResidualNm().clone(), c0, cr0 == null ? 0 : cr0[3], mu, edges, copy(in.jointTorquesNm()));
        }
        double[] points = new double[3 * n], normals = new double[3 * n];
        for (int i = 0; i < n; i++) {
            System.arraycopy(contacts.get(i).point(), 0, points, 3 * i, 3);
            System.arraycopy(contacts.get(i).normal(), 0, normals, 3 * i, 3);
        }
        double[] cr = in.centroidAndRadius();
        if (cr == null) cr = fromContacts(points, n);
        double[] c = {cr[0], cr[1], cr[2]};
        GraspQuality q = WrenchSpace.qualityWithoutFacets(GraspWrenches.of(n, points, normals, mu, edges, c, cr[3]), n * edges, n);
        double[] hold = hold(in, contacts, mu, edges, c, cr[3]).holdSix();
        double min = hold[0];
        for (double h : hold) min = Math.min(min, h);
        return new GraspAssessment(in.timeS(), q, hold, min, jointLimits(in), in.hand().handRatingN(), contacts,
            in.torqueResidualNm().clone(), c, cr[3], mu, edges, copy(in.jointTorquesNm()));
    }

    private static double[][] copy(double[][] a) {
        double[][] c = new double[a.length][];
        for (int i = 0; i < a.length; i++) c[i] = a[i].clone();
        return c;
    }

    /** The limit of every joint in its state ({@link #jointLimit}), per finger and joint. */
    private static double[][] jointLimits(Input in) {
        double[][] l = new double[3][3];
        for (int k = 1; k <= 3; k++) {
            for (int j = 1; j <= 3; j++) l[k - 1][j - 1] = jointLimit(in.hand(), k, j, in.clutchEngaged()[k - 1]);
        }
        return l;
    }

    /**
     * The hold LP of a grasp: per finger its joints — the spread k1 (fingers 1 and 2;
     * finger 3's first link is fixed to the palm), the inner k2, the outer k3 — each turning about
     * the z axis of the DH frame before it (world frame, {@link Input#framesWorld}), and each
     * contact loading the joints of its link's chain.
     */
    public static HoldCapacity hold(Input in, List<Contact> contacts, double mu, int edges, double[] c, double r) {
        HandDescription hand = in.hand();
        HoldCapacity hc = new HoldCapacity(mu, edges, c, r, hand.handRatingN());
        int[][] joint = new int[3][3];
        for (int k = 1; k <= 3; k++) {
            double[] f = in.framesWorld()[k - 1];
            for (int j = 1; j <= 3; j++) {
                double limit = jointLimit(hand, k, j, in.clutchEngaged()[k - 1]);
                int o = 12 * (j - 1);
                joint[k - 1][j - 1] = Double.isNaN(limit) ? -1
                    : hc.addJoint(new double[] {f[o + 2], f[o + 6], f[o + 10]}, new double[] {f[o + 3], f[o + 7], f[o + 11]}, limit);
            }
        }
        for (Contact ct : contacts) {
            int[] chain = new int[3];
            int used = 0;
            for (int j = 1; j <= ct.link(); j++) {
                int idx = joint[ct.finger() - 1][j - 1];
                if (idx >= 0) chain[used++] = idx;
            }
            hc.addContact(ct.point(), ct.normal(), java.util.Arrays.copyOf(chain, used));
        }
        return hc;
    }

    /**
     * What joint j (1 spread, 2 inner, 3 outer) of finger k resists in the hold LP, N·m — the
     * limits the simulation uses (DESIGN.md decision 6; sources in the hand file's {@code hold}):
     * the inner joint with its clutch engaged, τ_break (beyond it the clutch slips); NaN — no limit
     * known — for a joint its worm holds (the inner joint after a breakaway, the outer joint:
     * Barrett documents no strength of the worm drives, only the 2 kg finger rating, which is a
     * rating and gives warnings, not a limit), for the spread (back-drivable, held by its motor at
     * a torque setting of the controller, BH8 manual §9.3.2) and for finger 3's spread, which does
     * not exist (its first link is fixed to the palm).
     */
    public static double jointLimit(HandDescription hand, int finger, int joint, boolean clutchEngaged) {
        return joint == 2 && clutchEngaged ? hand.tauBreak() : Double.NaN;
    }

    /** {cx, cy, cz, R} from the contact points alone: their mean and largest distance from it (at least 1 mm). */
    private static double[] fromContacts(double[] points, int n) {
        double[] c = new double[3];
        for (int i = 0; i < n; i++) for (int a = 0; a < 3; a++) c[a] += points[3 * i + a] / n;
        double r = 1e-3;
        for (int i = 0; i < n; i++) {
            double dx = points[3 * i] - c[0], dy = points[3 * i + 1] - c[1], dz = points[3 * i + 2] - c[2];
            r = Math.max(r, Math.sqrt(dx * dx + dy * dy + dz * dz));
        }
        return new double[] {c[0], c[1], c[2], r};
    }

    /**
     * The JSON object of {@code handsim grasp} (and {@code "grasp"} in summary.json): keys
     * {@code time_s, contacts[{finger, link, point, normal, force_N}], force_closure, epsilon,
     * volume, hold_N{+x, −x, +y, −y, +z, −z}, hold_min_N, hold_joint_limits_Nm[[k11, k12, k13],
     * [k21, k22, k23], [k32, k33]] (null: no limit), hold_cap_N, torque_residual_Nm[finger 1, 2, 3],
     * joint_torques_Nm[[k11, k12, k13], [k21, k22, k23], [k32, k33]], center_m, radius_m, friction,
     * cone_edges} — the last four the wrench scaling and cones of ε and volume, so that
     * {@code handsim quality} given this object computes the same.
     * Contact points and normals are written whole (not rounded), so they read back bit for bit.
     */
    public Map<String, Object> toJson() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("time_s", timeS);
        List<Object> cs = new ArrayList<>();
        for (Contact c : contacts) {
            Map<String, Object> o = new LinkedHashMap<>();
            o.put("finger", c.finger());
            o.put("link", c.link());
            // the contact unrounded (it reads back bit for bit: quality's ε of this output is
            // grasp's); the force, a physical value, with noise below 1e-12 written as 0 (text.Decimal)
            o.put("point", c.point());
            o.put("normal", c.normal());
            o.put("force_N", Decimal.clean(c.forceN()));
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
        List<Object> limits = new ArrayList<>();
        for (int k = 0; k < 3; k++) {
            List<Object> l = new ArrayList<>();
            for (int j = k == 2 ? 1 : 0; j < 3; j++) l.add(Double.isNaN(jointLimitsNm[k][j]) ? null : jointLimitsNm[k][j]);
            limits.add(l);
        }
        m.put("hold_joint_limits_Nm", limits);
        m.put("hold_cap_N", holdCapN);
        // a torque error: rounding noise below 1e-12 N·m written as 0, like the trace's residual columns
        m.put("torque_residual_Nm", Decimal.clean(torqueResidualNm));
        List<Object> carried = new ArrayList<>();
        for (int k = 0; k < 3; k++) carried.add(Decimal.clean(java.util.Arrays.copyOfRange(jointTorquesNm[k], k == 2 ? 1 : 0, 3)));
        m.put("joint_torques_Nm", carried);
        m.put("center_m", centerM);
        m.put("radius_m", radiusM);
        m.put("friction", friction);
        m.put("cone_edges", coneEdges);
        return m;
    }
}
