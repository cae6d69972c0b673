package org.handsim.contact;

import static org.handsim.contact.ContactForcesTest.problem;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.handsim.grasp.FrictionCone;
import org.handsim.kinematics.FingerKinematics;
import org.handsim.testing.TestEffort;
import org.junit.jupiter.api.Test;
import org.ojalgo.optimisation.Expression;
import org.ojalgo.optimisation.ExpressionsBasedModel;
import org.ojalgo.optimisation.Optimisation;
import org.ojalgo.optimisation.Variable;

/**
 * Contact forces with Coulomb friction (least-norm forces in the linearised cones that carry
 * the joint torques): cases by hand, and the least-norm property against an independent
 * quadratic program (ojAlgo's convex solver on the edge weights).
 *
 * <p>The hand cases use finger 3 upright (ContactForcesTest): joint 2's axis z1 = (0, −1, 0)
 * through o1 = (0.05, 0, 0); a contact on the inner link at p − o1 = (0, 0, 0.05) moves, when
 * the joint closes, along t = z1 × (p − o1) = (−0.05, 0, 0), |t| = 0.05 m. The push direction
 * n = (−cos φ, 0, −sin φ) leans φ off t in the x–z plane; its cone (FrictionCone: |n_x| ≥ 0.9
 * gives a = e_y, t1 = (sin φ, 0, −cos φ)) has edges 0 and 4, n ± μ t1, in the same plane, and t
 * lies on edge 4's side.
 */
class ContactForcesFrictionTest {
    /** Seeded trials of the quadratic-program comparisons: 300 in ./test --all, a quarter in ./test. */
    private static final int TRIALS = TestEffort.cases(300);

    static final int M = 8;
    static final double MU = 0.5, TAU = 1.26;

    private static double[] upright() {
        double[] f = new double[48];
        FingerKinematics.of(3).frames(new double[] {0, Math.toRadians(90 - 2.46), 0}, f);
        return f;
    }

    private static double[] cones(double[] dirs, int n, double mu) {
        double[] c = new double[3 * M * n];
        for (int i = 0; i < n; i++) FrictionCone.edges(dirs[3 * i], dirs[3 * i + 1], dirs[3 * i + 2], mu, M, c, 3 * M * i);
        return c;
    }

    private static ContactForces solveOne(double phiDeg, double tau) {
        double phi = Math.toRadians(phiDeg);
        double[] d = {-Math.cos(phi), 0, -Math.sin(phi)};
        ContactForces cf = new ContactForces();
        cf.solve(problem(upright(), new double[] {0, tau, 0}, 1, new double[] {0.05, 0, 0.05}, d, new int[] {2}).friction(cones(d, 1, MU), M));
        return cf;
    }

    /**
     * φ = 20°: t is inside the cone (tan 20° = 0.36 < μ; in the plane of edges 0 and 4 the
     * pyramid's section is the full ±26.6° wedge), so the least-norm force is along t:
     * f = τ t/|t|² = 1.26 · (−0.05, 0, 0)/0.0025 = (−25.2, 0, 0) — less than the frictionless
     * τ/(0.05 cos 20°) = 26.82 N, and the torque is carried exactly.
     */
    @Test
    void insideTheConeTheForceFollowsTheLinksMotion() {
        ContactForces cf = solveOne(20, TAU);
        double[] f = new double[3];
        cf.forceVector(0, f, 0);
        assertEquals(-25.2, f[0], 1e-9);
        assertEquals(0, f[1], 1e-9);
        assertEquals(0, f[2], 1e-9);
        assertEquals(25.2, cf.force(0), 1e-9);
        assertEquals(TAU, cf.jointTorque(0, 1), 1e-12);
        assertEquals(0, cf.residual(), 1e-12);
        assertFalse(cf.undetermined(0));
    }

