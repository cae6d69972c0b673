package org.handsim.dynamics;

import org.handsim.hand.DhRow;
import org.handsim.hand.LinkInertia;
import org.handsim.math.RigidTransform;

/**
 * Recursive Newton–Euler inverse dynamics (Luh, Walker and Paul 1980; Fu–Gonzalez–Lee §3.3,
 * "efficient" form with every vector in its own link frame): the independent cross-check of
 * {@link LagrangeEuler}. It shares nothing with it beyond the chain data and the DH transform
 * ({@link RigidTransform#dhInto}): it uses the inertia tensor about the centre of mass
 * ({@link LinkInertia#inertiaAboutCentreOfMass()}: Table III's tensor about the frame origin
 * less m·(|s̄|²·E − s̄·s̄ᵀ)) instead of the pseudo-inertia, and propagates velocities and forces
 * instead of differentiating T.
 *
 * <h2>The recursion</h2>
 * Quantities of link j are expressed in its frame {j}; {@code R_j} is the rotation of
 * {@code T(j−1 → j)}, {@code ẑ_j = R_jᵀ·(0,0,1) = (0, sin α_j, cos α_j)} the axis of joint j,
 * {@code p*_j = R_jᵀ·(o_j − o_{j−1}) = (a_j, d_j·sin α_j, d_j·cos α_j)}, {@code s̄_j} the centre of
 * mass (Table III), {@code I_j} the inertia about it. Outward, j = 1..n, from
 * {@code ω_0 = ω̇_0 = 0} and {@code v̇_0 = −g} (gravity as a base acceleration):
 * <pre>
 *   ω_j   = R_jᵀ·ω_{j−1} + ẑ_j·q̇_j
 *   ω̇_j   = R_jᵀ·ω̇_{j−1} + ẑ_j·q̈_j + (R_jᵀ·ω_{j−1}) × ẑ_j·q̇_j
 *   v̇_j   = R_jᵀ·v̇_{j−1} + ω̇_j × p*_j + ω_j × (ω_j × p*_j)
 *   ā_j   = v̇_j + ω̇_j × s̄_j + ω_j × (ω_j × s̄_j)
 *   F_j   = m_j·ā_j,   N_j = I_j·ω̇_j + ω_j × (I_j·ω_j)
 * </pre>
 * Inward, j = n..1, with {@code f_{n+1} = n_{n+1} = 0}:
 * <pre>
 *   f_j = R_{j+1}·f_{j+1} + F_j
 *   n_j = R_{j+1}·n_{j+1} + p*_j × (R_{j+1}·f_{j+1}) + (p*_j + s̄_j) × F_j + N_j
 *   τ_j = n_jᵀ·ẑ_j
 * </pre>
 * A fixed joint has q̇ = q̈ = 0 and no reported torque.
 *
 * <p>D, H and C separately come from the same recursion with selected inputs (Walker and Orin
 * 1982, method 1): {@code C = τ(q, 0, 0, g)}, {@code H = τ(q, q̇, 0, 0)}, column k of
 * {@code D = τ(q, 0, e_k, 0)}. The energies come from a velocity pass and the centres of mass in
 * the base frame, again without D.
 *
 * <p>Units, frames and output conventions: {@link ChainDynamics}. Not thread-safe (scratch).
 */
public final class NewtonEuler implements ChainDynamics {
    private final LinkChain chain;
    private final int n, dof;
    private final double[] a, cosAlpha, sinAlpha, d, offset, fixedQ;
    private final boolean[] active;
    private final double[] zHat, pStar, com, inertia, mass;
    // scratch
    private final double[] tr;          // DH transforms T(j-1 -> j), 12 each
    private final double[] w, wd, acc;
    private final double[] qdF, qddF, zeroF, unitF;
    private final double[] column;

