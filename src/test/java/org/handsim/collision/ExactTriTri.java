package org.handsim.collision;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.math.MathContext;

/**
 * The exact reference for triangle–triangle intersection used by the tests: a different
 * algorithm and a different exact arithmetic from {@link TriangleIntersector}.
 *
 * <p><b>Algorithm.</b> Not Guigue–Devillers: the intersection of T1 with T2's plane is
 * computed as a list of points (vertices on the plane, and edge crossings as homogeneous
 * rational points (dₓ·y − d_y·x, dₓ − d_y)), likewise T2 ∩ π1; both lie on the line
 * π1 ∩ π2 with direction D = n1 × n2, and the triangles meet iff the two parameter intervals
 * D·X/W overlap (closed). Coplanar pairs are decided by the separating-axis theorem in the
 * projection (disjoint iff some edge has the whole other triangle strictly outside), not by
 * edge–edge tests as in the production code.
 *
 * <p><b>Arithmetic.</b> Every decision is the sign of a polynomial in the input doubles. Each
 * value is a {@link Num}: a floating-point value, the same expression evaluated on absolute
 * values (M), and the length d of the longest chain of roundings; the classical bound
 * |fl(E) − E| ≤ γ_d·M (Higham, "Accuracy and Stability of Numerical Algorithms", §3)
 * certifies the sign when |fl(E)| exceeds twice it (a sum or product of two input doubles that
 * is exact in floating point, checked by Two-Sum or FMA, becomes an exact leaf). Otherwise the
 * expression is re-evaluated exactly as a dyadic rational ({@link Dyadic}: BigInteger mantissa
 * times a power of two; sums and products of doubles are exact there). So the
 * reference is exact, and fast enough for a million pairs because the exact stage only runs
 * in the nearly degenerate cases. The end points are rounded to doubles from 40-digit
 * quotients, far below the 1e-12 the tests compare at.
 */
final class ExactTriTri {
    static final MathContext MC = new MathContext(40);

    /** An exact dyadic rational m·2^e (BigInteger mantissa): sums and products of doubles stay exact. */
    static final class Dyadic {
        static final Dyadic ZERO = new Dyadic(BigInteger.ZERO, 0);
        final BigInteger m;
        final int e;

        Dyadic(BigInteger m, int e) {
            this.m = m;
            this.e = e;
        }

        static Dyadic of(double x) {
            if (x == 0) return ZERO;
            int ex = Math.max(Math.getExponent(x), Double.MIN_EXPONENT) - 52;
            return new Dyadic(BigInteger.valueOf((long) Math.scalb(x, -ex)), ex);
        }

        Dyadic negate() { return new Dyadic(m.negate(), e); }

        Dyadic add(Dyadic o) {
            if (m.signum() == 0) return o;
            if (o.m.signum() == 0) return this;
            int emin = Math.min(e, o.e);
            BigInteger s = m.shiftLeft(e - emin).add(o.m.shiftLeft(o.e - emin));
            if (s.signum() == 0) return ZERO;
            int z = s.getLowestSetBit();
            return new Dyadic(s.shiftRight(z), emin + z);
        }

        Dyadic mul(Dyadic o) {
            if (m.signum() == 0 || o.m.signum() == 0) return ZERO;
            return new Dyadic(m.multiply(o.m), e + o.e);
        }

        BigDecimal toBigDecimal() {
            BigDecimal b = new BigDecimal(m);
            return e >= 0 ? b.multiply(new BigDecimal(BigInteger.ONE.shiftLeft(e)))
                : b.divide(new BigDecimal(BigInteger.ONE.shiftLeft(-e)));
        }
    }

    /** A filtered number: floating value, magnitude bound, rounding depth, exact value on demand. */
    static final class Num {
        final double v, mag;
        final int deg;
        final Num a, b;
        final char op;

        private Num(double v, double mag, int deg, Num a, Num b, char op) {
            this.v = v;
            this.mag = mag;
            this.deg = deg;
            this.a = a;
            this.b = b;
            this.op = op;
        }