    /**
     * φ = 40°: t is outside (tan 40° = 0.84 > μ): the force slides on edge 4, f = λ (n − μ t1),
     * with t·(n − μ t1) = 0.05 (cos φ + μ sin φ), so λ = τ / (0.05 (cos 40° + 0.5 sin 40°))
     * = 1.26 / 0.054372 = 23.174 N of normal force and |f| = λ √(1 + μ²) = 25.909 N.
     */
    @Test
    void outsideTheConeTheForceSlidesOnTheNearestEdge() {
        double phi = Math.toRadians(40);
        double lambda = TAU / (0.05 * (Math.cos(phi) + MU * Math.sin(phi)));
        ContactForces cf = solveOne(40, TAU);
        double[] f = new double[3];
        cf.forceVector(0, f, 0);
        double[] n = {-Math.cos(phi), 0, -Math.sin(phi)}, t1 = {Math.sin(phi), 0, -Math.cos(phi)};
        for (int c = 0; c < 3; c++) assertEquals(lambda * (n[c] - MU * t1[c]), f[c], 1e-9, "component " + c);
        assertEquals(lambda * Math.sqrt(1 + MU * MU), cf.force(0), 1e-9);
        assertEquals(TAU, cf.jointTorque(0, 1), 1e-12);
        assertEquals(0, cf.residual(), 1e-12);
    }

    /**
     * φ = 90°: the push passes through the joint axis (no frictionless moment arm: undetermined
     * without friction), but friction carries the torque: on edge 4, t·(n − μ t1) = 0.05 μ, so
     * λ = 1.26/0.025 = 50.4 N of normal force.
     */
    @Test
    void aPushThroughTheJointAxisIsCarriedByFrictionAlone() {
        ContactForces cf = solveOne(90, TAU);
        assertFalse(cf.undetermined(0));
        assertEquals(0, cf.arm(0, 1), 1e-15);
        assertEquals(TAU / (0.05 * MU) * Math.sqrt(1 + MU * MU), cf.force(0), 1e-9);
        assertEquals(TAU, cf.jointTorque(0, 1), 1e-12);
    }

    /** A torque that would need the contact to pull: no force, the whole torque is the residual. */
    @Test
    void contactsCannotPull() {
        ContactForces cf = solveOne(20, -0.5);
        assertEquals(0, cf.force(0));
        assertEquals(0.5, cf.residual(), 1e-12);
    }

    /**
     * A torque on joint 3 with contacts only on the inner link cannot be carried: joint 2's is,
     * exactly, and the residual is joint 3's torque.
     */
    @Test
    void aJointNoContactLoadsIsTheResidual() {
        double[] d = {-1, 0, 0};
        ContactForces cf = new ContactForces();
        cf.solve(problem(upright(), new double[] {0, TAU, 0.3}, 1, new double[] {0.05, 0, 0.05}, d, new int[] {2}).friction(cones(d, 1, MU), M));
        assertEquals(TAU, cf.jointTorque(0, 1), 1e-12);
        assertEquals(0.3, cf.residual(), 1e-12);
    }

    /** Near the joint axis (every edge's arm below 0.5 mm) the contact is undetermined, f = 0. */
    @Test
    void aContactOnTheJointAxisIsUndetermined() {
        double[] d = {-1, 0, 0};
        ContactForces cf = new ContactForces();
        cf.solve(problem(upright(), new double[] {0, TAU, 0}, 1, new double[] {0.05, 0, 0.0003}, d, new int[] {2}).friction(cones(d, 1, MU), M));
        assertTrue(cf.undetermined(0));
        assertEquals(0, cf.force(0));
        assertTrue(Double.isFinite(cf.residual()));
    }

