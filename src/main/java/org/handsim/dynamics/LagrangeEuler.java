package org.handsim.dynamics;

import org.handsim.hand.DhRow;
import org.handsim.math.RigidTransform;

/**
 * Lagrange–Euler dynamics of a serial chain after Fu, Gonzalez and Lee (FGL), <i>Robotics:
 * Control, Sensing, Vision, and Intelligence</i>, McGraw-Hill 1987, §3.2: the algorithm the paper
 * names for eq (8) and the reference the other implementations are tested against.
 *
 * <h2>The algorithm</h2>
 * Let {@code T_j = ⁰T_j} be the pose of frame {j} in the base frame (a product of DH
 * transforms), {@code J_j} the pseudo-inertia of link j about its frame origin
 * ({@link LinkChain#pseudoInertia}), {@code r̄_j} its homogeneous centre of mass
 * and {@code g = (gx, gy, gz, 0)} gravity in the base frame. With 1-based joints i, k, m, j:
 * <pre>
 *   U_ji  = ∂T_j/∂q_i  = T_{i−1}·Q·ⁱ⁻¹T_j            for i ≤ j, else 0      (LE1)
 *   U_jkm = ∂U_jk/∂q_m = T_{k−1}·Q·ᵏ⁻¹T_{m−1}·Q·ᵐ⁻¹T_j  for k ≤ m ≤ j          (LE2)
 *   D_ik  = Σ_{j=max(i,k)}^{n}   Tr(U_jk·J_j·U_jiᵀ)                          (LE3)
 *   h_ikm = Σ_{j=max(i,k,m)}^{n} Tr(U_jkm·J_j·U_jiᵀ),  h_i = Σ_k Σ_m h_ikm·q̇_k·q̇_m   (LE4)
 *   c_i   = Σ_{j=i}^{n} (−m_j·g·U_ji·r̄_j)                                    (LE5)
 *   τ     = D·q̈ + h + c                       (LE6: the paper's eq 8, H = h, C = c)
 * </pre>
 * with Q the derivative of a rotation about z (rows {@code (0 −1 0 0; 1 0 0 0; 0 0 0 0; 0 0 0 0)}).
 *
 * <h2>How it is evaluated</h2>
 * The definitions above, with three rearrangements that change no value:
 * <ul>
 *   <li>{@code T_{i−1}·Q·T_{i−1}⁻¹ = Δ_i} maps a point p to {@code z_{i−1} × (p − o_{i−1})}
 *       (z, o: axis and origin of frame {i−1} in the base), so {@code U_ji = Δ_i·T_j} is a
 *       column-wise cross product, and {@code U_jkm = Δ_k·U_jm} (k ≤ m) likewise;</li>
 *   <li>{@code Tr(A·J·Bᵀ) = ⟨A, B·J⟩} (Frobenius product, J symmetric), so the products
 *       {@code P_ji = U_ji·J_j} are formed once and every trace is a 12-term dot product;</li>
 *   <li>the sums over k and m in h_i are taken inside the trace:
 *       {@code h_i = Σ_j Tr(V_j·J_j·U_jiᵀ)} with {@code V_j = Σ_k Σ_m U_jkm·q̇_k·q̇_m}
 *       (the velocity part of {@code T̈_j}).</li>
 * </ul>
 * Fixed joints ({@link LinkChain}) have no U; their links still carry the chain.
 *
 * <h2>Also here</h2>
 * The Coriolis matrix {@code N_ik = Σ_m h_ikm·q̇_m} (so {@code H = N·q̇}; h_ikm, symmetric in k
 * and m, equals the Christoffel symbol of D, so {@code Ḋ − 2N} is skew-symmetric) and
 * {@code Ḋ = Σ_j Tr(U̇_jk·J_j·U_jiᵀ) + Tr(U_jk·J_j·U̇_jiᵀ)}, with {@code U̇_jk = Σ_m U_jkm·q̇_m}.
 *
 * <p>Units, frames and output conventions: {@link ChainDynamics}. Not thread-safe (scratch).
 */