        static Num of(double x) {
            return new Num(x, Math.abs(x), 0, null, null, '=');
        }

        /** Exact floating results (checked with Two-Sum / FMA) become new exact leaves. */
        Num add(Num o) {
            double s = v + o.v;
            if (deg == 0 && o.deg == 0) {
                double bv = s - v, err = (v - (s - bv)) + (o.v - bv);
                if (err == 0) return of(s);
                // a sum of two doubles: |error| <= u|exact| <= u|s|(1 + 2u): magnitude |s|, depth 1
                return new Num(s, Math.abs(s) * (1 + 0x1p-51), 1, this, o, '+');
            }
            return new Num(s, mag + o.mag, Math.max(deg, o.deg) + 1, this, o, '+');
        }

        Num sub(Num o) {
            double s = v - o.v;
            if (deg == 0 && o.deg == 0) {
                double ov = -o.v, bv = s - v, err = (v - (s - bv)) + (ov - bv);
                if (err == 0) return of(s);
                return new Num(s, Math.abs(s) * (1 + 0x1p-51), 1, this, o, '-');
            }
            return new Num(s, mag + o.mag, Math.max(deg, o.deg) + 1, this, o, '-');
        }

        Num mul(Num o) {
            double p = v * o.v;
            if (deg == 0 && o.deg == 0 && Math.fma(v, o.v, -p) == 0) return of(p);
            return new Num(p, mag * o.mag, deg + o.deg + 1, this, o, '*');
        }

        private Dyadic exact;

        Dyadic exact() {
            if (exact == null) {
                switch (op) {
                    case '=': exact = Dyadic.of(v); break;
                    case '+': exact = a.exact().add(b.exact()); break;
                    case '-': exact = a.exact().add(b.exact().negate()); break;
                    default: exact = a.exact().mul(b.exact()); break;
                }
            }
            return exact;
        }

        /** The exact sign. */
        int sign() {
            double bound = (deg + 1) * 0x1p-52 * mag * (1 + 0x1p-40) + Double.MIN_NORMAL;
            if (v > bound) return 1;
            if (v < -bound) return -1;
            return exact().m.signum();
        }

        /** The floating-point value (for conditioning estimates only, not decisions). */
        double approx() {
            return v;
        }
    }

    static Num[] sub3(Num[] x, Num[] y) { return new Num[] {x[0].sub(y[0]), x[1].sub(y[1]), x[2].sub(y[2])}; }

    static Num[] cross(Num[] x, Num[] y) {
        return new Num[] {x[1].mul(y[2]).sub(x[2].mul(y[1])), x[2].mul(y[0]).sub(x[0].mul(y[2])), x[0].mul(y[1]).sub(x[1].mul(y[0]))};
    }

    static Num dot(Num[] x, Num[] y) { return x[0].mul(y[0]).add(x[1].mul(y[1])).add(x[2].mul(y[2])); }

    /** The reference's answer for one pair. */
    static final class Answer {
        boolean intersects;
        boolean coplanar;
        /** Segment end points (non-coplanar intersections), doubles rounded from the exact values. */
        double[] a = new double[3], b = new double[3];
        /** True when the segment is well conditioned (see {@link #conditioned}). */
        boolean wellConditioned;
        boolean degenerateInput;
    }

