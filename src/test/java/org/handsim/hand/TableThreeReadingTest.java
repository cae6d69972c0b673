package org.handsim.hand;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.TestPaths;
import org.handsim.collision.TestMeshes;
import org.handsim.mesh.TriangleMesh;
import org.junit.jupiter.api.Test;

/**
 * Which way Table III is read ({@link LinkInertia}): about the origin of each link frame {kj},
 * products of inertia as +∫xy dm. Two independent checks: the hand's own link meshes, and the
 * physics every rigid body obeys.
 */
class TableThreeReadingTest {
    private static final HandDescription HAND = HandDescription.barrettHand();
    private static final int[] DIAGONAL = {LinkInertia.XX, LinkInertia.YY, LinkInertia.ZZ};

    /**
     * Each link's mesh in {@code vrml/hand} (in its own frame {kj}), filled with uniform density
     * scaled to the table's mass: its inertia about the origin of {kj} and about its own centre
     * of mass, by the divergence theorem ({@link TriangleMesh#secondMoments()}). The meshes are
     * simplified outlines, not the CAD bodies the paper's numbers come from, so the test compares
     * the two readings rather than demanding equality: the table's moments Ixx, Iyy, Izz over the
     * mesh's are
     * <pre>
     *   link   about the origin          about the centre of mass   worst |ln ratio|, origin / com
     *   1      1.236  1.075  1.107        2.979  1.723  2.093         0.212 / 1.092
     *   2      0.961  1.008  1.026        0.961  3.135  3.258         0.040 / 1.181
     *   3      1.649  0.979  0.968        1.649  5.092  5.185         0.500 / 1.646
     * </pre>
     * (Ixx of links 2 and 3 does not tell the readings apart: their centres of mass lie on the x
     * axis.) The origin reading is 5.2, 30 and 3.3 times closer in the worst log ratio. Link 1's
     * product, the only large one, has the mesh's sign and size about the origin: +5.72e-5 in the
     * table against +5.19e-5 kg·m² for the mesh's ∫xy dm.
     */
    @Test
    void theTableAgreesWithTheMeshesAboutTheOriginNotAboutTheCentreOfMass() {
        double[][] expectOrigin = {{1.236, 1.075, 1.107}, {0.961, 1.008, 1.026}, {1.649, 0.979, 0.968}};
        double[][] expectCom = {{2.979, 1.723, 2.093}, {0.961, 3.135, 3.258}, {1.649, 5.092, 5.185}};
        double[] closer = {5.2, 30, 3.3};
        for (int j = 0; j < 3; j++) {
            LinkInertia table = HAND.finger(1).link(j);
            TriangleMesh mesh = TestMeshes.vrml(TestPaths.root().resolve("vrml/hand/finger_link" + (j + 1) + ".wrl"));
            assertTrue(mesh.isClosed(), "link " + (j + 1) + " mesh must be closed for the divergence theorem");
            double rho = table.mass() / mesh.signedVolume();
            double[] s = mesh.secondMoments();
            for (int i = 0; i < 6; i++) s[i] *= rho;
            double trace = s[0] + s[3] + s[5];
            // I = tr(Σ)·E − Σ, matrix entries (products −∫xy dm)
            double[] origin = {trace - s[0], -s[1], -s[2], trace - s[3], -s[4], trace - s[5]};
            LinkInertia meshLink = new LinkInertia(table.mass(), mesh.centroid(), origin);
            double[] aboutCom = meshLink.inertiaAboutCentreOfMass();
            double[] t = table.inertia();
            double worstOrigin = 0, worstCom = 0;
            for (int k = 0; k < 3; k++) {
                int e = DIAGONAL[k];
                double rOrigin = t[e] / origin[e], rCom = t[e] / aboutCom[e];
                assertEquals(expectOrigin[j][k], rOrigin, 6e-4, "link " + (j + 1) + " moment " + k + " about the origin");
                assertEquals(expectCom[j][k], rCom, 6e-4, "link " + (j + 1) + " moment " + k + " about the centre of mass");
                worstOrigin = Math.max(worstOrigin, Math.abs(Math.log(rOrigin)));
                worstCom = Math.max(worstCom, Math.abs(Math.log(rCom)));
            }
            assertTrue(worstOrigin < worstCom, "link " + (j + 1) + ": origin " + worstOrigin + ", centre of mass " + worstCom);
            assertEquals(closer[j], worstCom / worstOrigin, 0.05 * closer[j], "link " + (j + 1));
            if (j == 0) {
                // +∫xy dm: the table's as printed (the matrix entry negated), the mesh's Σxy
                assertEquals(5.72e-5, -t[LinkInertia.XY], 1e-12);
                assertEquals(5.19e-5, s[1], 0.01e-5);
            }
        }
    }

