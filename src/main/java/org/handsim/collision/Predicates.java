package org.handsim.collision;

/**
 * Robust geometric predicates on double coordinates: the sign of the 3-D orientation
 * determinant and of the 2-D one, always correct, fast in the common case.
 *
 * <p><b>How (Shewchuk 1997).</b> Each predicate first evaluates its determinant in ordinary
 * floating point and compares it with a bound on that evaluation's rounding error (the
 * "static filter" of Shewchuk's {@code orient3d}/{@code orient2d}, bound A:
 * {@code (7 + 56ε)ε · permanent} and {@code (3 + 16ε)ε · permanent}, ε = 2⁻⁵³). When
 * |value| exceeds the bound the sign is certain. Otherwise (a nearly degenerate input: a
 * point on or within rounding noise of a plane or line) the determinant is recomputed exactly
 * with floating-point expansions: every difference of two doubles is held exactly as a
 * two-term expansion ({@code Two-Diff}), products by {@code Two-Product} (one {@link Math#fma}),
 * sums by {@code Fast-Expansion-Sum}; the sign of an expansion is the sign of its largest
 * component. The exact result is also returned as a value (the sum of the components, correct
 * to about one ulp), so callers that go on to use the value get a better one in the hard cases.
 *
 * <p><b>Conventions.</b> {@link #orient3d} returns {@code ((b−a) × (c−a)) · (d−a)}: positive
 * when d lies on the side of the plane (a, b, c) that the right-handed normal of a→b→c points
 * to ("above"), negative below, zero exactly on the plane. (This is minus Shewchuk's
 * {@code orient3d}, which is positive below.) {@link #orient2d} returns
 * {@code (b−a) × (c−a)}: positive when a, b, c turn counter-clockwise.
 *
 * <p>Valid for inputs without overflow or underflow in the products (|coordinates| between
 * about 1e-75 and 1e75 apart from zero, far beyond any mesh in metres).
 *
 * <p><b>Threads.</b> An instance keeps the scratch arrays of the exact stage: one instance per
 * thread. {@link #exactCalls()} counts the inputs that needed the exact stage.
 *
 * <p>References: J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust
 * Geometric Predicates", Discrete &amp; Computational Geometry 18:305–363, 1997; T. J. Dekker,
 * "A floating-point technique for extending the available precision", Numer. Math. 18, 1971.
 */
public final class Predicates {
    /** Shewchuk's ε: half an ulp of 1, 2⁻⁵³. */
    public static final double EPSILON = 0x1p-53;
    /** Error bound factor of the floating-point 3-D orientation (Shewchuk's o3derrboundA). */
    public static final double O3D_BOUND = (7.0 + 56.0 * EPSILON) * EPSILON;
    /** Error bound factor of the floating-point 2-D orientation (Shewchuk's ccwerrboundA). */
    public static final double O2D_BOUND = (3.0 + 16.0 * EPSILON) * EPSILON;

    // Scratch for the exact stage (sizes: 2x2 -> 8 terms, difference of two -> 16, times a
    // 2-term -> 64, sum of three -> 192).
    private final double[] t8a = new double[8], t8b = new double[8], t16 = new double[16];
    private final double[] t64a = new double[64], t64b = new double[64], t64c = new double[64];
    private final double[] t128 = new double[128], t192 = new double[192];
    private final double[] s32a = new double[32], s32b = new double[32];
    private final double[] p4a = new double[4], p4b = new double[4];
    private final double[] two1 = new double[2], two2 = new double[2], two3 = new double[2];
    private final double[] two4 = new double[2], two5 = new double[2], two6 = new double[2];
    private final double[] two7 = new double[2], two8 = new double[2], two9 = new double[2];
    private long exactCalls;

    /** @return how many calls needed the exact stage since this instance was made */
    public long exactCalls() { return exactCalls; }