    /** Newton–Euler dynamics of {@code chain}. */
    public NewtonEuler(LinkChain chain) {
        this.chain = chain;
        n = chain.links();
        dof = chain.dof();
        a = new double[n];
        cosAlpha = new double[n];
        sinAlpha = new double[n];
        d = new double[n];
        offset = new double[n];
        fixedQ = new double[n];
        active = new boolean[n];
        zHat = new double[3 * n];
        pStar = new double[3 * n];
        com = new double[3 * n];
        inertia = new double[9 * n];
        mass = new double[n];
        for (int j = 0; j < n; j++) {
            DhRow r = chain.dh(j);
            a[j] = r.a();
            cosAlpha[j] = Math.cos(r.alpha());
            sinAlpha[j] = Math.sin(r.alpha());
            d[j] = r.d();
            offset[j] = r.thetaOffset();
            fixedQ[j] = chain.fixedValue(j);
            active[j] = chain.isActive(j);
            double sa = sinAlpha[j], ca = cosAlpha[j];
            zHat[3 * j + 1] = sa;
            zHat[3 * j + 2] = ca;
            pStar[3 * j] = a[j];
            pStar[3 * j + 1] = d[j] * sa;
            pStar[3 * j + 2] = d[j] * ca;
            LinkInertia l = chain.link(j);
            mass[j] = l.mass();
            double[] c = l.com();
            System.arraycopy(c, 0, com, 3 * j, 3);
            double[] t = l.inertiaAboutCentreOfMass();
            double[] full = {
                t[LinkInertia.XX], t[LinkInertia.XY], t[LinkInertia.XZ],
                t[LinkInertia.XY], t[LinkInertia.YY], t[LinkInertia.YZ],
                t[LinkInertia.XZ], t[LinkInertia.YZ], t[LinkInertia.ZZ]};
            System.arraycopy(full, 0, inertia, 9 * j, 9);
        }
        tr = new double[12 * n];
        w = new double[3 * n];
        wd = new double[3 * n];
        acc = new double[3 * n];
        qdF = new double[n];
        qddF = new double[n];
        zeroF = new double[n];
        unitF = new double[n];
        column = new double[dof];
    }

    @Override
    public LinkChain chain() {
        return chain;
    }

    @Override
    public double[] inverseDynamics(double[] q, double[] qd, double[] qdd, double[] g, double[] tauOut) {
        tauOut = Check.out("tauOut", tauOut, dof, q, qd, qdd, g);
        Check.vec("qd", qd, dof);
        Check.vec("qdd", qdd, dof);
        Check.vec("g", g, 3);
        configure(q);
        spread(qd, qdF);
        spread(qdd, qddF);
        rnea(qdF, qddF, g[0], g[1], g[2], tauOut);
        return tauOut;
    }

    @Override
    public double[] massMatrix(double[] q, double[] dOut) {
        dOut = Check.out("dOut", dOut, dof * dof, q, null, null, null);
        configure(q);
        mass(dOut);
        return dOut;
    }

    @Override
    public double[] coriolisCentrifugal(double[] q, double[] qd, double[] hOut) {
        hOut = Check.out("hOut", hOut, dof, q, qd, null, null);
        Check.vec("qd", qd, dof);
        configure(q);
        spread(qd, qdF);
        rnea(qdF, zeroF, 0, 0, 0, hOut);
        return hOut;
    }

    @Override
    public double[] gravityTorque(double[] q, double[] g, double[] cOut) {
        cOut = Check.out("cOut", cOut, dof, q, g, null, null);
        Check.vec("g", g, 3);
        configure(q);
        rnea(zeroF, zeroF, g[0], g[1], g[2], cOut);
        return cOut;
    }

    @Override
    public void terms(double[] q, double[] qd, double[] g, double[] dOut, double[] hOut, double[] cOut) {
        Check.outNonNull("dOut", dOut, dof * dof, q, qd, g);
        Check.outNonNull("hOut", hOut, dof, q, qd, g);
        Check.outNonNull("cOut", cOut, dof, q, qd, g);
        Check.vec("qd", qd, dof);
        Check.vec("g", g, 3);
        configure(q);
        mass(dOut);
        spread(qd, qdF);
        rnea(qdF, zeroF, 0, 0, 0, hOut);
        rnea(zeroF, zeroF, g[0], g[1], g[2], cOut);
    }