    /**
     * Every link, taken to its centre of mass ({@code I_c = I_o − m(|p|²E − ppᵀ)}), is a body:
     * I_c positive definite and its principal moments within the triangle inequality
     * (λ1 + λ2 > λ3 for the largest λ3). Principal moments by the closed-form eigenvalues of a
     * symmetric 3×3 matrix (Smith 1961), not by the loader's Sylvester test.
     */
    @Test
    void everyLinkIsAPhysicalBodyAboutItsCentreOfMass() {
        double[][] expect = {{2.32558e-5, 8.05965e-5, 8.82672e-5}, {4.51971e-6, 3.58568e-5, 3.68957e-5},
            {2.78585e-6, 1.21427e-5, 1.33734e-5}};
        for (int j = 0; j < 3; j++) {
            double[] lambda = eigenvalues(HAND.finger(1).link(j).inertiaAboutCentreOfMass());
            for (int k = 0; k < 3; k++) assertEquals(expect[j][k], lambda[k], 1e-5 * expect[j][k], "link " + (j + 1));
            assertTrue(lambda[0] > 0, "link " + (j + 1) + " positive definite: " + lambda[0]);
            assertTrue(lambda[0] + lambda[1] > lambda[2], "link " + (j + 1) + " triangle inequality");
            // all three fingers carry the same links
            for (int k = 2; k <= 3; k++) {
                assertEquals(HAND.finger(1).link(j).mass(), HAND.finger(k).link(j).mass());
            }
        }
    }

    /**
     * The same numbers with the products read as matrix entries (the other sign) are no body:
     * link 1 about its centre of mass has the eigenvalue −5.44e-5 kg·m², and link 3's principal
     * moments break the triangle inequality (λ1 + λ2 − λ3 = −5.68e-7 kg·m²). So the sign is not a
     * matter of taste, and the loader refuses such a tensor.
     */
    @Test
    void theOtherProductSignIsNoBody() {
        double[] link1 = eigenvalues(otherSign(HAND.finger(1).link(0)).inertiaAboutCentreOfMass());
        assertEquals(-5.44338e-5, link1[0], 1e-9);
        double[] link3 = eigenvalues(otherSign(HAND.finger(1).link(2)).inertiaAboutCentreOfMass());
        assertTrue(link3[0] > 0);
        assertEquals(-5.68372e-7, link3[0] + link3[1] - link3[2], 1e-11);
    }

    private static LinkInertia otherSign(LinkInertia l) {
        double[] t = l.inertia();
        t[LinkInertia.XY] = -t[LinkInertia.XY];
        t[LinkInertia.XZ] = -t[LinkInertia.XZ];
        t[LinkInertia.YZ] = -t[LinkInertia.YZ];
        return new LinkInertia(l.mass(), l.com(), t);
    }

    /** Eigenvalues, ascending, of the symmetric matrix (xx, xy, xz, yy, yz, zz) (Smith 1961). */
    static double[] eigenvalues(double[] a) {
        double xx = a[0], xy = a[1], xz = a[2], yy = a[3], yz = a[4], zz = a[5];
        double q = (xx + yy + zz) / 3;
        double p1 = xy * xy + xz * xz + yz * yz;
        double p2 = (xx - q) * (xx - q) + (yy - q) * (yy - q) + (zz - q) * (zz - q) + 2 * p1;
        double p = Math.sqrt(p2 / 6);
        double bxx = (xx - q) / p, byy = (yy - q) / p, bzz = (zz - q) / p, bxy = xy / p, bxz = xz / p, byz = yz / p;
        double det = bxx * (byy * bzz - byz * byz) - bxy * (bxy * bzz - byz * bxz) + bxz * (bxy * byz - byy * bxz);
        double phi = Math.acos(Math.max(-1, Math.min(1, det / 2))) / 3;
        double l3 = q + 2 * p * Math.cos(phi);
        double l1 = q + 2 * p * Math.cos(phi + 2 * Math.PI / 3);
        return new double[] {l1, 3 * q - l1 - l3, l3};
    }
}
