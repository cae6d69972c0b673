package org.handsim.dynamics;

import org.handsim.hand.DhRow;
import org.handsim.hand.FingerDescription;
import org.handsim.hand.HandDescription;
import org.handsim.hand.LinkInertia;

/**
 * A serial chain of revolute joints and rigid links: the input of every dynamics algorithm in
 * this package. A BarrettHand finger is one ({@link #finger(FingerDescription)}); a test builds
 * a planar arm the same way ({@link #of(DhRow[], LinkInertia[])}).
 *
 * <p><b>Frames and joints (standard Denavit–Hartenberg, DESIGN.md "Conventions").</b> Link j
 * (1-based, as in Fu–Gonzalez–Lee) carries frame {j}; {@code T(j−1 → j) = Rz(θ_j)·Tz(d_j)·
 * Tx(a_j)·Rx(α_j)} with the DH angle {@code θ_j = q_j + thetaOffset_j}, where q_j is the joint
 * variable (the joint angle of the transmission, eqs 3–4). Joint j turns link j about the z
 * axis of frame {j−1}. Frame {0} is the chain's base, {k0} for a finger; gravity is given there.
 *
 * <p><b>Active and fixed joints.</b> A joint is either active (a generalised coordinate of the
 * dynamics) or fixed at a constant value of its joint variable. Finger 3 has no spread
 * (paper Table I, r = 0): its joint 1 is fixed at θ31 = 0, so its dynamics has two coordinates
 * (n3 = 2, paper eq 8) while link 1 still exists and still carries links 2 and 3. A fixed
 * link does not move, so its mass never enters D, H or C (it only loads its fixed joint,
 * whose torque is not reported). Joint vectors (q, q̇, q̈, τ) passed to the algorithms have
 * {@link #dof()} entries, one per active joint, in chain order.
 *
 * <p><b>Mass properties</b> are those of {@link LinkInertia} (paper Table III, DESIGN.md):
 * centre of mass r̄_j in frame {j}, inertia tensor I_j about the origin of {j} with the axes of
 * {j}, matrix entries (Ixy is the matrix element, i.e. −∫xy dm). The Lagrange–Euler
 * pseudo-inertia about the frame origin (Fu–Gonzalez–Lee §3.2) follows from it without a
 * parallel-axis shift, see {@link #pseudoInertia(int, double[], int)}.
 *
 * <p>Immutable and thread-safe.
 */
public final class LinkChain {
    private final int n;
    private final int dof;
    private final DhRow[] dh;
    private final LinkInertia[] links;
    private final boolean[] active;
    private final double[] fixedValue;
    private final int[] linkOfDof;
    private final int[] dofOfLink;
    private final double[] pseudo;   // 16 per link, row-major 4x4

    private LinkChain(DhRow[] dh, LinkInertia[] links, boolean[] active, double[] fixedValue) {
        if (dh == null || links == null || active == null || fixedValue == null) {
            throw new IllegalArgumentException("dh, links, active and fixedValue must not be null");
        }
        n = dh.length;
        if (n < 1) throw new IllegalArgumentException("a chain needs at least one link, got dh.length = 0");
        if (links.length != n) throw new IllegalArgumentException("links.length must equal dh.length = " + n + ", got " + links.length);
        if (active.length != n) throw new IllegalArgumentException("active.length must equal dh.length = " + n + ", got " + active.length);
        if (fixedValue.length != n) throw new IllegalArgumentException("fixedValue.length must equal dh.length = " + n + ", got " + fixedValue.length);
        this.dh = dh.clone();
        this.links = links.clone();
        this.active = active.clone();
        this.fixedValue = new double[n];
        int count = 0;
        for (int j = 0; j < n; j++) {
            DhRow r = dh[j];
            if (r == null) throw new IllegalArgumentException("dh[" + j + "] is null");
            finite("dh[" + j + "].a", r.a());
            finite("dh[" + j + "].alpha", r.alpha());
            finite("dh[" + j + "].d", r.d());
            finite("dh[" + j + "].thetaOffset", r.thetaOffset());
            LinkInertia l = links[j];
            if (l == null) throw new IllegalArgumentException("links[" + j + "] is null");
            if (!(l.mass() >= 0) || !Double.isFinite(l.mass())) {
                throw new IllegalArgumentException("links[" + j + "].mass must be finite and >= 0, got " + l.mass());
            }
            double[] c = l.com();
            double[] t = l.inertia();
            if (c.length != 3) throw new IllegalArgumentException("links[" + j + "].com needs 3 values, got " + c.length);
            if (t.length != 6) throw new IllegalArgumentException("links[" + j + "].inertia needs 6 values, got " + t.length);
            for (int i = 0; i < 3; i++) finite("links[" + j + "].com[" + i + "]", c[i]);
            for (int i = 0; i < 6; i++) finite("links[" + j + "].inertia[" + i + "]", t[i]);
            if (active[j]) {
                count++;
            } else {
                finite("fixedValue[" + j + "]", fixedValue[j]);
                this.fixedValue[j] = fixedValue[j];
            }
        }
        if (count == 0) throw new IllegalArgumentException("a chain needs at least one active joint, got none of " + n);
        dof = count;
        linkOfDof = new int[dof];
        dofOfLink = new int[n];
        for (int j = 0, p = 0; j < n; j++) {
            dofOfLink[j] = active[j] ? p : -1;
            if (active[j]) linkOfDof[p++] = j;
        }
        pseudo = new double[16 * n];
        for (int j = 0; j < n; j++) fillPseudoInertia(links[j], pseudo, 16 * j);
    }