    /**
     * Intersects triangles t1 and t2 (9 doubles each).
     *
     * @param minSine the smallest sine, between the planes and between each crossing edge and
     *                the other plane, for the segment to count as well conditioned
     */
    static Answer intersect(double[] t1, double[] t2, double minSine) {
        Answer ans = new Answer();
        Num[][] p = points(t1), q = points(t2);
        Num[] n1 = cross(sub3(p[1], p[0]), sub3(p[2], p[0]));
        Num[] n2 = cross(sub3(q[1], q[0]), sub3(q[2], q[0]));
        if (zero(n1) || zero(n2)) {
            ans.degenerateInput = true;
            return ans;
        }
        Num[] dq = new Num[3], dp = new Num[3];
        int[] sq = new int[3], sp = new int[3];
        for (int i = 0; i < 3; i++) {
            dq[i] = dot(n1, sub3(q[i], p[0]));
            sq[i] = dq[i].sign();
        }
        if (sameNonZero(sq)) return ans;
        for (int i = 0; i < 3; i++) {
            dp[i] = dot(n2, sub3(p[i], q[0]));
            sp[i] = dp[i].sign();
        }
        if (sameNonZero(sp)) return ans;
        if (sp[0] == 0 && sp[1] == 0 && sp[2] == 0) {
            ans.coplanar = true;
            ans.intersects = coplanarOverlap(p, q, n1);
            return ans;
        }
        Num[] dir = cross(n1, n2);
        Num[][] s1 = section(p, dp, sp), s2 = section(q, dq, sq);
        // each section: homogeneous points (X, Y, Z, W); find lo/hi by the parameter D·X/W
        int lo1 = extreme(s1, dir, -1), hi1 = extreme(s1, dir, 1);
        int lo2 = extreme(s2, dir, -1), hi2 = extreme(s2, dir, 1);
        if (compare(s1[hi1], s2[lo2], dir) < 0 || compare(s2[hi2], s1[lo1], dir) < 0) return ans;
        ans.intersects = true;
        Num[] start = compare(s1[lo1], s2[lo2], dir) >= 0 ? s1[lo1] : s2[lo2];
        Num[] end = compare(s1[hi1], s2[hi2], dir) <= 0 ? s1[hi1] : s2[hi2];
        ans.wellConditioned = conditioned(p, dp, sp, n2, minSine) && conditioned(q, dq, sq, n1, minSine)
            && planeSine(n1, n2) >= minSine;
        if (ans.wellConditioned) {   // the exact end points are only compared for these
            toDouble(start, ans.a);
            toDouble(end, ans.b);
        }
        return ans;
    }

    private static Num[][] points(double[] t) {
        Num[][] p = new Num[3][3];
        for (int i = 0; i < 3; i++) for (int c = 0; c < 3; c++) p[i][c] = Num.of(t[3 * i + c]);
        return p;
    }

    private static boolean zero(Num[] v) { return v[0].sign() == 0 && v[1].sign() == 0 && v[2].sign() == 0; }

    private static boolean sameNonZero(int[] s) { return s[0] != 0 && s[0] == s[1] && s[1] == s[2]; }

    /** The points of triangle t on the other plane, as homogeneous (X, Y, Z, W). */
    private static Num[][] section(Num[][] t, Num[] d, int[] s) {
        Num[][] out = new Num[3][];
        int n = 0;
        Num one = Num.of(1);
        for (int i = 0; i < 3; i++) {
            if (s[i] == 0) out[n++] = new Num[] {t[i][0], t[i][1], t[i][2], one};
        }
        for (int i = 0; i < 3; i++) {
            int j = (i + 1) % 3;
            if (s[i] * s[j] < 0) {
                // x = (d_i t_j − d_j t_i) / (d_i − d_j)
                Num[] h = new Num[4];
                for (int c = 0; c < 3; c++) h[c] = d[i].mul(t[j][c]).sub(d[j].mul(t[i][c]));
                h[3] = d[i].sub(d[j]);
                out[n++] = h;
            }
        }
        return java.util.Arrays.copyOf(out, n);
    }

    /** sign of param(x) − param(y), param = D·X/W. */
    private static int compare(Num[] x, Num[] y, Num[] dir) {
        Num px = dir[0].mul(x[0]).add(dir[1].mul(x[1])).add(dir[2].mul(x[2]));
        Num py = dir[0].mul(y[0]).add(dir[1].mul(y[1])).add(dir[2].mul(y[2]));
        int s = px.mul(y[3]).sub(py.mul(x[3])).sign();
        return s * x[3].sign() * y[3].sign();
    }