    /**
     * The least-norm property on 300 seeded finger poses with 1–5 contacts on links 2 and 3:
     * torques made by random forces in the cones (so they can be carried), solved, and compared
     * with an independent quadratic program — minimise Σ|f_i|² over edge weights λ ≥ 0 with
     * f_i = Σ λ_ie e_ie and the two torque equations — solved by ojAlgo. The least-norm forces
     * are unique, so they must agree; every force must lie in its cone and carry the torques.
     */
    @Test
    void leastNormForcesAgreeWithAQuadraticProgram() {
        Random rnd = new Random(20260412);
        ContactForces cf = new ContactForces();
        int compared = 0;
        for (int trial = 0; trial < TRIALS; trial++) {
            Pose pose = Pose.draw(rnd, 5);
            double[] frames = pose.frames, p = pose.p, d = pose.d, cones = pose.cones;
            int n = pose.n;
            int[] links = pose.links;
            double[] tau = new double[3];
            // torques from random forces in the cones: carriable by construction
            for (int i = 0; i < n; i++) {
                for (int e = 0; e < M; e++) {
                    double w = rnd.nextDouble() < 0.5 ? 0 : 10 * rnd.nextDouble();
                    for (int jm = 1; jm < links[i]; jm++) {
                        tau[jm] += w * torqueDir(frames, jm, p, i, cones, 3 * M * i + 3 * e);
                    }
                }
            }
            cf.solve(problem(frames, tau, n, p, d, links).friction(cones, M));
            double[] ref = quadraticProgram(frames, tau, n, p, links, cones, cf);
            if (ref == null) continue;
            double scale = 1e-6 * (1 + norm(ref));
            double[] f = new double[3];
            double t2 = 0, t3 = 0;
            for (int i = 0; i < n; i++) {
                cf.forceVector(i, f, 0);
                for (int c = 0; c < 3; c++) assertEquals(ref[3 * i + c], f[c], scale, "trial " + trial + " contact " + i + " component " + c);
                if (!cf.undetermined(i)) {
                    double[] e = java.util.Arrays.copyOfRange(cones, 3 * M * i, 3 * M * (i + 1));
                    assertTrue(ConeProjectionTest.inCone(e, M, new double[] {d[3 * i], d[3 * i + 1], d[3 * i + 2]}, f, 1e-9 * (1 + cf.force(i))),
                        "trial " + trial + ": force in its cone");
                }
                t2 += cf.jointTorque(i, 1);
                t3 += cf.jointTorque(i, 2);
            }
            if (cf.residual() < 1e-9) {
                assertEquals(tau[1], t2, 1e-9 * (1 + Math.abs(tau[1])), "trial " + trial);
                assertEquals(tau[2], t3, 1e-9 * (1 + Math.abs(tau[2])), "trial " + trial);
            }
            compared++;
        }
        assertTrue(compared > TRIALS * 5 / 6, "compared " + compared);
    }

    /**
     * One contact on the outer link pushing along the link's closing side, asked for τk3 = 1.26
     * N·m with τk2 = 0: its force line would have to pass through joint k2's axis, which no
     * force in its cone does (k2's lever is about three times k3's), so the torques cannot be
     * carried. The answer must be the least-squares torque τ* = argmin |τ − Tᵀf| over forces in
     * the cone, checked here by its optimality conditions (Moreau: τ* is the projection of τ onto
     * the convex cone C of carriable torques iff τ* ∈ C, r = τ − τ* has r·c ≤ 0 for every
     * generator c of C — here the cone edges' torques — and r·τ* = 0): a nonzero force that
     * reduces the error below the frictionless one. Before the two-phase fix, Newton's method on
     * the regularised dual stalled at the cone's apex and reported f = 0 (residual 1.26 N·m).
     */
    @Test
    void torquesNoConeForceCarriesGetTheLeastSquaresTorque() {
        double[] frames = upright();
        int fr = 36;                                          // frame {k3}: x along link 3
        double[] p = new double[3], d = new double[3];
        for (int c = 0; c < 3; c++) {
            p[c] = frames[fr + 4 * c + 3] - 0.03 * frames[fr + 4 * c];
            d[c] = frames[fr + 4 * c + 1];
        }
        double[] tau = {0, 0, TAU};
        double[] cones = cones(d, 1, MU);
        ContactForces cf = new ContactForces();
        cf.solve(problem(frames, tau, 1, p, d, new int[] {3}).friction(cones, M));
        ContactForces frictionless = new ContactForces();
        frictionless.solve(problem(frames, tau, 1, p, d, new int[] {3}));
        assertTrue(frictionless.residual() > 0.1, "the case needs torques no force carries: " + frictionless.residual());
        assertTrue(cf.force(0) > 1, "a force: " + cf.force(0));
        double[] star = {0, cf.jointTorque(0, 1), cf.jointTorque(0, 2)};
        double[] r = {0, tau[1] - star[1], tau[2] - star[2]};
        assertTrue(cf.residual() < frictionless.residual() - 0.01, cf.residual() + " vs frictionless " + frictionless.residual());
        assertEquals(0, r[1] * star[1] + r[2] * star[2], 1e-12, "r · τ* = 0");
        for (int e = 0; e < M; e++) {
            double g = r[1] * torqueDir(frames, 1, p, 0, cones, 3 * e) + r[2] * torqueDir(frames, 2, p, 0, cones, 3 * e);
            assertTrue(g <= 1e-12, "edge " + e + ": r · Tᵀe = " + g + " > 0: a force along it would reduce the error");
        }
        double[] f = new double[3];
        cf.forceVector(0, f, 0);
        assertTrue(ConeProjectionTest.inCone(cones, M, d, f, 1e-9 * cf.force(0)), "in its cone");
    }