    /** Σ ½·m_j·|v̄_j|² + ½·ω_jᵀ·I_j·ω_j from an outward velocity pass (FGL §3.2, evaluated per body). */
    @Override
    public double kineticEnergy(double[] q, double[] qd) {
        Check.vec("qd", qd, dof);
        configure(q);
        spread(qd, qdF);
        double wx = 0, wy = 0, wz = 0, vx = 0, vy = 0, vz = 0, e = 0;
        for (int j = 0; j < n; j++) {
            int t = 12 * j, k = 3 * j;
            // rotate the parent's ω and v into frame j: x_j = Rᵀ·x_{j−1}
            double rwx = tr[t] * wx + tr[t + 4] * wy + tr[t + 8] * wz;
            double rwy = tr[t + 1] * wx + tr[t + 5] * wy + tr[t + 9] * wz;
            double rwz = tr[t + 2] * wx + tr[t + 6] * wy + tr[t + 10] * wz;
            double rvx = tr[t] * vx + tr[t + 4] * vy + tr[t + 8] * vz;
            double rvy = tr[t + 1] * vx + tr[t + 5] * vy + tr[t + 9] * vz;
            double rvz = tr[t + 2] * vx + tr[t + 6] * vy + tr[t + 10] * vz;
            wx = rwx + zHat[k] * qdF[j];
            wy = rwy + zHat[k + 1] * qdF[j];
            wz = rwz + zHat[k + 2] * qdF[j];
            double px = pStar[k], py = pStar[k + 1], pz = pStar[k + 2];
            vx = rvx + wy * pz - wz * py;
            vy = rvy + wz * px - wx * pz;
            vz = rvz + wx * py - wy * px;
            double cx = com[k], cy = com[k + 1], cz = com[k + 2];
            double ux = vx + wy * cz - wz * cy, uy = vy + wz * cx - wx * cz, uz = vz + wx * cy - wy * cx;
            int i = 9 * j;
            double iwx = inertia[i] * wx + inertia[i + 1] * wy + inertia[i + 2] * wz;
            double iwy = inertia[i + 3] * wx + inertia[i + 4] * wy + inertia[i + 5] * wz;
            double iwz = inertia[i + 6] * wx + inertia[i + 7] * wy + inertia[i + 8] * wz;
            e += 0.5 * mass[j] * (ux * ux + uy * uy + uz * uz) + 0.5 * (wx * iwx + wy * iwy + wz * iwz);
        }
        return e;
    }

    /** −Σ m_j·g·p̄_j with the centres of mass p̄_j placed in the base frame link by link. */
    @Override
    public double potentialEnergy(double[] q, double[] g) {
        Check.vec("g", g, 3);
        configure(q);
        // running pose of frame j in the base: rotation r (row-major 3x3) and origin o
        double r0 = 1, r1 = 0, r2 = 0, r3 = 0, r4 = 1, r5 = 0, r6 = 0, r7 = 0, r8 = 1;
        double ox = 0, oy = 0, oz = 0, v = 0;
        for (int j = 0; j < n; j++) {
            int t = 12 * j, k = 3 * j;
            double tx = tr[t + 3], ty = tr[t + 7], tz = tr[t + 11];
            ox += r0 * tx + r1 * ty + r2 * tz;
            oy += r3 * tx + r4 * ty + r5 * tz;
            oz += r6 * tx + r7 * ty + r8 * tz;
            double n0 = r0 * tr[t] + r1 * tr[t + 4] + r2 * tr[t + 8];
            double n1 = r0 * tr[t + 1] + r1 * tr[t + 5] + r2 * tr[t + 9];
            double n2 = r0 * tr[t + 2] + r1 * tr[t + 6] + r2 * tr[t + 10];
            double n3 = r3 * tr[t] + r4 * tr[t + 4] + r5 * tr[t + 8];
            double n4 = r3 * tr[t + 1] + r4 * tr[t + 5] + r5 * tr[t + 9];
            double n5 = r3 * tr[t + 2] + r4 * tr[t + 6] + r5 * tr[t + 10];
            double n6 = r6 * tr[t] + r7 * tr[t + 4] + r8 * tr[t + 8];
            double n7 = r6 * tr[t + 1] + r7 * tr[t + 5] + r8 * tr[t + 9];
            double n8 = r6 * tr[t + 2] + r7 * tr[t + 6] + r8 * tr[t + 10];
            r0 = n0; r1 = n1; r2 = n2; r3 = n3; r4 = n4; r5 = n5; r6 = n6; r7 = n7; r8 = n8;
            double cx = com[k], cy = com[k + 1], cz = com[k + 2];
            double px = ox + r0 * cx + r1 * cy + r2 * cz;
            double py = oy + r3 * cx + r4 * cy + r5 * cz;
            double pz = oz + r6 * cx + r7 * cy + r8 * cz;
            v -= mass[j] * (g[0] * px + g[1] * py + g[2] * pz);
        }
        return v;
    }