    /**
     * {@code ((b−a) × (c−a)) · (d−a)} with the correct sign (and the exact value rounded to
     * about one ulp when the floating-point value was inconclusive). Units: length³.
     */
    public double orient3d(double ax, double ay, double az, double bx, double by, double bz,
                           double cx, double cy, double cz, double dx, double dy, double dz) {
        // Shewchuk's expression det[a−d; b−d; c−d], negated at the end.
        double adx = ax - dx, bdx = bx - dx, cdx = cx - dx;
        double ady = ay - dy, bdy = by - dy, cdy = cy - dy;
        double adz = az - dz, bdz = bz - dz, cdz = cz - dz;
        double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
        double cdxady = cdx * ady, adxcdy = adx * cdy;
        double adxbdy = adx * bdy, bdxady = bdx * ady;
        double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
        double permanent = (Math.abs(bdxcdy) + Math.abs(cdxbdy)) * Math.abs(adz)
            + (Math.abs(cdxady) + Math.abs(adxcdy)) * Math.abs(bdz)
            + (Math.abs(adxbdy) + Math.abs(bdxady)) * Math.abs(cdz);
        double bound = O3D_BOUND * permanent;
        if (det > bound || -det > bound) return -det;
        return -orient3dExact(ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz);
    }

    /**
     * The filter of {@link #orient3d} for a plane given by its floating-point normal: with
     * {@code n = (b−a) × (c−a)} computed as {@link #normal} does and {@code nAbs} its
     * permanent terms, returns {@code n · (d − a)} if its sign is certain, else NaN (the
     * caller then asks {@link #orient3d}). The expression and its rounding are those of
     * Shewchuk's orient3d expanded along the row d − a, so bound A holds.
     */
    public static double orient3dFiltered(double[] n, double[] nAbs, int o,
                                          double ax, double ay, double az, double dx, double dy, double dz) {
        return orient3dFiltered(n[o], n[o + 1], n[o + 2], nAbs[o], nAbs[o + 1], nAbs[o + 2], ax, ay, az, dx, dy, dz);
    }

    /**
     * {@link #orient3dFiltered(double[], double[], int, double, double, double, double, double, double)}
     * with the normal (nx, ny, nz) and its permanent terms (mx, my, mz) passed as values: the
     * same arithmetic in the same order, so the same result.
     */
    public static double orient3dFiltered(double nx, double ny, double nz, double mx, double my, double mz,
                                          double ax, double ay, double az, double dx, double dy, double dz) {
        double ux = dx - ax, uy = dy - ay, uz = dz - az;
        double det = ux * nx + uy * ny + uz * nz;
        double perm = Math.abs(ux) * mx + Math.abs(uy) * my + Math.abs(uz) * mz;
        double bound = O3D_BOUND * perm;
        return (det > bound || -det > bound) ? det : Double.NaN;
    }

    /**
     * Writes the floating-point normal {@code (b−a) × (c−a)} to {@code n[o..o+2]} and its
     * permanent terms ({@code |u_y w_z| + |u_z w_y|}, ...) to {@code nAbs[o..o+2]}, for
     * {@link #orient3dFiltered}.
     */
    public static void normal(double ax, double ay, double az, double bx, double by, double bz,
                              double cx, double cy, double cz, double[] n, double[] nAbs, int o) {
        double ux = bx - ax, uy = by - ay, uz = bz - az;
        double wx = cx - ax, wy = cy - ay, wz = cz - az;
        double p1 = uy * wz, p2 = uz * wy, p3 = uz * wx, p4 = ux * wz, p5 = ux * wy, p6 = uy * wx;
        n[o] = p1 - p2;
        n[o + 1] = p3 - p4;
        n[o + 2] = p5 - p6;
        nAbs[o] = Math.abs(p1) + Math.abs(p2);
        nAbs[o + 1] = Math.abs(p3) + Math.abs(p4);
        nAbs[o + 2] = Math.abs(p5) + Math.abs(p6);
    }

