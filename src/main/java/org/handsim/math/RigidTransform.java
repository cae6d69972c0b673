package org.handsim.math;

import java.util.Arrays;

/**
 * An immutable rigid transform (rotation R, translation t) mapping points from a child frame
 * into its parent: {@code p_parent = R · p_child + t}. Stored row-major in 12 doubles
 * {@code [r00 r01 r02 tx; r10 r11 r12 ty; r20 r21 r22 tz]}, the top three rows of the
 * homogeneous 4×4 matrix.
 *
 * <p><b>Convention (worked example).</b> {@code RigidTransform.dh(θ, d, a, α)} is the standard
 * Denavit–Hartenberg link transform {@code T(i−1 → i) = Rz(θ)·Tz(d)·Tx(a)·Rx(α)} (Craig's
 * "classic" DH, Fu–Gonzalez–Lee §2.2). With θ = 90°, d = 0, a = 1, α = 0 the child origin is at
 * parent (0, 1, 0) and the child x axis is the parent y axis: {@code apply({0,0,0})} = (0, 1, 0).
 */
public final class RigidTransform {
    /** The identity transform. */
    public static final RigidTransform IDENTITY = new RigidTransform(new double[] {
        1, 0, 0, 0,
        0, 1, 0, 0,
        0, 0, 1, 0});

    /**
     * The range of a pose read from input (scenario {@code position_m} and {@code rotation_rad},
     * {@code collide --pose-b}): each rotation-vector component within ±{@value #MAX_ROTATION_RAD}
     * rad (160 turns: beyond, the angle's rounding passes 1e-13 rad and the value is a typo, not
     * a pose; at 1e300 its square overflows and Rodrigues' formula gives NaN), each position
     * component within ±{@value #MAX_POSITION_M} m (1000 km: nothing the hand grasps).
     */
    public static final double MAX_ROTATION_RAD = 1000, MAX_POSITION_M = 1e6;

    /**
     * Why a pose read from input is out of range ({@link #MAX_ROTATION_RAD}, {@link #MAX_POSITION_M}),
     * naming the component as {@code name[i]}, or null.
     *
     * @param position 3 numbers (metres) or null; rotation 3 numbers (radians) or null
     */
    public static String poseProblem(String positionName, double[] position, String rotationName, double[] rotation) {
        for (int i = 0; position != null && i < 3; i++) {
            if (!(Math.abs(position[i]) <= MAX_POSITION_M)) {
                return positionName + "[" + i + "] must be within +-1e6 m, got " + org.handsim.text.Decimal.format(position[i]);
            }
        }
        for (int i = 0; rotation != null && i < 3; i++) {
            if (!(Math.abs(rotation[i]) <= MAX_ROTATION_RAD)) {
                return rotationName + "[" + i + "] must be within +-1000 rad (an axis-angle vector: its length is the angle), got "
                    + org.handsim.text.Decimal.format(rotation[i]);
            }
        }
        return null;
    }

    private final double[] m;

    private RigidTransform(double[] m12) {
        this.m = m12;
    }

    /**
     * Wraps a copy of the given 12 row-major values. The rotation part is not re-orthogonalised;
     * callers pass rotations they built from angles.
     */
    public static RigidTransform of(double[] m12) {
        if (m12.length != 12) {
            throw new IllegalArgumentException("a rigid transform needs 12 values, got " + m12.length);
        }
        return new RigidTransform(m12.clone());
    }

    /** A pure translation. */
    public static RigidTransform translation(double x, double y, double z) {
        return new RigidTransform(new double[] {1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z});
    }

    /** A rotation by {@code angle} radians about the z axis. */
    public static RigidTransform rotZ(double angle) {
        double c = Math.cos(angle), s = Math.sin(angle);
        return new RigidTransform(new double[] {c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0});
    }