    /**
     * Torques on the boundary of what the cones carry, solved by hand: the inner contact A of
     * {@link #insideTheConeTheForceFollowsTheLinksMotion} (φ = 0, t = (−0.05, 0, 0)) with 10 N
     * locked along its axis, f⁰_A = (−10, 0, 0), and the outer contact B of
     * {@link #torquesNoConeForceCarriesGetTheLeastSquaresTorque}, every edge of whose cone presses
     * k3 closed, with 10 N locked along its normal; k2 driven at 1.26 N·m, k3 at 0. B can carry
     * no k3 torque but 0, so f_B = 0: its cone's apex, where the dual's multiplier of k3 runs off
     * to infinity and Newton's method carries the torques only to about 1e-8 of them. A alone
     * carries k2: f_A = f⁰_A + y t with t · f_A = 1.26, y = (1.26 − 0.5)/0.0025 = 304, f_A =
     * (−25.2, 0, 0), inside its cone. The same without locked loads (least norm): f_A = 1.26 t/|t|²,
     * the same (−25.2, 0, 0); and frictionless, 25.2 N along A's normal. The edge forces of the
     * least-squares phase carry these torques too, but they are not the nearest ones: A on its
     * cone's edge, (−25.2, 0, −12.6) N.
     */
    @Test
    void torquesOnTheBoundaryOfTheConesKeepTheMechanismsForces() {
        double[] frames = upright();
        int fr = 36;                                          // frame {k3}: x along link 3
        double[] p = {0.05, 0, 0.05, 0, 0, 0}, d = {-1, 0, 0, 0, 0, 0};
        for (int c = 0; c < 3; c++) {
            p[3 + c] = frames[fr + 4 * c + 3] - 0.03 * frames[fr + 4 * c];
            d[3 + c] = frames[fr + 4 * c + 1];
        }
        double[] cones = cones(d, 2, MU);
        for (int e = 0; e < M; e++) {
            assertTrue(torqueDir(frames, 2, p, 1, cones, 3 * M + 3 * e) > 0.01, "edge " + e + " of B presses k3 closed");
        }
        for (double locked : new double[] {10, 0}) {
            double[] f0 = {-locked, 0, 0, locked * d[3], locked * d[4], locked * d[5]};
            ContactForces cf = new ContactForces();
            cf.solve(problem(frames, new double[] {0, TAU, 0}, 2, p, d, new int[] {2, 3}).friction(cones, M).locked(f0));
            double[] f = new double[6];
            cf.forceVector(0, f, 0);
            cf.forceVector(1, f, 3);
            double[] expected = {-25.2, 0, 0, 0, 0, 0};
            for (int c = 0; c < 6; c++) assertEquals(expected[c], f[c], 1e-9, locked + " N locked: component " + c);
            assertEquals(0, cf.residual(), 1e-12, locked + " N locked");
        }
        ContactForces frictionless = new ContactForces();
        frictionless.solve(problem(frames, new double[] {0, TAU, 0}, 2, p, d, new int[] {2, 3}).locked(new double[] {-10, 0, 0, 10 * d[3], 10 * d[4], 10 * d[5]}));
        assertEquals(25.2, frictionless.force(0), 1e-9);
        assertEquals(0, frictionless.force(1), 1e-9);
        assertEquals(0, frictionless.residual(), 1e-12);
    }