public final class LagrangeEuler implements ChainDynamics {
    private final LinkChain chain;
    private final int n, dof;
    private final double[] dhA, dhCosAlpha, dhSinAlpha, dhD, dhOffset, fixedQ;
    private final int[] linkOfDof;
    private final double[] pseudo;
    // scratch
    private final double[] tf;      // T_0f for f = 0..n, 12 each
    private final double[] link;    // one DH transform
    private final double[] u;       // U(j,i): (j*n + i)*12, link j moves frame j+1, joint i turns about z_i
    private final double[] pj;      // P(j,i) = U(j,i)·J_j
    private final double[] uu;      // U(j,k,m), k <= m: ((j*n + k)*n + m)*12
    private final double[] vj;      // V_j
    private final double[] yjk;     // U̇(j,k)
    private final double[] dTmp, hTmp, cTmp, qdFull;

    /** Lagrange–Euler dynamics of {@code chain}. */
    public LagrangeEuler(LinkChain chain) {
        this.chain = chain;
        n = chain.links();
        dof = chain.dof();
        dhA = new double[n];
        dhCosAlpha = new double[n];
        dhSinAlpha = new double[n];
        dhD = new double[n];
        dhOffset = new double[n];
        fixedQ = new double[n];
        for (int j = 0; j < n; j++) {
            DhRow r = chain.dh(j);
            dhA[j] = r.a();
            dhCosAlpha[j] = Math.cos(r.alpha());
            dhSinAlpha[j] = Math.sin(r.alpha());
            dhD[j] = r.d();
            dhOffset[j] = r.thetaOffset();
            fixedQ[j] = chain.fixedValue(j);
        }
        linkOfDof = new int[dof];
        for (int p = 0; p < dof; p++) linkOfDof[p] = chain.linkOfDof(p);
        pseudo = new double[16 * n];
        for (int j = 0; j < n; j++) chain.pseudoInertia(j, pseudo, 16 * j);
        tf = new double[12 * (n + 1)];
        tf[0] = 1;
        tf[5] = 1;
        tf[10] = 1;
        link = new double[12];
        u = new double[12 * n * n];
        pj = new double[12 * n * n];
        uu = new double[12 * n * n * n];
        vj = new double[12 * n];
        yjk = new double[12 * n * n];
        dTmp = new double[dof * dof];
        hTmp = new double[dof];
        cTmp = new double[dof];
        qdFull = new double[n];
    }

    @Override
    public LinkChain chain() {
        return chain;
    }

    @Override
    public double[] inverseDynamics(double[] q, double[] qd, double[] qdd, double[] g, double[] tauOut) {
        tauOut = Check.out("tauOut", tauOut, dof, q, qd, qdd, g);
        Check.vec("qdd", qdd, dof);
        terms(q, qd, g, dTmp, hTmp, cTmp);
        for (int i = 0; i < dof; i++) {
            double s = hTmp[i] + cTmp[i];
            for (int k = 0; k < dof; k++) s += dTmp[i * dof + k] * qdd[k];
            tauOut[i] = s;
        }
        return tauOut;
    }

    @Override
    public double[] massMatrix(double[] q, double[] dOut) {
        dOut = Check.out("dOut", dOut, dof * dof, q, null, null, null);
        kinematics(q);
        products();
        mass(dOut);
        return dOut;
    }

    @Override
    public double[] coriolisCentrifugal(double[] q, double[] qd, double[] hOut) {
        hOut = Check.out("hOut", hOut, dof, q, qd, null, null);
        kinematics(q);
        products();
        velocity(qd);
        coriolis(hOut);
        return hOut;
    }

    @Override
    public double[] gravityTorque(double[] q, double[] g, double[] cOut) {
        cOut = Check.out("cOut", cOut, dof, q, g, null, null);
        kinematics(q);
        gravity(g, cOut);
        return cOut;
    }

