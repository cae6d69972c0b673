package org.handsim.body;

import java.util.Arrays;
import org.handsim.math.SymmetricEigen3;
import org.handsim.mesh.MeshWelder;
import org.handsim.mesh.TriangleMesh;
import org.handsim.text.Decimal;

/**
 * The mass, centre of mass and inertia tensor of a rigid body: an immutable value, SI units, in
 * the body's own (mesh) frame.
 *
 * <p><b>From a closed mesh</b> ({@link #ofSolid}): the exact integrals over the polyhedron the
 * surface bounds, by the divergence theorem — volume and first moments as
 * {@link TriangleMesh#signedVolume()} and {@link TriangleMesh#centroid()}, second moments
 * {@code Σ = ∫ r rᵀ dV} as {@link TriangleMesh#secondMoments()} (signed tetrahedra from the
 * origin; Mirtich, "Fast and accurate computation of polyhedral mass properties", J. Graphics
 * Tools 1(2), 1996; Eberly, "Polyhedral mass properties (revisited)", 2002; Tonon 2004) — then
 * the inertia about the origin {@code ρ(tr Σ·E − Σ)} moved to the centre of mass by the parallel
 * axis theorem, {@code I_c = I_o − m(|c|²E − c cᵀ)}. A surface that does not close (after welding
 * coincident vertices, {@link MeshWelder}) or closes around no volume has no interior to
 * integrate over: it is refused, naming the mesh and what to give instead.
 *
 * <p><b>Given</b> ({@link #of}): checked to be a physical body, each failure naming the field
 * ({@code mass_kg}, {@code com_m}, {@code inertia_kg_m2}, the scenario's names): a mass that is
 * not a finite number above 0; a centre of mass that is not finite; an inertia that is not
 * finite, not symmetric, not positive definite, or whose principal moments break the triangle
 * inequality {@code I₁ + I₂ ≥ I₃} (a body's second moments about its centre of mass,
 * {@code ½ tr(I)·E − I}, cannot be negative in any direction).
 *
 * <p>Worked example: a solid box 0.1 × 0.06 × 0.04 m of 1000 kg/m³ has m = 0.24 kg and, about
 * its centre, I = m/12·diag(0.06² + 0.04², 0.1² + 0.04², 0.1² + 0.06²) = diag(1.04e-4,
 * 2.32e-4, 2.72e-4) kg·m².
 */
public final class MassProperties {
    /** Relative tolerance for symmetry and for the triangle inequality (rounding of CAD exports). */
    public static final double TOLERANCE = 1e-9;

    private final double mass;
    private final double[] com;
    private final double[] inertia;
    private final double[] inverse;
    private final double volume;

    private MassProperties(double mass, double[] com, double[] inertia, double volume) {
        this.mass = mass;
        this.com = com;
        this.inertia = inertia;
        this.volume = volume;
        this.inverse = invert(inertia);
    }

    /**
     * A body of the given mass, centre of mass (m, body frame) and inertia about the centre of
     * mass (kg·m², body axes, 9 values row-major).
     *
     * @throws IllegalArgumentException naming the field ({@code mass_kg}, {@code com_m},
     *                                  {@code inertia_kg_m2}) and the value when it is not a body
     */
    public static MassProperties of(double massKg, double[] comM, double[] inertiaKgM2) {
        checkMass(massKg);
        if (comM == null || comM.length != 3) throw new IllegalArgumentException("com_m must have 3 values");
        for (int i = 0; i < 3; i++) {
            if (!Double.isFinite(comM[i])) throw new IllegalArgumentException("com_m[" + i + "] must be a finite number, got " + comM[i]);
        }
        checkInertia(inertiaKgM2);
        return new MassProperties(massKg, comM.clone(), symmetrised(inertiaKgM2), Double.NaN);
    }

    /**
     * The solid the closed mesh bounds, of uniform density (kg/m³).
     *
     * @throws IllegalArgumentException for a density that is not finite and above 0
     *                                  ({@code density_kg_m3}), or a mesh that is open or
     *                                  encloses no volume (naming the mesh and what to add)
     */
    public static MassProperties ofSolid(TriangleMesh mesh, double densityKgM3) {
        if (!(densityKgM3 > 0) || !Double.isFinite(densityKgM3)) {
            throw new IllegalArgumentException("density_kg_m3 must be a finite number above 0, got " + fmt(densityKgM3));
        }
        return solid(mesh, densityKgM3, Double.NaN);
    }

