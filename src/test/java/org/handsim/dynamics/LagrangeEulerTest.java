package org.handsim.dynamics;

import static org.handsim.dynamics.DynamicsTesting.EXACT;
import static org.handsim.dynamics.DynamicsTesting.FINITE_DIFFERENCE;
import static org.handsim.dynamics.DynamicsTesting.SEED;
import static org.handsim.dynamics.DynamicsTesting.maxAbs;
import static org.handsim.dynamics.DynamicsTesting.randomState;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * {@link LagrangeEuler} against the {@link ChainDynamics} contract, cross-checked with
 * {@link NewtonEuler}; and the extras only it has: the Coriolis matrix N, Ḋ and the
 * coefficients h_ikm.
 */
class LagrangeEulerTest extends AbstractChainDynamicsTest {
    /** Ḋ − 2N must be skew-symmetric within this (absolute, kg·m²/s). */
    private static final double SKEW = 1e-10;

    @Override
    ChainDynamics create(LinkChain chain) {
        return new LagrangeEuler(chain);
    }

    @Override
    ChainDynamics reference(LinkChain chain) {
        return new NewtonEuler(chain);
    }

    /**
     * The passivity property: {@code Ḋ − 2N} is skew-symmetric, so {@code xᵀ(Ḋ − 2N)x = 0}.
     * Ḋ is also checked against a central difference of D along the motion, and N against the
     * Christoffel symbols of D by central differences, so the property is not a tautology of
     * how the two are computed.
     */
    @Test
    void dDotMinusTwoNIsSkewSymmetric() {
        double worstSkew = 0, worstRelSkew = 0;
        for (int k = 1; k <= 3; k += 2) {
            LinkChain chain = LinkChain.finger(k);
            LagrangeEuler le = new LagrangeEuler(chain);
            int n = chain.dof();
            Random r = new Random(SEED);
            double[] nm = new double[n * n], dd = new double[n * n];
            for (int s = 0; s < 1000; s++) {
                DynamicsTesting.State st = randomState(chain, r);
                le.coriolisMatrix(st.q, st.qd, nm);
                le.massMatrixDerivative(st.q, st.qd, dd);
                for (int i = 0; i < n; i++) {
                    for (int j = 0; j < n; j++) {
                        double sym = (dd[i * n + j] - 2 * nm[i * n + j]) + (dd[j * n + i] - 2 * nm[j * n + i]);
                        worstSkew = Math.max(worstSkew, Math.abs(sym));
                        worstRelSkew = Math.max(worstRelSkew, Math.abs(sym) / maxAbs(dd));
                    }
                }
            }
        }
        assertTrue(worstSkew <= SKEW, "max |S + Sᵀ| = " + worstSkew);
        assertTrue(worstRelSkew <= 1e-13, "max |S + Sᵀ| / max|Ḋ| = " + worstRelSkew);
    }

    /** Ḋ against (D(q + ε·q̇) − D(q − ε·q̇)) / 2ε. */
    @Test
    void massMatrixDerivativeMatchesAFiniteDifferenceAlongTheMotion() {
        LinkChain chain = LinkChain.finger(1);
        LagrangeEuler le = new LagrangeEuler(chain);
        Random r = new Random(SEED);
        double eps = 1e-6;
        for (int s = 0; s < 200; s++) {
            DynamicsTesting.State st = randomState(chain, r);
            double[] dd = le.massMatrixDerivative(st.q, st.qd, null);
            double[] qp = st.q.clone(), qm = st.q.clone();
            for (int i = 0; i < 3; i++) {
                qp[i] += eps * st.qd[i];
                qm[i] -= eps * st.qd[i];
            }
            double[] dp = le.massMatrix(qp, null), dmn = le.massMatrix(qm, null);
            double scale = maxAbs(le.massMatrix(st.q, null)) * Math.sqrt(DynamicsTesting.dot(st.qd, st.qd));
            for (int i = 0; i < 9; i++) assertEquals((dp[i] - dmn[i]) / (2 * eps), dd[i], FINITE_DIFFERENCE * scale);
        }
    }

    /**
     * N_ik = Σ_m c_ikm·q̇_m with the Christoffel symbols c_ikm = ½(∂D_ik/∂q_m + ∂D_im/∂q_k −
     * ∂D_km/∂q_i) of D (by central differences); H = N·q̇; h_ikm symmetric in k, m.
     */
    @Test
    void coriolisMatrixIsBuiltFromTheChristoffelSymbolsOfD() {
        for (int k = 1; k <= 3; k += 2) {
            LinkChain chain = LinkChain.finger(k);
            LagrangeEuler le = new LagrangeEuler(chain);
            int n = chain.dof();
            Random r = new Random(SEED);
            double eps = 1e-6;
            for (int s = 0; s < 100; s++) {
                DynamicsTesting.State st = randomState(chain, r);
                double[][] dD = new double[n][];   // dD[m] = ∂D/∂q_m
                for (int m = 0; m < n; m++) {
                    double[] qp = st.q.clone(), qm = st.q.clone();
                    qp[m] += eps;
                    qm[m] -= eps;
                    double[] a = le.massMatrix(qp, null), b = le.massMatrix(qm, null);
                    dD[m] = new double[n * n];
                    for (int i = 0; i < n * n; i++) dD[m][i] = (a[i] - b[i]) / (2 * eps);
                }
                double[] h = le.coriolisCoefficients(st.q, null);
                double[] nm = le.coriolisMatrix(st.q, st.qd, null);
                double[] hv = le.coriolisCentrifugal(st.q, st.qd, null);
                double scaleD = maxAbs(le.massMatrix(st.q, null));
                for (int i = 0; i < n; i++) {
                    double hi = 0;
                    for (int kk = 0; kk < n; kk++) {
                        double nik = 0;
                        for (int m = 0; m < n; m++) {
                            double c = 0.5 * (dD[m][i * n + kk] + dD[kk][i * n + m] - dD[i][kk * n + m]);
                            double hikm = h[(i * n + kk) * n + m];
                            assertEquals(c, hikm, FINITE_DIFFERENCE * scaleD, "h_ikm = Christoffel symbol");
                            assertEquals(h[(i * n + m) * n + kk], hikm, EXACT * scaleD, "h_ikm symmetric in k, m");
                            nik += hikm * st.qd[m];
                        }
                        assertEquals(nik, nm[i * n + kk], 1e-13 * scaleD * 5);
                        hi += nm[i * n + kk] * st.qd[kk];
                    }
                    assertEquals(hi, hv[i], 1e-13 * scaleD * 25);
                }
            }
        }
    }
}