    private static void finite(String name, double v) {
        if (!Double.isFinite(v)) throw new IllegalArgumentException(name + " must be finite, got " + v);
    }

    /** A chain whose joints are all active. */
    public static LinkChain of(DhRow[] dh, LinkInertia[] links) {
        boolean[] all = new boolean[dh.length];
        java.util.Arrays.fill(all, true);
        return new LinkChain(dh, links, all, new double[dh.length]);
    }

    /**
     * A chain with some joints fixed.
     *
     * @param active     true for a joint that is a generalised coordinate
     * @param fixedValue the joint variable q_j (radians) of each fixed joint; ignored for active ones
     */
    public static LinkChain of(DhRow[] dh, LinkInertia[] links, boolean[] active, double[] fixedValue) {
        return new LinkChain(dh, links, active, fixedValue);
    }

    /**
     * Finger k as a chain in its base frame {k0}: three links, all active for fingers 1 and 2;
     * for a finger without spread (finger 3) joint 1 fixed at θk1 = 0 (paper Table I, r = 0).
     */
    public static LinkChain finger(FingerDescription f) {
        boolean[] act = {f.hasSpread(), true, true};
        return new LinkChain(f.dh(), f.links(), act, new double[3]);
    }

    /** Finger k (1, 2 or 3) of the bundled BarrettHand description. */
    public static LinkChain finger(int k) {
        return finger(HandDescription.barrettHand().finger(k));
    }

    /** @return the number of links (and joints, active or fixed) */
    public int links() { return n; }

    /** @return the number of active joints: the size of q, q̇, q̈, τ and of D (dof × dof) */
    public int dof() { return dof; }

    /** @return DH row of link j (0-based) */
    public DhRow dh(int j) { return dh[j]; }

    /** @return mass properties of link j (0-based), in frame {j+1} of the 1-based numbering */
    public LinkInertia link(int j) { return links[j]; }

    /** @return whether joint j (0-based) is active */
    public boolean isActive(int j) { return active[j]; }

    /** @return the constant joint variable of fixed joint j (0-based), radians; 0 for an active joint */
    public double fixedValue(int j) { return fixedValue[j]; }

    /** @return the 0-based link index of active coordinate p */
    public int linkOfDof(int p) { return linkOfDof[p]; }

    /** @return the coordinate index of joint j (0-based), or −1 if the joint is fixed */
    public int dofOfLink(int j) { return dofOfLink[j]; }

    /**
     * Writes the pseudo-inertia matrix of link j (Fu–Gonzalez–Lee §3.2)
     * <pre>
     *   J_j = ∫ r̄ r̄ᵀ dm  (r̄ = (x, y, z, 1) in frame {j}) =
     *       [ Σxx  Σxy  Σxz  m·x̄ ]
     *       [ Σxy  Σyy  Σyz  m·ȳ ]
     *       [ Σxz  Σyz  Σzz  m·z̄ ]
     *       [ m·x̄  m·ȳ  m·z̄  m   ]
     * </pre>
     * as 16 row-major values into {@code out[off..off+15]} (kg, kg·m, kg·m²). The second moments
     * about the frame origin follow from the inertia tensor I about that origin (matrix entries,
     * {@link LinkInertia}) by {@code Σ = ½·tr(I)·E − I}; e.g. {@code Σxx = ∫x² dm =
     * (−Ixx + Iyy + Izz)/2} and {@code Σxy = ∫xy dm = −Ixy} (FGL §3.2 writes the same with products
     * of inertia, there about the centre of mass plus the parallel-axis term m·r̄·r̄ᵀ: Table III is
     * about the origin already).
     */
    public void pseudoInertia(int j, double[] out, int off) {
        System.arraycopy(pseudo, 16 * j, out, off, 16);
    }

    static void fillPseudoInertia(LinkInertia l, double[] out, int o) {
        double m = l.mass();
        double[] c = l.com();
        double[] t = l.inertia();
        double ixx = t[LinkInertia.XX], ixy = t[LinkInertia.XY], ixz = t[LinkInertia.XZ];
        double iyy = t[LinkInertia.YY], iyz = t[LinkInertia.YZ], izz = t[LinkInertia.ZZ];
        double half = 0.5 * (ixx + iyy + izz);
        double[] s = {
            half - ixx, -ixy, -ixz,
            -ixy, half - iyy, -iyz,
            -ixz, -iyz, half - izz};
        for (int r = 0; r < 3; r++) {
            for (int k = 0; k < 3; k++) out[o + 4 * r + k] = s[3 * r + k];
            out[o + 4 * r + 3] = m * c[r];
            out[o + 12 + r] = m * c[r];
        }
        out[o + 15] = m;
    }

    @Override
    public String toString() {
        return "LinkChain[" + n + " links, " + dof + " active joints]";
    }
}