    /** A rotation by {@code angle} radians about the x axis. */
    public static RigidTransform rotX(double angle) {
        double c = Math.cos(angle), s = Math.sin(angle);
        return new RigidTransform(new double[] {1, 0, 0, 0, 0, c, -s, 0, 0, s, c, 0});
    }

    /**
     * Rotation by the axis-angle vector {@code (rx, ry, rz)} (direction = axis, length = angle
     * in radians, Rodrigues' formula) followed by the translation {@code (tx, ty, tz)}: the
     * {@code --pose-b} convention of the CLI.
     */
    public static RigidTransform fromPose(double tx, double ty, double tz, double rx, double ry, double rz) {
        double[] m = new double[12];
        double angle = Math.sqrt(rx * rx + ry * ry + rz * rz);
        if (!Double.isFinite(angle) || !Double.isFinite(tx + ty + tz)) {
            throw new IllegalArgumentException("pose (" + tx + ", " + ty + ", " + tz + "; " + rx + ", " + ry + ", " + rz
                + ") is not finite: a rotation vector's length must be a finite angle");
        }
        if (angle < 1e-300) {
            m[0] = m[5] = m[10] = 1;
        } else {
            double x = rx / angle, y = ry / angle, z = rz / angle;
            double c = Math.cos(angle), s = Math.sin(angle), v = 1 - c;
            m[0] = x * x * v + c;     m[1] = x * y * v - z * s; m[2] = x * z * v + y * s;
            m[4] = y * x * v + z * s; m[5] = y * y * v + c;     m[6] = y * z * v - x * s;
            m[8] = z * x * v - y * s; m[9] = z * y * v + x * s; m[10] = z * z * v + c;
        }
        m[3] = tx; m[7] = ty; m[11] = tz;
        return new RigidTransform(m);
    }

    /**
     * The rotation as an axis-angle vector (direction = unit axis, length = angle in [0, π]
     * radians): the inverse of the rotation of {@link #fromPose}, so
     * {@code fromPose(t, rotationVector())} rebuilds R to rounding. The angle is
     * atan2(|v|, tr R − 1) with v = (r21 − r12, r02 − r20, r10 − r01) = 2 sin θ·u; near θ = π,
     * where v vanishes, the axis comes from the symmetric part (R + Rᵀ)/2 − cos θ·I
     * = (1 − cos θ)·u uᵀ (its largest column), signed to agree with v (Murray, Li, Sastry,
     * <i>A Mathematical Introduction to Robotic Manipulation</i>, §2.2.3).
     */
    public double[] rotationVector() {
        double vx = m[9] - m[6], vy = m[2] - m[8], vz = m[4] - m[1];
        double s2 = Math.sqrt(vx * vx + vy * vy + vz * vz);          // 2 sin θ
        double c2 = m[0] + m[5] + m[10] - 1;                          // 2 cos θ
        double angle = Math.atan2(s2, c2);
        if (angle < 1e-300) return new double[3];
        double ux, uy, uz;
        if (c2 > -1.0) {                                              // θ < 120°: v is well conditioned
            ux = vx / s2; uy = vy / s2; uz = vz / s2;
        } else {
            double c = 0.5 * c2;
            double b00 = m[0] - c, b11 = m[5] - c, b22 = m[10] - c;
            double b01 = 0.5 * (m[1] + m[4]), b02 = 0.5 * (m[2] + m[8]), b12 = 0.5 * (m[6] + m[9]);
            if (b00 >= b11 && b00 >= b22) { ux = b00; uy = b01; uz = b02; }
            else if (b11 >= b22) { ux = b01; uy = b11; uz = b12; }
            else { ux = b02; uy = b12; uz = b22; }
            double l = Math.sqrt(ux * ux + uy * uy + uz * uz);
            ux /= l; uy /= l; uz /= l;
            if (ux * vx + uy * vy + uz * vz < 0) { ux = -ux; uy = -uy; uz = -uz; }
        }
        return new double[] {ux * angle, uy * angle, uz * angle};
    }