    /**
     * Torques drawn at random (τk2, τk3 in [−0.5, 1.5] N·m, most of them not carriable by the
     * contacts of the pose) on 300 seeded finger poses: the torques carried are the least-squares
     * ones of an independent quadratic program (ojAlgo: minimise |Σ Tᵀf − τ|² over edge weights
     * λ ≥ 0), and the forces are the least-norm ones carrying them (the second program of
     * {@link #leastNormForcesAgreeWithAQuadraticProgram} on those torques).
     */
    @Test
    void leastSquaresTorquesAgreeWithAQuadraticProgram() {
        Random rnd = new Random(20260518);
        ContactForces cf = new ContactForces();
        int compared = 0, infeasible = 0;
        for (int trial = 0; trial < TRIALS; trial++) {
            Pose pose = Pose.draw(rnd, 4);
            double[] frames = pose.frames, p = pose.p, d = pose.d, cones = pose.cones;
            int n = pose.n;
            int[] links = pose.links;
            double[] tau = {0, -0.5 + 2 * rnd.nextDouble(), -0.5 + 2 * rnd.nextDouble()};
            cf.solve(problem(frames, tau, n, p, d, links).friction(cones, M));
            double[] star = leastSquaresTorque(frames, tau, n, p, links, cones, cf);
            if (star == null) continue;
            double t2 = 0, t3 = 0;
            for (int i = 0; i < n; i++) { t2 += cf.jointTorque(i, 1); t3 += cf.jointTorque(i, 2); }
            assertEquals(star[1], t2, 1e-6, "trial " + trial + ": least-squares torque on k2");
            assertEquals(star[2], t3, 1e-6, "trial " + trial + ": least-squares torque on k3");
            if (Math.hypot(tau[1] - star[1], tau[2] - star[2]) > 1e-3) infeasible++;
            double[] ref = quadraticProgram(frames, star, n, p, links, cones, cf);
            if (ref == null) continue;
            double scale = 1e-5 * (1 + norm(ref));
            double[] f = new double[3];
            for (int i = 0; i < n; i++) {
                cf.forceVector(i, f, 0);
                for (int c = 0; c < 3; c++) assertEquals(ref[3 * i + c], f[c], scale, "trial " + trial + " contact " + i + " component " + c);
            }
            compared++;
        }
        assertTrue(compared > TRIALS * 5 / 6, "compared " + compared);
        assertTrue(infeasible > TRIALS / 3, "torques no cone forces carry: " + infeasible);
    }