    /**
     * The solid the closed mesh bounds, uniform, of the given total mass (kg).
     *
     * @throws IllegalArgumentException as {@link #ofSolid}, for the mass ({@code mass_kg})
     */
    public static MassProperties ofSolidWithMass(TriangleMesh mesh, double massKg) {
        checkMass(massKg);
        return solid(mesh, Double.NaN, massKg);
    }

    /**
     * The solid's volume (m³) and centre of mass (m) alone, checked as {@link #ofSolid}, for a
     * body whose mass is given and whose inertia is given too: {volume, cx, cy, cz}.
     */
    public static double[] volumeAndCentre(TriangleMesh mesh) {
        double vol = checkedVolume(mesh);
        double[] c = mesh.centroid();
        return new double[] {vol, c[0], c[1], c[2]};
    }

    private static MassProperties solid(TriangleMesh mesh, double density, double mass) {
        double vol = checkedVolume(mesh);
        double rho = Double.isNaN(density) ? mass / vol : density;
        double m = rho * vol;
        double[] c = mesh.centroid();
        double[] s = mesh.secondMoments();
        double xx = rho * s[0], xy = rho * s[1], xz = rho * s[2], yy = rho * s[3], yz = rho * s[4], zz = rho * s[5];
        double tr = xx + yy + zz;
        double cc = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
        double[] in = {
            tr - xx - m * (cc - c[0] * c[0]), -xy + m * c[0] * c[1], -xz + m * c[0] * c[2],
            -xy + m * c[0] * c[1], tr - yy - m * (cc - c[1] * c[1]), -yz + m * c[1] * c[2],
            -xz + m * c[0] * c[2], -yz + m * c[1] * c[2], tr - zz - m * (cc - c[2] * c[2])};
        try {
            checkMass(m);
            checkInertia(in);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(mesh.name() + ": the solid it bounds is not a body (" + e.getMessage()
                + "); give \"mass_kg\" and \"inertia_kg_m2\"", e);
        }
        return new MassProperties(m, c, in, vol);
    }

    /** The enclosed volume (m³, > 0) of a closed mesh, or an error naming the mesh and what to add. */
    private static double checkedVolume(TriangleMesh mesh) {
        TriangleMesh welded = new MeshWelder().weld(mesh.withoutDegenerate());
        if (!welded.isClosed()) {
            int open = openEdges(welded);
            throw new IllegalArgumentException(mesh.name() + ": the surface is not closed (" + open
                + " edges are not shared by exactly two triangles in opposite directions), so it bounds no solid"
                + " to take the mass from: give \"mass_kg\" and \"inertia_kg_m2\" (and \"com_m\"), or close the mesh");
        }
        double vol = mesh.signedVolume();
        double d = mesh.diagonal();
        if (!(Math.abs(vol) > 1e-9 * d * d * d)) {
            throw new IllegalArgumentException(mesh.name() + ": the closed surface encloses no volume ("
                + fmt(vol) + " m³), so it has no mass to take: give \"mass_kg\" and \"inertia_kg_m2\" (and \"com_m\")");
        }
        if (vol < 0) {
            throw new IllegalArgumentException(mesh.name() + ": the surface's triangles face inwards (enclosed volume "
                + fmt(vol) + " m³): reverse their winding, or give \"mass_kg\" and \"inertia_kg_m2\" (and \"com_m\")");
        }
        return vol;
    }

    /** Directed edges of a welded mesh without their reverse, or used twice. */
    private static int openEdges(TriangleMesh m) {
        int[] t = m.triangles();
        long n = m.vertexCount();
        long[] d = new long[t.length];
        for (int i = 0; i < t.length; i += 3) {
            for (int e = 0; e < 3; e++) d[i + e] = t[i + e] * n + t[i + (e + 1) % 3];
        }
        Arrays.sort(d);
        int bad = 0;
        for (int i = 0; i < d.length; i++) {
            boolean twice = (i > 0 && d[i] == d[i - 1]) || (i + 1 < d.length && d[i] == d[i + 1]);
            long a = d[i] / n, b = d[i] % n;
            if (twice || Arrays.binarySearch(d, b * n + a) < 0) bad++;
        }
        return bad;
    }

    private static void checkMass(double m) {
        if (!(m > 0) || !Double.isFinite(m)) {
            throw new IllegalArgumentException("mass_kg must be a finite number above 0, got " + fmt(m));
        }
    }