    /**
     * The standard Denavit–Hartenberg transform {@code Rz(θ)·Tz(d)·Tx(a)·Rx(α)}
     * (paper Table I; Fu–Gonzalez–Lee eq. 2.2-29). Angles in radians, lengths in metres.
     */
    public static RigidTransform dh(double theta, double d, double a, double alpha) {
        double[] m = new double[12];
        dhInto(theta, d, a, alpha, m, 0);
        return new RigidTransform(m);
    }

    /** Writes the DH transform's 12 values into {@code out[off..off+11]} (allocation-free). */
    public static void dhInto(double theta, double d, double a, double alpha, double[] out, int off) {
        dhInto(theta, d, a, Math.cos(alpha), Math.sin(alpha), out, off);
    }

    /**
     * As {@link #dhInto(double, double, double, double, double[], int)} with the twist given as
     * {@code cos α} and {@code sin α}, precomputed by callers whose twists are constant (two
     * trigonometric calls per link instead of four; allocation-free).
     */
    public static void dhInto(double theta, double d, double a, double ca, double sa, double[] out, int off) {
        double ct = Math.cos(theta), st = Math.sin(theta);
        out[off] = ct;      out[off + 1] = -st * ca; out[off + 2] = st * sa;  out[off + 3] = a * ct;
        out[off + 4] = st;  out[off + 5] = ct * ca;  out[off + 6] = -ct * sa; out[off + 7] = a * st;
        out[off + 8] = 0;   out[off + 9] = sa;       out[off + 10] = ca;      out[off + 11] = d;
    }

    /**
     * out = A · DH(θ, d, a, α): appends a DH link transform to {@code A} without a temporary
     * (allocation-free; {@code out} must not overlap {@code A}'s 12 values).
     */
    public static void multiplyDh(double[] a, int ao, double theta, double d, double len, double alpha,
                                  double[] out, int oo) {
        multiplyDh(a, ao, theta, d, len, Math.cos(alpha), Math.sin(alpha), out, oo);
    }

    /**
     * As {@link #multiplyDh(double[], int, double, double, double, double, double[], int)} with
     * the twist given as {@code cos α} and {@code sin α}, precomputed by callers whose twists are
     * constant (allocation-free).
     */
    public static void multiplyDh(double[] a, int ao, double theta, double d, double len, double ca, double sa,
                                  double[] out, int oo) {
        double ct = Math.cos(theta), st = Math.sin(theta);
        double c1x = -st * ca, c1y = ct * ca, c1z = sa;
        double c2x = st * sa, c2y = -ct * sa, c2z = ca;
        double c3x = len * ct, c3y = len * st, c3z = d;
        for (int r = 0; r < 3; r++) {
            int i = ao + 4 * r;
            double a0 = a[i], a1 = a[i + 1], a2 = a[i + 2];
            int o = oo + 4 * r;
            out[o] = a0 * ct + a1 * st;
            out[o + 1] = a0 * c1x + a1 * c1y + a2 * c1z;
            out[o + 2] = a0 * c2x + a1 * c2y + a2 * c2z;
            out[o + 3] = a0 * c3x + a1 * c3y + a2 * c3z + a[i + 3];
        }
    }

    /** out = A·B for 12-value row-major rigid transforms (allocation-free; out must not alias). */
    public static void multiply(double[] a, int ao, double[] b, int bo, double[] out, int oo) {
        for (int r = 0; r < 3; r++) {
            double a0 = a[ao + 4 * r], a1 = a[ao + 4 * r + 1], a2 = a[ao + 4 * r + 2];
            out[oo + 4 * r] = a0 * b[bo] + a1 * b[bo + 4] + a2 * b[bo + 8];
            out[oo + 4 * r + 1] = a0 * b[bo + 1] + a1 * b[bo + 5] + a2 * b[bo + 9];
            out[oo + 4 * r + 2] = a0 * b[bo + 2] + a1 * b[bo + 6] + a2 * b[bo + 10];
            out[oo + 4 * r + 3] = a0 * b[bo + 3] + a1 * b[bo + 7] + a2 * b[bo + 11] + a[ao + 4 * r + 3];
        }
    }