    // ------------------------------------------------------------------ internals

    private void configure(double[] q) {
        Check.vec("q", q, dof);
        for (int j = 0, p = 0; j < n; j++) {
            double qj = active[j] ? q[p++] : fixedQ[j];
            RigidTransform.dhInto(qj + offset[j], d[j], a[j], cosAlpha[j], sinAlpha[j], tr, 12 * j);
        }
    }

    private void spread(double[] v, double[] full) {
        for (int j = 0, p = 0; j < n; j++) full[j] = active[j] ? v[p++] : 0.0;
    }

    private void mass(double[] dOut) {
        for (int kp = 0; kp < dof; kp++) {
            int k = chain.linkOfDof(kp);
            unitF[k] = 1;
            rnea(zeroF, unitF, 0, 0, 0, column);
            unitF[k] = 0;
            for (int ip = 0; ip < dof; ip++) dOut[ip * dof + kp] = column[ip];
        }
    }

    /** One outward and one inward pass with the cached transforms; τ of the active joints into tau. */
    private void rnea(double[] qd, double[] qdd, double gx, double gy, double gz, double[] tau) {
        double wx = 0, wy = 0, wz = 0, ax = 0, ay = 0, az = 0, vx = -gx, vy = -gy, vz = -gz;
        for (int j = 0; j < n; j++) {
            int t = 12 * j, k = 3 * j;
            // parent quantities in frame j: x' = Rᵀ·x
            double rwx = tr[t] * wx + tr[t + 4] * wy + tr[t + 8] * wz;
            double rwy = tr[t + 1] * wx + tr[t + 5] * wy + tr[t + 9] * wz;
            double rwz = tr[t + 2] * wx + tr[t + 6] * wy + tr[t + 10] * wz;
            double rax = tr[t] * ax + tr[t + 4] * ay + tr[t + 8] * az;
            double ray = tr[t + 1] * ax + tr[t + 5] * ay + tr[t + 9] * az;
            double raz = tr[t + 2] * ax + tr[t + 6] * ay + tr[t + 10] * az;
            double rvx = tr[t] * vx + tr[t + 4] * vy + tr[t + 8] * vz;
            double rvy = tr[t + 1] * vx + tr[t + 5] * vy + tr[t + 9] * vz;
            double rvz = tr[t + 2] * vx + tr[t + 6] * vy + tr[t + 10] * vz;
            double zx = zHat[k], zy = zHat[k + 1], zz = zHat[k + 2];
            double qdj = qd[j], qddj = qdd[j];
            wx = rwx + zx * qdj;
            wy = rwy + zy * qdj;
            wz = rwz + zz * qdj;
            // ω̇ = Rᵀω̇' + ẑq̈ + (Rᵀω') × ẑq̇
            ax = rax + zx * qddj + (rwy * zz - rwz * zy) * qdj;
            ay = ray + zy * qddj + (rwz * zx - rwx * zz) * qdj;
            az = raz + zz * qddj + (rwx * zy - rwy * zx) * qdj;
            double px = pStar[k], py = pStar[k + 1], pz = pStar[k + 2];
            // v̇ = Rᵀv̇' + ω̇ × p* + ω × (ω × p*)
            double cpx = wy * pz - wz * py, cpy = wz * px - wx * pz, cpz = wx * py - wy * px;
            vx = rvx + (ay * pz - az * py) + (wy * cpz - wz * cpy);
            vy = rvy + (az * px - ax * pz) + (wz * cpx - wx * cpz);
            vz = rvz + (ax * py - ay * px) + (wx * cpy - wy * cpx);
            w[k] = wx; w[k + 1] = wy; w[k + 2] = wz;
            wd[k] = ax; wd[k + 1] = ay; wd[k + 2] = az;
            acc[k] = vx; acc[k + 1] = vy; acc[k + 2] = vz;
        }
        double fx = 0, fy = 0, fz = 0, nx = 0, ny = 0, nz = 0;
        for (int j = n - 1; j >= 0; j--) {
            int k = 3 * j;
            // child's force and moment in frame j: R_{j+1}·f_{j+1}
            double cfx = 0, cfy = 0, cfz = 0, cnx = 0, cny = 0, cnz = 0;
            if (j < n - 1) {
                int t = 12 * (j + 1);
                cfx = tr[t] * fx + tr[t + 1] * fy + tr[t + 2] * fz;
                cfy = tr[t + 4] * fx + tr[t + 5] * fy + tr[t + 6] * fz;
                cfz = tr[t + 8] * fx + tr[t + 9] * fy + tr[t + 10] * fz;
                cnx = tr[t] * nx + tr[t + 1] * ny + tr[t + 2] * nz;
                cny = tr[t + 4] * nx + tr[t + 5] * ny + tr[t + 6] * nz;
                cnz = tr[t + 8] * nx + tr[t + 9] * ny + tr[t + 10] * nz;
            }
            double wx2 = w[k], wy2 = w[k + 1], wz2 = w[k + 2];
            double ax2 = wd[k], ay2 = wd[k + 1], az2 = wd[k + 2];
            double sx = com[k], sy = com[k + 1], sz = com[k + 2];
            // ā = v̇ + ω̇ × s̄ + ω × (ω × s̄)
            double csx = wy2 * sz - wz2 * sy, csy = wz2 * sx - wx2 * sz, csz = wx2 * sy - wy2 * sx;
            double m = mass[j];
            double bigFx = m * (acc[k] + (ay2 * sz - az2 * sy) + (wy2 * csz - wz2 * csy));
            double bigFy = m * (acc[k + 1] + (az2 * sx - ax2 * sz) + (wz2 * csx - wx2 * csz));
            double bigFz = m * (acc[k + 2] + (ax2 * sy - ay2 * sx) + (wx2 * csy - wy2 * csx));
            // N = I·ω̇ + ω × (I·ω)
            int i = 9 * j;
            double iwx = inertia[i] * wx2 + inertia[i + 1] * wy2 + inertia[i + 2] * wz2;
            double iwy = inertia[i + 3] * wx2 + inertia[i + 4] * wy2 + inertia[i + 5] * wz2;
            double iwz = inertia[i + 6] * wx2 + inertia[i + 7] * wy2 + inertia[i + 8] * wz2;
            double bigNx = inertia[i] * ax2 + inertia[i + 1] * ay2 + inertia[i + 2] * az2 + (wy2 * iwz - wz2 * iwy);
            double bigNy = inertia[i + 3] * ax2 + inertia[i + 4] * ay2 + inertia[i + 5] * az2 + (wz2 * iwx - wx2 * iwz);
            double bigNz = inertia[i + 6] * ax2 + inertia[i + 7] * ay2 + inertia[i + 8] * az2 + (wx2 * iwy - wy2 * iwx);
            double px = pStar[k], py = pStar[k + 1], pz = pStar[k + 2];
            double rx = px + sx, ry = py + sy, rz = pz + sz;
            fx = cfx + bigFx;
            fy = cfy + bigFy;
            fz = cfz + bigFz;
            nx = cnx + (py * cfz - pz * cfy) + (ry * bigFz - rz * bigFy) + bigNx;
            ny = cny + (pz * cfx - px * cfz) + (rz * bigFx - rx * bigFz) + bigNy;
            nz = cnz + (px * cfy - py * cfx) + (rx * bigFy - ry * bigFx) + bigNz;
            int p = chain.dofOfLink(j);
            if (p >= 0) tau[p] = nx * zHat[k] + ny * zHat[k + 1] + nz * zHat[k + 2];
        }
    }
}