    @Override
    public void terms(double[] q, double[] qd, double[] g, double[] dOut, double[] hOut, double[] cOut) {
        Check.outNonNull("dOut", dOut, dof * dof, q, qd, g);
        Check.outNonNull("hOut", hOut, dof, q, qd, g);
        Check.outNonNull("cOut", cOut, dof, q, qd, g);
        kinematics(q);
        products();
        mass(dOut);
        velocity(qd);
        coriolis(hOut);
        gravity(g, cOut);
    }

    @Override
    public double kineticEnergy(double[] q, double[] qd) {
        Check.vec("qd", qd, dof);
        massMatrix(q, dTmp);
        double s = 0;
        for (int i = 0; i < dof; i++) {
            double r = 0;
            for (int k = 0; k < dof; k++) r += dTmp[i * dof + k] * qd[k];
            s += qd[i] * r;
        }
        return 0.5 * s;
    }

    @Override
    public double potentialEnergy(double[] q, double[] g) {
        Check.vec("g", g, 3);
        kinematics(q);
        double v = 0;
        for (int j = 0; j < n; j++) {
            int t = 12 * (j + 1), jo = 16 * j;
            double mx = pseudo[jo + 12], my = pseudo[jo + 13], mz = pseudo[jo + 14], m = pseudo[jo + 15];
            for (int r = 0; r < 3; r++) {
                v -= g[r] * (tf[t + 4 * r] * mx + tf[t + 4 * r + 1] * my + tf[t + 4 * r + 2] * mz + tf[t + 4 * r + 3] * m);
            }
        }
        return v;
    }

    /**
     * The Coriolis matrix {@code N_ik = Σ_m h_ikm·q̇_m = Σ_j Tr(U̇_jk·J_j·U_jiᵀ)} (N·m·s), with
     * {@code H = N·q̇} and {@code Ḋ − 2N} skew-symmetric (h_ikm are the Christoffel symbols of D).
     *
     * @return nOut (dof×dof row-major; new if null)
     */
    public double[] coriolisMatrix(double[] q, double[] qd, double[] nOut) {
        nOut = Check.out("nOut", nOut, dof * dof, q, qd, null, null);
        kinematics(q);
        products();
        velocity(qd);
        for (int ip = 0; ip < dof; ip++) {
            int i = linkOfDof[ip];
            for (int kp = 0; kp < dof; kp++) {
                int k = linkOfDof[kp];
                double s = 0;
                for (int j = Math.max(i, k); j < n; j++) s += dot12(yjk, (j * n + k) * 12, pj, (j * n + i) * 12);
                nOut[ip * dof + kp] = s;
            }
        }
        return nOut;
    }

    /**
     * The time derivative of the inertia matrix along the motion,
     * {@code Ḋ_ik = Σ_j Tr(U̇_jk·J_j·U_jiᵀ) + Tr(U_jk·J_j·U̇_jiᵀ)} (the derivative of (LE3) by the
     * product rule), kg·m²/s.
     *
     * @return dDotOut (dof×dof row-major; new if null)
     */
    public double[] massMatrixDerivative(double[] q, double[] qd, double[] dDotOut) {
        dDotOut = Check.out("dDotOut", dDotOut, dof * dof, q, qd, null, null);
        kinematics(q);
        products();
        velocity(qd);
        for (int ip = 0; ip < dof; ip++) {
            int i = linkOfDof[ip];
            for (int kp = 0; kp < dof; kp++) {
                int k = linkOfDof[kp];
                double s = 0;
                for (int j = Math.max(i, k); j < n; j++) {
                    s += dot12(yjk, (j * n + k) * 12, pj, (j * n + i) * 12)
                        + dot12(yjk, (j * n + i) * 12, pj, (j * n + k) * 12);
                }
                dDotOut[ip * dof + kp] = s;
            }
        }
        return dDotOut;
    }