    /**
     * out = A⁻¹·B for 12-value row-major rigid transforms (B seen from A: {@code aFromB} for
     * {@code worldFromA}, {@code worldFromB}), through {@code scratch} (12 values, A⁻¹ = (Rᵀ,
     * −Rᵀt) as {@link #inverse()}). Allocation-free; out must not alias a, b or scratch.
     */
    public static void inverseTimes(double[] a, double[] b, double[] scratch, double[] out) {
        inverseTimes(a, 0, b, 0, scratch, out, 0);
    }

    /** {@link #inverseTimes(double[], double[], double[], double[])} with A, B and out at offsets. */
    public static void inverseTimes(double[] a, int ao, double[] b, int bo, double[] scratch, double[] out, int oo) {
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) scratch[4 * r + c] = a[ao + 4 * c + r];
        }
        for (int r = 0; r < 3; r++) {
            scratch[4 * r + 3] = -(scratch[4 * r] * a[ao + 3] + scratch[4 * r + 1] * a[ao + 7] + scratch[4 * r + 2] * a[ao + 11]);
        }
        multiply(scratch, 0, b, bo, out, oo);
    }

    /** @return this · other (apply {@code other} first, then this). */
    public RigidTransform compose(RigidTransform other) {
        double[] out = new double[12];
        multiply(m, 0, other.m, 0, out, 0);
        return new RigidTransform(out);
    }

    /** @return the inverse transform (Rᵀ, −Rᵀt). */
    public RigidTransform inverse() {
        double[] o = new double[12];
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                o[4 * r + c] = m[4 * c + r];
            }
        }
        for (int r = 0; r < 3; r++) {
            o[4 * r + 3] = -(o[4 * r] * m[3] + o[4 * r + 1] * m[7] + o[4 * r + 2] * m[11]);
        }
        return new RigidTransform(o);
    }

    /** out = R·p + t (allocation-free; out may alias p). */
    public void apply(double[] p, double[] out) {
        double x = p[0], y = p[1], z = p[2];
        out[0] = m[0] * x + m[1] * y + m[2] * z + m[3];
        out[1] = m[4] * x + m[5] * y + m[6] * z + m[7];
        out[2] = m[8] * x + m[9] * y + m[10] * z + m[11];
    }

    /** out = R·v (a direction: no translation; out may alias v). */
    public void rotate(double[] v, double[] out) {
        double x = v[0], y = v[1], z = v[2];
        out[0] = m[0] * x + m[1] * y + m[2] * z;
        out[1] = m[4] * x + m[5] * y + m[6] * z;
        out[2] = m[8] * x + m[9] * y + m[10] * z;
    }

    /** @return the point {@code R·p + t} as a new array. */
    public double[] apply(double[] p) {
        double[] out = new double[3];
        apply(p, out);
        return out;
    }

    /** @return element (row, col) of the 3×4 matrix. */
    public double get(int row, int col) {
        return m[4 * row + col];
    }

    /** @return the translation (the child origin in the parent frame), a new array. */
    public double[] origin() {
        return new double[] {m[3], m[7], m[11]};
    }

    /** @return column {@code axis} (0 = x, 1 = y, 2 = z) of R: the child axis in the parent frame. */
    public double[] axis(int axis) {
        return new double[] {m[axis], m[4 + axis], m[8 + axis]};
    }

    /** Copies the 12 row-major values into {@code out[off..off+11]}. */
    public void copyTo(double[] out, int off) {
        System.arraycopy(m, 0, out, off, 12);
    }

    /** @return a copy of the 12 row-major values. */
    public double[] toArray() {
        return m.clone();
    }

    @Override
    public String toString() {
        return "RigidTransform" + Arrays.toString(m);
    }
}