    private static int extreme(Num[][] pts, Num[] dir, int which) {
        int best = 0;
        for (int i = 1; i < pts.length; i++) {
            if (compare(pts[i], pts[best], dir) * which > 0) best = i;
        }
        return best;
    }

    /**
     * X/W rounded to double: the floating quotient when its certified error bound is below 1e-14
     * (relative to max(1, |X/W|): a hundredth of the tests' tolerance), else a 40-digit BigDecimal quotient.
     */
    private static void toDouble(Num[] h, double[] out) {
        Num w = h[3];
        double ew = (w.deg + 1) * 0x1p-52 * w.mag * (1 + 0x1p-40);
        for (int c = 0; c < 3; c++) {
            Num x = h[c];
            double ex = (x.deg + 1) * 0x1p-52 * x.mag * (1 + 0x1p-40);
            double q = x.v / w.v;
            double aw = Math.abs(w.v) - ew;
            if (aw > 0) {
                double err = (ex + Math.abs(q) * ew) / aw + Math.abs(q) * 0x1p-52;
                if (err <= 1e-14 * Math.max(1, Math.abs(q))) {
                    out[c] = q;
                    continue;
                }
            }
            out[c] = x.exact().toBigDecimal().divide(w.exact().toBigDecimal(), MC).doubleValue();
        }
    }

    /** Every edge crossing the other plane does so at a sine of at least minSine. */
    private static boolean conditioned(Num[][] t, Num[] d, int[] s, Num[] nOther, double minSine) {
        double nLen = len(nOther);
        for (int i = 0; i < 3; i++) {
            int j = (i + 1) % 3;
            if (s[i] * s[j] < 0) {
                double dd = Math.abs(d[i].approx() - d[j].approx());
                double ex = t[j][0].v - t[i][0].v, ey = t[j][1].v - t[i][1].v, ez = t[j][2].v - t[i][2].v;
                double el = Math.sqrt(ex * ex + ey * ey + ez * ez);
                if (dd / (nLen * el) < minSine) return false;
            }
        }
        return true;
    }

    private static double len(Num[] v) {
        double x = v[0].approx(), y = v[1].approx(), z = v[2].approx();
        return Math.sqrt(x * x + y * y + z * z);
    }

    private static double planeSine(Num[] n1, Num[] n2) {
        double[] a = {n1[0].approx(), n1[1].approx(), n1[2].approx()};
        double[] b = {n2[0].approx(), n2[1].approx(), n2[2].approx()};
        double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2], cz = a[0] * b[1] - a[1] * b[0];
        return Math.sqrt(cx * cx + cy * cy + cz * cz)
            / (Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * Math.sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
    }

    /** Separating-axis test in the projection that drops an axis along which n1 is non-zero. */
    private static boolean coplanarOverlap(Num[][] p, Num[][] q, Num[] n1) {
        int drop = n1[2].sign() != 0 ? 2 : (n1[1].sign() != 0 ? 1 : 0);
        int u = (drop + 1) % 3, v = (drop + 2) % 3;
        int o1 = orient2(p[0], p[1], p[2], u, v), o2 = orient2(q[0], q[1], q[2], u, v);
        return !separates(p, o1, q, u, v) && !separates(q, o2, p, u, v);
    }

    /** Some edge of t (orientation o) has every vertex of other strictly outside. */
    private static boolean separates(Num[][] t, int o, Num[][] other, int u, int v) {
        for (int i = 0; i < 3; i++) {
            Num[] a = t[i], b = t[(i + 1) % 3];
            boolean allOut = true;
            for (int j = 0; j < 3 && allOut; j++) {
                if (orient2(a, b, other[j], u, v) * o >= 0) allOut = false;
            }
            if (allOut) return true;
        }
        return false;
    }

    private static int orient2(Num[] a, Num[] b, Num[] c, int u, int v) {
        return b[u].sub(a[u]).mul(c[v].sub(a[v])).sub(b[v].sub(a[v]).mul(c[u].sub(a[u]))).sign();
    }
}