    /**
     * Locked-in forces and held joints with friction (the mechanism's forces, DESIGN.md "Which
     * contact forces"): on 300 seeded finger poses with 1–5 contacts, forces locked into the
     * contacts drawn in their cones, joint k2 held in half the trials, the driven joints' torques
     * made by other random forces in the cones (so they can be carried): the forces agree with an
     * independent quadratic program — minimise Σ|f_i − f⁰_i|² over edge weights λ ≥ 0 with the
     * driven joints' rows, the contacts the solver leaves undetermined fixed at their locked
     * forces (ojAlgo) — to 1e-6 relative, the driven torques are carried (residual ≤ 1e-9) and a
     * held joint's reaction is the forces' torque on it.
     */
    @Test
    void lockedForcesAndHeldJointsAgreeWithAQuadraticProgram() {
        Random rnd = new Random(20260501);
        ContactForces cf = new ContactForces();
        int compared = 0, held = 0, moved = 0;
        for (int trial = 0; trial < TRIALS; trial++) {
            Pose pose = Pose.draw(rnd, 5);
            double[] frames = pose.frames, p = pose.p, d = pose.d, cones = pose.cones;
            int n = pose.n;
            int[] links = pose.links;
            double[] tau = new double[3], locked = new double[3 * n];
            for (int i = 0; i < n; i++) {
                for (int e = 0; e < M; e++) {
                    double w = rnd.nextDouble() < 0.5 ? 0 : 10 * rnd.nextDouble();
                    for (int jm = 1; jm < links[i]; jm++) tau[jm] += w * torqueDir(frames, jm, p, i, cones, 3 * M * i + 3 * e);
                    double l = rnd.nextDouble() < 0.6 ? 0 : 10 * rnd.nextDouble();
                    for (int c = 0; c < 3; c++) locked[3 * i + c] += l * cones[3 * M * i + 3 * e + c];
                }
            }
            boolean k2held = rnd.nextBoolean();
            ContactForces.Problem pr = new ContactForces.Problem().frames(frames).held(0).driven(2, tau[2])
                .contacts(n, p, d, links).friction(cones, M).locked(locked);
            if (k2held) pr.held(1); else pr.driven(1, tau[1]);
            cf.solve(pr);
            double[] ref = lockedQuadraticProgram(frames, tau, k2held, locked, n, p, links, cones, cf);
            if (ref == null) continue;
            double scale = 1e-6 * (1 + norm(ref));
            double[] f = new double[3];
            double t2 = 0, t3 = 0, change = 0;
            for (int i = 0; i < n; i++) {
                cf.forceVector(i, f, 0);
                for (int c = 0; c < 3; c++) {
                    assertEquals(ref[3 * i + c], f[c], scale, "trial " + trial + " contact " + i + " component " + c);
                    change = Math.max(change, Math.abs(f[c] - locked[3 * i + c]));
                }
                t2 += cf.jointTorque(i, 1);
                t3 += cf.jointTorque(i, 2);
            }
            assertTrue(cf.residual() <= 1e-9 * (1 + Math.abs(tau[1]) + Math.abs(tau[2])), "trial " + trial + ": residual " + cf.residual());
            assertEquals(t2, cf.torqueOn(1), 1e-12 * (1 + Math.abs(t2)), "trial " + trial);
            if (!k2held) assertEquals(tau[1], t2, 1e-9 * (1 + Math.abs(tau[1])), "trial " + trial);
            assertEquals(tau[2], t3, 1e-9 * (1 + Math.abs(tau[2])), "trial " + trial);
            if (k2held) held++;
            if (change > 1e-3) moved++;
            compared++;
        }
        assertTrue(compared > TRIALS * 5 / 6, "compared " + compared);
        assertTrue(held > TRIALS / 4, "trials with k2 held: " + held);
        assertTrue(moved > TRIALS / 2, "trials whose forces moved from the locked ones: " + moved);
    }

