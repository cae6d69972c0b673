package org.handsim.grasp;

/**
 * The Coulomb friction cone of a point contact, linearised with m edges at a fixed azimuth so
 * that results are reproducible across programs (DESIGN.md decision 5).
 *
 * <p><b>Convention.</b> For a contact with unit normal n — the direction of the force the
 * finger applies to the object, pointing <em>into</em> the object — take
 * a = e_x if |n_x| &lt; 0.9, else e_y; t1 = (n × a)/|n × a|; t2 = n × t1. Edge i (i = 0..m−1)
 * is the force
 * <pre>  f_i = n + μ (cos(2πi/m) t1 + sin(2πi/m) t2)</pre>
 * with a normal component of 1 N, as GraspIt! does. Worked example: n = (0, 0, 1), μ = 0.5,
 * m = 4: a = e_x, t1 = (0, 1, 0), t2 = (−1, 0, 0); edges (0, 0.5, 1), (−0.5, 0, 1),
 * (0, −0.5, 1), (0.5, 0, 1).
 *
 * <p>μ = 0 gives m identical edges (the frictionless contact); callers that want one wrench
 * per frictionless contact may pass m = 1.
 */
public final class FrictionCone {
    /** Default Coulomb coefficient of an object, μ = 0.5 (scenario field {@code object.friction}). */
    public static final double DEFAULT_MU = 0.5;
    /**
     * Largest Coulomb coefficient accepted, μ = 10 (a cone 84° from its axis). Measured
     * coefficients stay below about 2 (rubber on rough surfaces); far beyond, the cone's edges
     * dwarf its normal part and the grasp wrench space degenerates numerically (at μ = 1e308
     * the edges overflow and every hull is "degenerate").
     */
    public static final double MAX_MU = 10;
    /** Default number of cone edges, m = 8. */
    public static final int DEFAULT_EDGES = 8;

    private FrictionCone() {}

    /**
     * Writes the m edge forces of the cone at unit normal (nx, ny, nz) into {@code out} from
     * {@code off}: 3·m values, newtons, in the normal's frame.
     *
     * @throws IllegalArgumentException for μ &lt; 0 or not finite, m &lt; 1, or a normal that is
     *                                  not a finite non-zero vector (it is normalised here)
     */
    public static void edges(double nx, double ny, double nz, double mu, int m, double[] out, int off) {
        checkMu(mu);
        checkEdges(m);
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (!(len > 1e-150) || !(len < 1e150)) {
            // tiny or huge (the squares under- or overflow): scale by the largest component first,
            // so (1e-300, 0, 0) is the unit x axis, not "zero"
            double s = Math.max(Math.abs(nx), Math.max(Math.abs(ny), Math.abs(nz)));
            if (!(s > 0) || !Double.isFinite(s)) {
                throw new IllegalArgumentException("contact normal must be a finite non-zero vector, got ("
                    + nx + ", " + ny + ", " + nz + ")");
            }
            nx /= s; ny /= s; nz /= s;
            len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        }
        nx /= len; ny /= len; nz /= len;
        // a = e_x if |n_x| < 0.9 else e_y; t1 = n × a / |n × a|
        double t1x, t1y, t1z;
        if (Math.abs(nx) < 0.9) { t1x = 0; t1y = nz; t1z = -ny; }      // n × e_x = (0, n_z, −n_y)
        else { t1x = -nz; t1y = 0; t1z = nx; }                          // n × e_y = (−n_z, 0, n_x)
        double tl = Math.sqrt(t1x * t1x + t1y * t1y + t1z * t1z);
        t1x /= tl; t1y /= tl; t1z /= tl;
        double t2x = ny * t1z - nz * t1y, t2y = nz * t1x - nx * t1z, t2z = nx * t1y - ny * t1x;
        for (int i = 0; i < m; i++) {
            double ang = 2 * Math.PI * i / m;
            double c = mu * Math.cos(ang), s = mu * Math.sin(ang);
            out[off + 3 * i] = nx + c * t1x + s * t2x;
            out[off + 3 * i + 1] = ny + c * t1y + s * t2y;
            out[off + 3 * i + 2] = nz + c * t1z + s * t2z;
        }
    }

    /** @throws IllegalArgumentException naming the value unless 0 ≤ μ ≤ {@link #MAX_MU} */
    public static double checkMu(double mu) {
        String why = muProblem(mu);
        if (why != null) throw new IllegalArgumentException("friction coefficient " + why);
        return mu;
    }

    /** Why μ is not accepted ("must be in [0, 10] ..., got V"), or null for 0 ≤ μ ≤ {@link #MAX_MU}. */
    public static String muProblem(double mu) {
        if (mu >= 0 && mu <= MAX_MU) return null;
        return "must be in [0, 10] (measured coefficients stay below 2; beyond 10 the friction cone is numerically a half-space), got "
            + (Double.isNaN(mu) ? "NaN" : org.handsim.text.Decimal.format(mu));
    }

    /** @throws IllegalArgumentException naming the value unless 1 ≤ m ≤ 1024 */
    public static int checkEdges(int m) {
        if (m < 1 || m > 1024) {
            throw new IllegalArgumentException("friction cone edges must be between 1 and 1024, got " + m);
        }
        return m;
    }
}