    /**
     * The Coriolis/centrifugal coefficients {@code h_ikm} of (LE4) (kg·m²), written at
     * {@code out[(i·dof + k)·dof + m]}; symmetric in k and m.
     *
     * @return out (dof³ values; new if null)
     */
    public double[] coriolisCoefficients(double[] q, double[] out) {
        out = Check.out("out", out, dof * dof * dof, q, null, null, null);
        kinematics(q);
        products();
        secondDerivatives();
        for (int ip = 0; ip < dof; ip++) {
            int i = linkOfDof[ip];
            for (int kp = 0; kp < dof; kp++) {
                int k = linkOfDof[kp];
                for (int mp = 0; mp < dof; mp++) {
                    int m = linkOfDof[mp];
                    int lo = Math.min(k, m), hi = Math.max(k, m);
                    double s = 0;
                    for (int j = Math.max(i, hi); j < n; j++) s += dot12(uu, ((j * n + lo) * n + hi) * 12, pj, (j * n + i) * 12);
                    out[(ip * dof + kp) * dof + mp] = s;
                }
            }
        }
        return out;
    }

    // ------------------------------------------------------------------ the steps

    /** T_0f for every frame and U(j,i) = Δ_i·T_{j+1} for every active joint i ≤ j. */
    private void kinematics(double[] q) {
        Check.vec("q", q, dof);
        for (int j = 0, p = 0; j < n; j++) {
            double qj = chain.isActive(j) ? q[p++] : fixedQ[j];
            RigidTransform.dhInto(qj + dhOffset[j], dhD[j], dhA[j], dhCosAlpha[j], dhSinAlpha[j], link, 0);
            RigidTransform.multiply(tf, 12 * j, link, 0, tf, 12 * (j + 1));
        }
        for (int ip = 0; ip < dof; ip++) {
            int i = linkOfDof[ip];
            int zi = 12 * i;
            double zx = tf[zi + 2], zy = tf[zi + 6], zz = tf[zi + 10];
            double ox = tf[zi + 3], oy = tf[zi + 7], oz = tf[zi + 11];
            for (int j = i; j < n; j++) {
                int t = 12 * (j + 1), o = (j * n + i) * 12;
                for (int c = 0; c < 3; c++) {
                    cross(zx, zy, zz, tf[t + c], tf[t + 4 + c], tf[t + 8 + c], u, o + c);
                }
                cross(zx, zy, zz, tf[t + 3] - ox, tf[t + 7] - oy, tf[t + 11] - oz, u, o + 3);
            }
        }
    }

    /** P(j,i) = U(j,i)·J_j. */
    private void products() {
        for (int ip = 0; ip < dof; ip++) {
            int i = linkOfDof[ip];
            for (int j = i; j < n; j++) {
                int o = (j * n + i) * 12, jo = 16 * j;
                for (int r = 0; r < 3; r++) {
                    double u0 = u[o + 4 * r], u1 = u[o + 4 * r + 1], u2 = u[o + 4 * r + 2], u3 = u[o + 4 * r + 3];
                    for (int c = 0; c < 4; c++) {
                        pj[o + 4 * r + c] = u0 * pseudo[jo + c] + u1 * pseudo[jo + 4 + c]
                            + u2 * pseudo[jo + 8 + c] + u3 * pseudo[jo + 12 + c];
                    }
                }
            }
        }
    }

    /** U(j,k,m) = Δ_k·U(j,m) for active k ≤ m ≤ j. */
    private void secondDerivatives() {
        for (int kp = 0; kp < dof; kp++) {
            int k = linkOfDof[kp];
            int zk = 12 * k;
            double zx = tf[zk + 2], zy = tf[zk + 6], zz = tf[zk + 10];
            for (int mp = kp; mp < dof; mp++) {
                int m = linkOfDof[mp];
                for (int j = m; j < n; j++) {
                    int src = (j * n + m) * 12, dst = ((j * n + k) * n + m) * 12;
                    for (int c = 0; c < 4; c++) cross(zx, zy, zz, u[src + c], u[src + 4 + c], u[src + 8 + c], uu, dst + c);
                }
            }
        }
    }