    /**
     * The locked-forces reference: minimise Σ|f − f⁰|² over λ ≥ 0 with the driven joints' rows
     * (k3 always, k2 unless held) that some determined contact loads, the undetermined contacts'
     * forces fixed at f⁰ (which lies in their cones); null if ojAlgo does not report an optimum.
     */
    private static double[] lockedQuadraticProgram(double[] frames, double[] tau, boolean k2held, double[] locked, int n, double[] p,
                                                   int[] links, double[] cones, ContactForces cf) {
        ExpressionsBasedModel model = new ExpressionsBasedModel();
        Variable[] lam = new Variable[n * M];
        for (int v = 0; v < n * M; v++) lam[v] = model.addVariable("l" + v).lower(0);
        Expression obj = model.addExpression("objective").weight(1);
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < M; a++) {
                int ea = 3 * M * i + 3 * a;
                obj.set(lam[i * M + a], -2 * (locked[3 * i] * cones[ea] + locked[3 * i + 1] * cones[ea + 1] + locked[3 * i + 2] * cones[ea + 2]));
                for (int b = 0; b < M; b++) {
                    int eb = 3 * M * i + 3 * b;
                    obj.set(lam[i * M + a], lam[i * M + b], cones[ea] * cones[eb] + cones[ea + 1] * cones[eb + 1] + cones[ea + 2] * cones[eb + 2]);
                }
            }
            if (cf.undetermined(i)) {
                for (int c = 0; c < 3; c++) {
                    Expression fix = model.addExpression("fix" + i + "_" + c).level(locked[3 * i + c]);
                    for (int e = 0; e < M; e++) fix.set(lam[i * M + e], cones[3 * M * i + 3 * e + c]);
                }
            }
        }
        torqueRows(model, lam, frames, tau, k2held ? 2 : 1, n, p, links, cones, cf);
        return forcesOfTheOptimum(model, lam, n, cones);
    }

    /**
     * n contacts on links 2 and 3 of the finger at {@code frames}: on the link's closing side
     * (link frame {kj}: x along the link, back to the joint), pushing roughly along its y axis,
     * tilted at random.
     */
    /**
     * A seeded finger-3 pose with 1 to {@code bound} contacts: θ32 in [10°, 110°],
     * θ33 in [5°, 65°], the contact count, μ in [0.1, 1], the contacts ({@link #randomContacts})
     * and their cones, drawn from {@code rnd} in that order.
     */
    private static final class Pose {
        final double[] frames = new double[48];
        int n;
        double[] p, d, cones;
        int[] links;

        static Pose draw(Random rnd, int bound) {
            Pose x = new Pose();
            FingerKinematics.of(3).frames(new double[] {0, Math.toRadians(10 + 100 * rnd.nextDouble()),
                Math.toRadians(5 + 60 * rnd.nextDouble())}, x.frames);
            x.n = 1 + rnd.nextInt(bound);
            double mu = 0.1 + 0.9 * rnd.nextDouble();
            x.p = new double[3 * x.n];
            x.d = new double[3 * x.n];
            x.links = new int[x.n];
            randomContacts(rnd, x.frames, x.n, x.p, x.d, x.links);
            x.cones = cones(x.d, x.n, mu);
            return x;
        }
    }

    private static void randomContacts(Random rnd, double[] frames, int n, double[] p, double[] d, int[] links) {
        for (int i = 0; i < n; i++) {
            links[i] = 2 + rnd.nextInt(2);
            int fr = 12 * links[i];
            double s = -(0.01 + 0.04 * rnd.nextDouble());
            double off = 0.008 * (rnd.nextDouble() - 0.5);
            for (int c = 0; c < 3; c++) {
                p[3 * i + c] = frames[fr + 4 * c + 3] + s * frames[fr + 4 * c] + off * frames[fr + 4 * c + 1];
                d[3 * i + c] = frames[fr + 4 * c + 1] + 0.6 * rnd.nextGaussian() * (c == 0 ? 1 : 0.5);
            }
            double l = Math.sqrt(d[3 * i] * d[3 * i] + d[3 * i + 1] * d[3 * i + 1] + d[3 * i + 2] * d[3 * i + 2]);
            for (int c = 0; c < 3; c++) d[3 * i + c] /= l;
        }
    }

    /**
     * The reference least-squares torque: minimise |A λ − τ|² over λ ≥ 0 (A: the cone edges'
     * torques on joints 2 and 3, undetermined contacts left out as the solver does) by ojAlgo;
     * returns {0, τ*2, τ*3} = A λ (unique, the projection onto a convex cone), null if ojAlgo does
     * not report an optimum.
     */
    private static double[] leastSquaresTorque(double[] frames, double[] tau, int n, double[] p, int[] links, double[] cones, ContactForces cf) {
        ExpressionsBasedModel model = new ExpressionsBasedModel();
        Variable[] lam = new Variable[n * M];
        for (int v = 0; v < n * M; v++) lam[v] = model.addVariable("l" + v).lower(0);
        double[][] a = new double[3][n * M];
        for (int i = 0; i < n; i++) {
            for (int e = 0; e < M; e++) {
                if (cf.undetermined(i)) { lam[i * M + e].upper(0); continue; }
                for (int jm = 1; jm < links[i]; jm++) a[jm][i * M + e] = torqueDir(frames, jm, p, i, cones, 3 * M * i + 3 * e);
            }
        }
        Expression obj = model.addExpression("objective").weight(1);
        for (int u = 0; u < n * M; u++) {
            double lin = 0;
            for (int jm = 1; jm < 3; jm++) lin += a[jm][u] * tau[jm];
            obj.set(lam[u], -2 * lin);
            for (int v = 0; v < n * M; v++) {
                double q = a[1][u] * a[1][v] + a[2][u] * a[2][v];
                if (q != 0) obj.set(lam[u], lam[v], q);
            }
        }
        Optimisation.Result r = model.minimise();
        if (!r.getState().isOptimal()) return null;
        double[] star = new double[3];
        for (int u = 0; u < n * M; u++) {
            double w = lam[u].getValue().doubleValue();
            for (int jm = 1; jm < 3; jm++) star[jm] += a[jm][u] * w;
        }
        return star;
    }

    /** t_m · e for joint m (0-based) at contact i: (z × (p − o)) · e. */
    private static double torqueDir(double[] frames, int jm, double[] p, int i, double[] e, int eo) {
        int f = 12 * jm;
        double zx = frames[f + 2], zy = frames[f + 6], zz = frames[f + 10];
        double rx = p[3 * i] - frames[f + 3], ry = p[3 * i + 1] - frames[f + 7], rz = p[3 * i + 2] - frames[f + 11];
        double tx = zy * rz - zz * ry, ty = zz * rx - zx * rz, tz = zx * ry - zy * rx;
        return tx * e[eo] + ty * e[eo + 1] + tz * e[eo + 2];
    }

    /**
     * The reference: minimise Σ|f|² over λ ≥ 0 (undetermined contacts left out, as the solver
     * does) with the torque rows of joints 2 and 3 that some contact loads; null if ojAlgo does
     * not report an optimum.
     */
    private static double[] quadraticProgram(double[] frames, double[] tau, int n, double[] p, int[] links, double[] cones, ContactForces cf) {
        ExpressionsBasedModel model = new ExpressionsBasedModel();
        Variable[] lam = new Variable[n * M];
        for (int v = 0; v < n * M; v++) lam[v] = model.addVariable("l" + v).lower(0);
        Expression obj = model.addExpression("objective").weight(1);
        for (int i = 0; i < n; i++) {
            if (cf.undetermined(i)) { for (int e = 0; e < M; e++) lam[i * M + e].upper(0); }
            for (int a = 0; a < M; a++) {
                for (int b = 0; b < M; b++) {
                    int ea = 3 * M * i + 3 * a, eb = 3 * M * i + 3 * b;
                    double dot = cones[ea] * cones[eb] + cones[ea + 1] * cones[eb + 1] + cones[ea + 2] * cones[eb + 2];
                    obj.set(lam[i * M + a], lam[i * M + b], dot);
                }
            }
        }
        torqueRows(model, lam, frames, tau, 1, n, p, links, cones, cf);
        return forcesOfTheOptimum(model, lam, n, cones);
    }

    /**
     * The rows Σ t_m · f = τ_m of the joints from {@code first} to k3 that some contact the
     * solver determined loads (each edge weight's torque on the joint).
     */
    private static void torqueRows(ExpressionsBasedModel model, Variable[] lam, double[] frames, double[] tau, int first, int n, double[] p,
                                   int[] links, double[] cones, ContactForces cf) {
        for (int jm = first; jm < 3; jm++) {
            boolean used = false;
            for (int i = 0; i < n; i++) used |= jm < links[i] && !cf.undetermined(i);
            if (!used) continue;
            Expression row = model.addExpression("tau" + jm).level(tau[jm]);
            for (int i = 0; i < n; i++) {
                if (jm >= links[i]) continue;
                for (int e = 0; e < M; e++) row.set(lam[i * M + e], torqueDir(frames, jm, p, i, cones, 3 * M * i + 3 * e));
            }
        }
    }

    /** The forces Σ λ_e e_e of the program's optimum, 3 per contact; null if ojAlgo does not report one. */
    private static double[] forcesOfTheOptimum(ExpressionsBasedModel model, Variable[] lam, int n, double[] cones) {
        Optimisation.Result r = model.minimise();
        if (!r.getState().isOptimal()) return null;
        double[] f = new double[3 * n];
        for (int i = 0; i < n; i++) {
            for (int e = 0; e < M; e++) {
                double w = lam[i * M + e].getValue().doubleValue();
                for (int c = 0; c < 3; c++) f[3 * i + c] += w * cones[3 * M * i + 3 * e + c];
            }
        }
        return f;
    }

    private static double norm(double[] v) {
        double s = 0;
        for (double x : v) s += x * x;
        return Math.sqrt(s);
    }
}
