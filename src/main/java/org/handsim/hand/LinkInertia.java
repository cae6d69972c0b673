package org.handsim.hand;

/**
 * Mass properties of one link (paper Table III), in the link's own DH frame {kj}: mass in kg,
 * centre of mass {@code com} in metres, and the inertia tensor <b>about the origin of {kj}</b>,
 * axes of {kj}, in kg·m², as the symmetric matrix entries {@code (Ixx, Ixy, Ixz, Iyy, Iyz, Izz)}
 * with {@code Ixx = ∫(y² + z²) dm} and {@code Ixy = −∫xy dm} (the matrix element).
 *
 * <p><b>How Table III is read</b> (DESIGN.md, "Conventions"). The paper says its tensors are
 * "computed at the frame {kj}", and its products of inertia are listed with the CAD sign,
 * {@code +∫xy dm}; the hand description stores them as printed and the loader negates them
 * into matrix entries. The evidence for this reading over "about the centre of mass":
 * <ul>
 *   <li>about the origin with the CAD sign every link is a physical body (taken to its centre of
 *       mass, positive definite and within the triangle inequality); read with the matrix sign,
 *       link 1 is not positive definite and link 3 breaks the triangle inequality;</li>
 *   <li>against the link meshes of {@code vrml/hand} (uniform density, the table's masses) the
 *       table's moments are 0.96–1.24× the meshes' about the origin (link 3's Ixx 1.65×), but
 *       1.7–5.2× their moments about the centre of mass; link 1's product is the mesh's in sign
 *       and size (+5.72e-5 against +5.19e-5 kg·m² for ∫xy dm) — {@code LinkInertiaFromMeshTest};</li>
 *   <li>Pinocchio, given this reading, gives the mass matrix HandSim gives
 *       ({@code tools/dynamics/pinocchio_reference.py}, {@code PinocchioReferenceTest}).</li>
 * </ul>
 *
 * <p>Lagrange–Euler uses the tensor as it is (the pseudo-inertia about the frame origin is
 * {@code ½·tr(I)·E − I}, no parallel-axis shift); Newton–Euler takes it to the centre of mass,
 * {@link #inertiaAboutCentreOfMass()}.
 */
public record LinkInertia(double mass, double[] com, double[] inertia) {
    /** Index of Ixx, Ixy, Ixz, Iyy, Iyz, Izz in {@link #inertia()}. */
    public static final int XX = 0, XY = 1, XZ = 2, YY = 3, YZ = 4, ZZ = 5;

    public LinkInertia {
        com = com.clone();
        inertia = inertia.clone();
    }

    /**
     * A link given by its inertia about its centre of mass (axes of {kj}, matrix entries),
     * moved to the frame origin by the parallel-axis rule {@code I_o = I_c + m·(|p|²·E − p·pᵀ)}.
     */
    public static LinkInertia aboutCentreOfMass(double mass, double[] com, double[] inertiaAboutCom) {
        if (com.length != 3) throw new IllegalArgumentException("com needs 3 values, got " + com.length);
        if (inertiaAboutCom.length != 6) throw new IllegalArgumentException("inertiaAboutCom needs 6 values, got " + inertiaAboutCom.length);
        return new LinkInertia(mass, com, parallelAxis(mass, com, inertiaAboutCom, +1));
    }

    @Override
    public double[] com() { return com.clone(); }

    /** The tensor about the origin of {kj}, matrix entries (a new array). */
    @Override
    public double[] inertia() { return inertia.clone(); }

    /**
     * The inertia tensor about the centre of mass, axes of {kj}, matrix entries in the order of
     * {@link #inertia()}: {@code I_c = I_o − m·(|p|²·E − p·pᵀ)} (parallel-axis rule), kg·m².
     */
    public double[] inertiaAboutCentreOfMass() {
        return parallelAxis(mass, com, inertia, -1);
    }

    /**
     * The second moments of the mass about the centre of mass, {@code Σc = ∫(r − p)(r − p)ᵀ dm =
     * ½·tr(I_c)·E − I_c}, entries in the order of {@link #inertia()}, kg·m². The link is a physical
     * body exactly when Σc is positive semi-definite (Wensing, Kim, Slotine 2017): then I_c is
     * positive definite and its principal moments satisfy the triangle inequality.
     */
    public double[] secondMomentsAboutCentreOfMass() {
        double[] c = inertiaAboutCentreOfMass();
        double half = 0.5 * (c[XX] + c[YY] + c[ZZ]);
        return new double[] {half - c[XX], -c[XY], -c[XZ], half - c[YY], -c[YZ], half - c[ZZ]};
    }

    private static double[] parallelAxis(double m, double[] p, double[] t, double sign) {
        double s = sign * m;
        double xx = p[0] * p[0], yy = p[1] * p[1], zz = p[2] * p[2];
        return new double[] {
            t[XX] + s * (yy + zz), t[XY] - s * p[0] * p[1], t[XZ] - s * p[0] * p[2],
            t[YY] + s * (xx + zz), t[YZ] - s * p[1] * p[2],
            t[ZZ] + s * (xx + yy)};
    }
}