    /** {@code (b−a) × (c−a)} in 2-D with the correct sign. Units: length². */
    public double orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
        double detleft = (bx - ax) * (cy - ay);
        double detright = (by - ay) * (cx - ax);
        double det = detleft - detright;
        double bound = O2D_BOUND * (Math.abs(detleft) + Math.abs(detright));
        if (det > bound || -det > bound) return det;
        return orient2dExact(ax, ay, bx, by, cx, cy);
    }

    // ------------------------------------------------------------------ exact stage

    /** Shewchuk's det[a−d; b−d; c−d] exactly (value of the expansion's sum). */
    double orient3dExact(double ax, double ay, double az, double bx, double by, double bz,
                         double cx, double cy, double cz, double dx, double dy, double dz) {
        exactCalls++;
        double[] adx = twoDiff(ax, dx, two1), ady = twoDiff(ay, dy, two2), adz = twoDiff(az, dz, two3);
        double[] bdx = twoDiff(bx, dx, two4), bdy = twoDiff(by, dy, two5), bdz = twoDiff(bz, dz, two6);
        double[] cdx = twoDiff(cx, dx, two7), cdy = twoDiff(cy, dy, two8), cdz = twoDiff(cz, dz, two9);
        if (adx[0] == 0 && ady[0] == 0 && adz[0] == 0 && bdx[0] == 0 && bdy[0] == 0 && bdz[0] == 0
            && cdx[0] == 0 && cdy[0] == 0 && cdz[0] == 0) {
            // the common case (Shewchuk's stage B): every difference is exact, a single double
            int la = minor1(bdx[1], cdy[1], cdx[1], bdy[1], adz[1], t64a);
            int lb = minor1(cdx[1], ady[1], adx[1], cdy[1], bdz[1], t64b);
            int lc = minor1(adx[1], bdy[1], bdx[1], ady[1], cdz[1], t64c);
            int l = fastExpansionSum(t64a, la, t64b, lb, t128);
            l = fastExpansionSum(t128, l, t64c, lc, t192);
            return estimate(t192, l);
        }
        // adz * (bdx*cdy - cdx*bdy)
        int la = minor(bdx, cdy, cdx, bdy, adz, t64a);
        // bdz * (cdx*ady - adx*cdy)
        int lb = minor(cdx, ady, adx, cdy, bdz, t64b);
        // cdz * (adx*bdy - bdx*ady)
        int lc = minor(adx, bdy, bdx, ady, cdz, t64c);
        int l = fastExpansionSum(t64a, la, t64b, lb, t128);
        l = fastExpansionSum(t128, l, t64c, lc, t192);
        return estimate(t192, l);
    }

    /** (p·q − r·s)·z for doubles, exactly, into out (at most 8 terms); returns the length. */
    private int minor1(double p, double q, double r, double s, double z, double[] out) {
        double x1 = p * q, y1 = Math.fma(p, q, -x1);
        double x2 = r * s, y2 = Math.fma(r, s, -x2);
        p4a[0] = y1; p4a[1] = x1;
        p4b[0] = -y2; p4b[1] = -x2;
        int l = fastExpansionSum(p4a, 2, p4b, 2, t8a);
        return scaleExpansion(t8a, l, z, out);
    }

    /** (p·q − r·s)·z for two-term expansions, into out; returns the length. */
    private int minor(double[] p, double[] q, double[] r, double[] s, double[] z, double[] out) {
        int l1 = product2(p, q, t8a);
        int l2 = product2(r, s, t8b);
        for (int i = 0; i < l2; i++) t8b[i] = -t8b[i];
        int l3 = fastExpansionSum(t8a, l1, t8b, l2, t16);
        int l4 = scaleExpansion(t16, l3, z[0], s32a);
        int l5 = scaleExpansion(t16, l3, z[1], s32b);
        return fastExpansionSum(s32a, l4, s32b, l5, out);
    }

    /** Product of two two-term expansions (at most 8 terms). */
    private int product2(double[] e, double[] f, double[] out) {
        int la = scaleExpansion(e, 2, f[0], p4a);
        int lb = scaleExpansion(e, 2, f[1], p4b);
        return fastExpansionSum(p4a, la, p4b, lb, out);
    }

    double orient2dExact(double ax, double ay, double bx, double by, double cx, double cy) {
        exactCalls++;
        double[] bax = twoDiff(bx, ax, two1), cay = twoDiff(cy, ay, two2);
        double[] bay = twoDiff(by, ay, two3), cax = twoDiff(cx, ax, two4);
        int l1 = product2(bax, cay, t8a);
        int l2 = product2(bay, cax, t8b);
        for (int i = 0; i < l2; i++) t8b[i] = -t8b[i];
        int l = fastExpansionSum(t8a, l1, t8b, l2, t16);
        return estimate(t16, l);
    }

    /** a − b exactly as {lo, hi} (increasing magnitude), into out. */
    static double[] twoDiff(double a, double b, double[] out) {
        double x = a - b;
        double bvirt = a - x;
        double avirt = x + bvirt;
        double bround = bvirt - b;
        double around = a - avirt;
        out[0] = around + bround;
        out[1] = x;
        return out;
    }

    /**
     * Shewchuk's Scale-Expansion-Zeroelim: h = e·b exactly, e non-overlapping with components
     * in increasing magnitude; returns the length of h (at least 1).
     */
    static int scaleExpansion(double[] e, int elen, double b, double[] h) {
        double q = e[0] * b;
        double hh = Math.fma(e[0], b, -q);
        int hi = 0;
        if (hh != 0) h[hi++] = hh;
        for (int i = 1; i < elen; i++) {
            double enow = e[i];
            double p1 = enow * b;
            double p0 = Math.fma(enow, b, -p1);
            // Two-Sum(q, p0)
            double sum = q + p0;
            double bv = sum - q;
            double av = sum - bv;
            hh = (q - av) + (p0 - bv);
            if (hh != 0) h[hi++] = hh;
            // Fast-Two-Sum(p1, sum)
            q = p1 + sum;
            hh = sum - (q - p1);
            if (hh != 0) h[hi++] = hh;
        }
        if (q != 0 || hi == 0) h[hi++] = q;
        return hi;
    }

    /**
     * Shewchuk's Fast-Expansion-Sum-Zeroelim: h = e + f exactly (both non-overlapping,
     * increasing magnitude, length at least 1); returns the length of h (at least 1).
     */
    static int fastExpansionSum(double[] e, int elen, double[] f, int flen, double[] h) {
        int ei = 0, fi = 0, hi = 0;
        double enow = e[0], fnow = f[0];
        double q, qnew, hh, bv, av;
        if ((fnow > enow) == (fnow > -enow)) {
            q = enow;
            enow = ++ei < elen ? e[ei] : 0;
        } else {
            q = fnow;
            fnow = ++fi < flen ? f[fi] : 0;
        }
        if (ei < elen && fi < flen) {
            if ((fnow > enow) == (fnow > -enow)) {
                qnew = enow + q;
                hh = q - (qnew - enow);
                enow = ++ei < elen ? e[ei] : 0;
            } else {
                qnew = fnow + q;
                hh = q - (qnew - fnow);
                fnow = ++fi < flen ? f[fi] : 0;
            }
            q = qnew;
            if (hh != 0) h[hi++] = hh;
            while (ei < elen && fi < flen) {
                double x;
                if ((fnow > enow) == (fnow > -enow)) {
                    x = enow;
                    enow = ++ei < elen ? e[ei] : 0;
                } else {
                    x = fnow;
                    fnow = ++fi < flen ? f[fi] : 0;
                }
                qnew = q + x;
                bv = qnew - q;
                av = qnew - bv;
                hh = (q - av) + (x - bv);
                q = qnew;
                if (hh != 0) h[hi++] = hh;
            }
        }
        while (ei < elen) {
            qnew = q + enow;
            bv = qnew - q;
            av = qnew - bv;
            hh = (q - av) + (enow - bv);
            enow = ++ei < elen ? e[ei] : 0;
            q = qnew;
            if (hh != 0) h[hi++] = hh;
        }
        while (fi < flen) {
            qnew = q + fnow;
            bv = qnew - q;
            av = qnew - bv;
            hh = (q - av) + (fnow - bv);
            fnow = ++fi < flen ? f[fi] : 0;
            q = qnew;
            if (hh != 0) h[hi++] = hh;
        }
        if (q != 0 || hi == 0) h[hi++] = q;
        return hi;
    }

    /** The sum of an expansion's components, smallest first: its sign is the expansion's. */
    static double estimate(double[] e, int len) {
        double s = 0;
        for (int i = 0; i < len; i++) s += e[i];
        return s;
    }
}