    /**
     * Checks a 3×3 inertia tensor: finite, symmetric to {@link #TOLERANCE}, positive definite,
     * within the triangle inequality.
     *
     * @throws IllegalArgumentException naming {@code inertia_kg_m2}, the entry or the principal moments
     */
    public static void checkInertia(double[] in) {
        if (in == null || in.length != 9) throw new IllegalArgumentException("inertia_kg_m2 must be a 3×3 matrix (9 values)");
        double scale = 0;
        for (int i = 0; i < 9; i++) {
            if (!Double.isFinite(in[i])) {
                throw new IllegalArgumentException("inertia_kg_m2[" + i / 3 + "][" + i % 3 + "] must be a finite number, got " + in[i]);
            }
            scale = Math.max(scale, Math.abs(in[i]));
        }
        int[][] off = {{0, 1}, {0, 2}, {1, 2}};
        for (int[] p : off) {
            double a = in[3 * p[0] + p[1]], b = in[3 * p[1] + p[0]];
            if (Math.abs(a - b) > TOLERANCE * scale) {
                throw new IllegalArgumentException("inertia_kg_m2 must be symmetric: [" + p[0] + "][" + p[1] + "] = " + fmt(a)
                    + " but [" + p[1] + "][" + p[0] + "] = " + fmt(b));
            }
        }
        double[] vals = new double[3], vecs = new double[9];
        SymmetricEigen3.decompose(symmetrised(in), vals, vecs);
        String moments = "principal moments " + fmt(vals[0]) + ", " + fmt(vals[1]) + ", "
            + fmt(vals[2]) + " kg·m²";
        if (!(vals[0] > TOLERANCE * scale)) {
            throw new IllegalArgumentException("inertia_kg_m2 must be positive definite (" + moments + ")");
        }
        if (vals[0] + vals[1] < vals[2] * (1 - TOLERANCE)) {
            throw new IllegalArgumentException("inertia_kg_m2 breaks the triangle inequality: the two smaller principal moments must add up"
                + " to at least the largest (" + moments + "); no body has such an inertia");
        }
    }

    /** A number for a message: shortest round-trip text, NaN and infinities by name. */
    static String fmt(double d) {
        return Double.isFinite(d) ? Decimal.format(d) : String.valueOf(d);
    }

    private static double[] symmetrised(double[] in) {
        double[] s = in.clone();
        for (int i = 0; i < 3; i++) {
            for (int j = i + 1; j < 3; j++) {
                double v = 0.5 * (in[3 * i + j] + in[3 * j + i]);
                s[3 * i + j] = v;
                s[3 * j + i] = v;
            }
        }
        return s;
    }

    /** Inverse of a symmetric positive definite 3×3 by cofactors. */
    private static double[] invert(double[] a) {
        double c00 = a[4] * a[8] - a[5] * a[7], c01 = a[5] * a[6] - a[3] * a[8], c02 = a[3] * a[7] - a[4] * a[6];
        double det = a[0] * c00 + a[1] * c01 + a[2] * c02;
        double[] inv = {
            c00, a[2] * a[7] - a[1] * a[8], a[1] * a[5] - a[2] * a[4],
            c01, a[0] * a[8] - a[2] * a[6], a[2] * a[3] - a[0] * a[5],
            c02, a[1] * a[6] - a[0] * a[7], a[0] * a[4] - a[1] * a[3]};
        for (int i = 0; i < 9; i++) inv[i] /= det;
        return inv;
    }

    /** @return the mass, kg */
    public double mass() { return mass; }

    /** @return the centre of mass in the body (mesh) frame, m (a copy) */
    public double[] centreOfMass() { return com.clone(); }

    /** @return the inertia tensor about the centre of mass, body axes, kg·m², 9 values row-major (a copy) */
    public double[] inertia() { return inertia.clone(); }

    /** @return the inverse of {@link #inertia()}, 1/(kg·m²) (a copy) */
    public double[] inverseInertia() { return inverse.clone(); }

    /** @return the volume the mesh bounds (m³), NaN when the properties were given */
    public double volume() { return volume; }

    /** @return the principal moments, ascending, kg·m² (a new array) */
    public double[] principalMoments() {
        double[] vals = new double[3], vecs = new double[9];
        SymmetricEigen3.decompose(inertia, vals, vecs);
        return vals;
    }

    double[] inertiaRef() { return inertia; }
    double[] inverseRef() { return inverse; }
    double[] comRef() { return com; }

    @Override
    public String toString() {
        return "MassProperties[m=" + mass + " kg, com=" + Arrays.toString(com) + ", I=" + Arrays.toString(inertia) + "]";
    }
}