    /** U̇(j,k) = Σ_m U(j,k,m)·q̇_m and V_j = Σ_k U̇(j,k)·q̇_k. */
    private void velocity(double[] qd) {
        Check.vec("qd", qd, dof);
        secondDerivatives();
        for (int p = 0; p < dof; p++) qdFull[linkOfDof[p]] = qd[p];
        java.util.Arrays.fill(vj, 0.0);
        for (int kp = 0; kp < dof; kp++) {
            int k = linkOfDof[kp];
            for (int j = k; j < n; j++) {
                int y = (j * n + k) * 12;
                for (int c = 0; c < 12; c++) yjk[y + c] = 0;
                for (int mp = 0; mp < dof; mp++) {
                    int m = linkOfDof[mp];
                    if (m > j) break;
                    double w = qdFull[m];
                    int src = ((j * n + Math.min(k, m)) * n + Math.max(k, m)) * 12;
                    for (int c = 0; c < 12; c++) yjk[y + c] += w * uu[src + c];
                }
                double w = qdFull[k];
                for (int c = 0; c < 12; c++) vj[12 * j + c] += w * yjk[y + c];
            }
        }
    }

    /** D_ik = Σ_j ⟨U(j,k), P(j,i)⟩ (LE3); upper triangle computed, lower mirrored. */
    private void mass(double[] d) {
        for (int ip = 0; ip < dof; ip++) {
            int i = linkOfDof[ip];
            for (int kp = ip; kp < dof; kp++) {
                int k = linkOfDof[kp];
                double s = 0;
                for (int j = k; j < n; j++) s += dot12(u, (j * n + k) * 12, pj, (j * n + i) * 12);
                d[ip * dof + kp] = s;
                d[kp * dof + ip] = s;
            }
        }
    }

    /** h_i = Σ_j ⟨V_j, P(j,i)⟩ (LE4 with the sums over k, m inside). */
    private void coriolis(double[] h) {
        for (int ip = 0; ip < dof; ip++) {
            int i = linkOfDof[ip];
            double s = 0;
            for (int j = i; j < n; j++) s += dot12(vj, 12 * j, pj, (j * n + i) * 12);
            h[ip] = s;
        }
    }

    /** c_i = −Σ_j gᵀ·U(j,i)·(m_j·r̄_j) (LE5). */
    private void gravity(double[] g, double[] c) {
        Check.vec("g", g, 3);
        double gx = g[0], gy = g[1], gz = g[2];
        for (int ip = 0; ip < dof; ip++) {
            int i = linkOfDof[ip];
            double s = 0;
            for (int j = i; j < n; j++) {
                int o = (j * n + i) * 12, jo = 16 * j;
                double mx = pseudo[jo + 12], my = pseudo[jo + 13], mz = pseudo[jo + 14], m = pseudo[jo + 15];
                s += gx * (u[o] * mx + u[o + 1] * my + u[o + 2] * mz + u[o + 3] * m)
                    + gy * (u[o + 4] * mx + u[o + 5] * my + u[o + 6] * mz + u[o + 7] * m)
                    + gz * (u[o + 8] * mx + u[o + 9] * my + u[o + 10] * mz + u[o + 11] * m);
            }
            c[ip] = -s;
        }
    }

    /** Writes z × v into column slot (out[o], out[o+4], out[o+8]) of a 3×4 matrix. */
    private static void cross(double zx, double zy, double zz, double vx, double vy, double vz, double[] out, int o) {
        out[o] = zy * vz - zz * vy;
        out[o + 4] = zz * vx - zx * vz;
        out[o + 8] = zx * vy - zy * vx;
    }

    private static double dot12(double[] a, int ao, double[] b, int bo) {
        double s = 0;
        for (int c = 0; c < 12; c++) s += a[ao + c] * b[bo + c];
        return s;
    }
}
