package org.handsim.math;

/**
 * Unit quaternions for orientations, as {@code double[]} (w, x, y, z) at an offset: static,
 * allocation-free helpers (Hamilton's product; Shuster, "A survey of attitude
 * representations", J. Astronautical Sciences 41(4), 1993, for the conventions, here the
 * Hamilton/robotics one).
 *
 * <p><b>Convention</b> (docs/STYLE.md, item 1): q = (cos θ/2, sin θ/2·u) is the rotation by θ about
 * the unit axis u acting on vectors, {@code v' = q ⊗ (0, v) ⊗ q*}; as an orientation it maps
 * body coordinates to world coordinates. {@code a ⊗ b} applies b first. Worked example:
 * q = (cos 45°, 0, 0, sin 45°), a quarter turn about z, maps (1, 0, 0) to (0, 1, 0); its
 * matrix is [[0, −1, 0], [1, 0, 0], [0, 0, 1]].
 */
public final class Quaternion {
    private Quaternion() {}

    /** out = a ⊗ b (Hamilton product; out may alias a or b). */
    public static void multiply(double[] a, int ao, double[] b, int bo, double[] out, int oo) {
        double aw = a[ao], ax = a[ao + 1], ay = a[ao + 2], az = a[ao + 3];
        double bw = b[bo], bx = b[bo + 1], by = b[bo + 2], bz = b[bo + 3];
        out[oo] = aw * bw - ax * bx - ay * by - az * bz;
        out[oo + 1] = aw * bx + ax * bw + ay * bz - az * by;
        out[oo + 2] = aw * by - ax * bz + ay * bw + az * bx;
        out[oo + 3] = aw * bz + ax * by - ay * bx + az * bw;
    }

    /** Scales q to unit length in place; returns the length it had. */
    public static double normalize(double[] q, int o) {
        double n = Math.sqrt(q[o] * q[o] + q[o + 1] * q[o + 1] + q[o + 2] * q[o + 2] + q[o + 3] * q[o + 3]);
        q[o] /= n; q[o + 1] /= n; q[o + 2] /= n; q[o + 3] /= n;
        return n;
    }

    /** The 3×3 rotation matrix of unit q, row-major, into {@code r[ro..ro+8]}. */
    public static void toMatrix(double[] q, int o, double[] r, int ro) {
        double w = q[o], x = q[o + 1], y = q[o + 2], z = q[o + 3];
        double xx = x * x, yy = y * y, zz = z * z, xy = x * y, xz = x * z, yz = y * z, wx = w * x, wy = w * y, wz = w * z;
        r[ro] = 1 - 2 * (yy + zz); r[ro + 1] = 2 * (xy - wz);     r[ro + 2] = 2 * (xz + wy);
        r[ro + 3] = 2 * (xy + wz); r[ro + 4] = 1 - 2 * (xx + zz); r[ro + 5] = 2 * (yz - wx);
        r[ro + 6] = 2 * (xz - wy); r[ro + 7] = 2 * (yz + wx);     r[ro + 8] = 1 - 2 * (xx + yy);
    }

    /**
     * The unit quaternion of the rotation vector (rx, ry, rz) (axis × angle, radians; the
     * rotation of {@link RigidTransform#fromPose}) into {@code q[o..o+3]}.
     */
    public static void fromRotationVector(double rx, double ry, double rz, double[] q, int o) {
        double angle = Math.sqrt(rx * rx + ry * ry + rz * rz);
        if (angle < 1e-300) {
            q[o] = 1; q[o + 1] = 0; q[o + 2] = 0; q[o + 3] = 0;
            return;
        }
        double s = Math.sin(0.5 * angle) / angle;
        q[o] = Math.cos(0.5 * angle);
        q[o + 1] = rx * s; q[o + 2] = ry * s; q[o + 3] = rz * s;
    }

    /**
     * The unit quaternion of a rotation matrix (row-major 3×3 at {@code r[ro..]}, or the rotation
     * part of a 12-value transform when {@code stride} is 4), by Shepperd's method: the largest
     * of 1 + tr, 1 + 2r₀₀ − tr, … chosen as the pivot so no square root of a small number is
     * taken. w ≥ 0.
     */
    public static void fromMatrix(double[] r, int ro, int stride, double[] q, int o) {
        double m00 = r[ro], m01 = r[ro + 1], m02 = r[ro + 2];
        double m10 = r[ro + stride], m11 = r[ro + stride + 1], m12 = r[ro + stride + 2];
        double m20 = r[ro + 2 * stride], m21 = r[ro + 2 * stride + 1], m22 = r[ro + 2 * stride + 2];
        double tr = m00 + m11 + m22;
        double w, x, y, z;
        if (tr >= m00 && tr >= m11 && tr >= m22) {
            double s = 2 * Math.sqrt(1 + tr);
            w = 0.25 * s; x = (m21 - m12) / s; y = (m02 - m20) / s; z = (m10 - m01) / s;
        } else if (m00 >= m11 && m00 >= m22) {
            double s = 2 * Math.sqrt(1 + m00 - m11 - m22);
            w = (m21 - m12) / s; x = 0.25 * s; y = (m01 + m10) / s; z = (m02 + m20) / s;
        } else if (m11 >= m22) {
            double s = 2 * Math.sqrt(1 + m11 - m00 - m22);
            w = (m02 - m20) / s; x = (m01 + m10) / s; y = 0.25 * s; z = (m12 + m21) / s;
        } else {
            double s = 2 * Math.sqrt(1 + m22 - m00 - m11);
            w = (m10 - m01) / s; x = (m02 + m20) / s; y = (m12 + m21) / s; z = 0.25 * s;
        }
        if (w < 0) { w = -w; x = -x; y = -y; z = -z; }
        q[o] = w; q[o + 1] = x; q[o + 2] = y; q[o + 3] = z;
        normalize(q, o);
    }

    /**
     * The angle (radians, in [0, π]) of the rotation that takes orientation a to orientation b:
     * 2·atan2(|vec(a* ⊗ b)|, |scalar(a* ⊗ b)|), accurate for small angles.
     */
    public static double angleBetween(double[] a, int ao, double[] b, int bo) {
        double aw = a[ao], ax = -a[ao + 1], ay = -a[ao + 2], az = -a[ao + 3];
        double bw = b[bo], bx = b[bo + 1], by = b[bo + 2], bz = b[bo + 3];
        double w = aw * bw - ax * bx - ay * by - az * bz;
        double x = aw * bx + ax * bw + ay * bz - az * by;
        double y = aw * by - ax * bz + ay * bw + az * bx;
        double z = aw * bz + ax * by - ay * bx + az * bw;
        return 2 * Math.atan2(Math.sqrt(x * x + y * y + z * z), Math.abs(w));
    }
}
