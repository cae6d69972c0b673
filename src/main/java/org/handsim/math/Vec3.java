package org.handsim.math;

/**
 * Static helpers for 3-vectors stored in {@code double[]} (x, y, z) or at an offset inside a
 * flat array. All methods are allocation-free unless they return a new array.
 */
public final class Vec3 {
    private Vec3() {}

    /** @return a·b */
    public static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    /** out = a × b; {@code out} must not alias {@code a} or {@code b}. */
    public static void cross(double[] a, double[] b, double[] out) {
        double x = a[1] * b[2] - a[2] * b[1];
        double y = a[2] * b[0] - a[0] * b[2];
        double z = a[0] * b[1] - a[1] * b[0];
        out[0] = x; out[1] = y; out[2] = z;
    }

    /** out = a − b (out may alias a or b). */
    public static void sub(double[] a, double[] b, double[] out) {
        out[0] = a[0] - b[0]; out[1] = a[1] - b[1]; out[2] = a[2] - b[2];
    }

    /** out = a + b (out may alias a or b). */
    public static void add(double[] a, double[] b, double[] out) {
        out[0] = a[0] + b[0]; out[1] = a[1] + b[1]; out[2] = a[2] + b[2];
    }

    /** out = a·s (out may alias a). */
    public static void scale(double[] a, double s, double[] out) {
        out[0] = a[0] * s; out[1] = a[1] * s; out[2] = a[2] * s;
    }

    /** @return |a| */
    public static double norm(double[] a) {
        return Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    }

    /** @return |a − b| */
    public static double distance(double[] a, double[] b) {
        double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /**
     * Normalises {@code a} in place.
     *
     * @return the original length; if it is 0 (or not finite) {@code a} is left unchanged
     */
    public static double normalize(double[] a) {
        double n = norm(a);
        if (n > 0 && Double.isFinite(n)) {
            a[0] /= n; a[1] /= n; a[2] /= n;
        }
        return n;
    }

    /** @return true if all three components are finite */
    public static boolean isFinite(double[] a) {
        return Double.isFinite(a[0]) && Double.isFinite(a[1]) && Double.isFinite(a[2]);
    }

    /** @return a new array {x, y, z} */
    public static double[] of(double x, double y, double z) {
        return new double[] {x, y, z};
    }
}
