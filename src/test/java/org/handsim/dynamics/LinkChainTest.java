package org.handsim.dynamics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.handsim.hand.DhRow;
import org.handsim.hand.LinkInertia;
import org.junit.jupiter.api.Test;

class LinkChainTest {
    @Test
    void fingersHaveTheirActiveJoints() {
        LinkChain f1 = LinkChain.finger(1), f3 = LinkChain.finger(3);
        assertEquals(3, f1.dof());
        assertEquals(3, f3.links());
        assertEquals(2, f3.dof());
        assertFalse(f3.isActive(0));
        assertEquals(0.0, f3.fixedValue(0));
        assertEquals(1, f3.linkOfDof(0));
        assertEquals(-1, f3.dofOfLink(0));
        assertEquals(1, f3.dofOfLink(2));
    }

    /**
     * Pseudo-inertia by hand for a link with m = 2, centre (0.1, 0.2, 0.3) and the tensor
     * diag(1, 2, 4) + Ixy = 0.5 about the frame origin (Table III's reading): no parallel-axis
     * shift, Σ = ½·tr(I)·E − I = diag(2.5, 1.5, −0.5) with Σxy = −0.5, and the last column m·r̄.
     * (Not a physical body — Σzz < 0 — which does not matter for the algebra.)
     */
    @Test
    void pseudoInertiaOfATensorAboutTheOrigin() {
        LinkInertia l = new LinkInertia(2, new double[] {0.1, 0.2, 0.3}, new double[] {1, 0.5, 0, 2, 0, 4});
        double[] j = pseudo(l);
        double eps = 1e-15;
        assertEquals(2.5, j[0], eps);
        assertEquals(-0.5, j[1], eps);
        assertEquals(0.0, j[2], eps);
        assertEquals(1.5, j[5], eps);
        assertEquals(0.0, j[6], eps);
        assertEquals(-0.5, j[10], eps);
        assertEquals(0.2, j[3], eps);
        assertEquals(0.4, j[7], eps);
        assertEquals(0.6, j[11], eps);
        assertEquals(0.6, j[14], eps);
        assertEquals(2.0, j[15]);
        assertSymmetric(j);
    }

    /**
     * The same tensor given about the centre of mass ({@link LinkInertia#aboutCentreOfMass}) is
     * moved by the parallel-axis rule: Σ = Σc + m·r̄·r̄ᵀ, so Σxx = 2.5 + 0.02, Σxy = −0.5 + 0.04,
     * Σzz = −0.5 + 0.18 (FGL §3.2); and {@link LinkInertia#inertiaAboutCentreOfMass()} gives the
     * tensor back.
     */
    @Test
    void aTensorAboutTheCentreOfMassIsMovedByTheParallelAxisRule() {
        double[] ic = {1, 0.5, 0, 2, 0, 4};
        LinkInertia l = LinkInertia.aboutCentreOfMass(2, new double[] {0.1, 0.2, 0.3}, ic);
        double[] j = pseudo(l);
        double eps = 1e-15;
        assertEquals(2.52, j[0], eps);
        assertEquals(-0.46, j[1], eps);
        assertEquals(0.06, j[2], eps);
        assertEquals(1.5 + 0.08, j[5], eps);
        assertEquals(0.12, j[6], eps);
        assertEquals(-0.5 + 0.18, j[10], eps);
        assertEquals(0.2, j[3], eps);
        assertEquals(0.6, j[14], eps);
        assertSymmetric(j);
        // about the origin: Ixx = 1 + m(y² + z²) = 1.26, Ixy = 0.5 − m·x·y = 0.46
        assertEquals(1.26, l.inertia()[LinkInertia.XX], eps);
        assertEquals(0.46, l.inertia()[LinkInertia.XY], eps);
        double[] back = l.inertiaAboutCentreOfMass();
        for (int i = 0; i < 6; i++) assertEquals(ic[i], back[i], 1e-15);
    }

    private static double[] pseudo(LinkInertia l) {
        LinkChain c = LinkChain.of(new DhRow[] {new DhRow(1, 0, 0, 0)}, new LinkInertia[] {l});
        double[] j = new double[16];
        c.pseudoInertia(0, j, 0);
        return j;
    }

    private static void assertSymmetric(double[] j) {
        for (int r = 0; r < 4; r++) {
            for (int k = 0; k < 4; k++) assertEquals(j[4 * r + k], j[4 * k + r]);
        }
    }

    @Test
    void misuseNamesTheField() {
        DhRow row = new DhRow(1, 0, 0, 0);
        LinkInertia l = new LinkInertia(1, new double[3], new double[6]);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
            () -> LinkChain.of(new DhRow[] {row, row}, new LinkInertia[] {l}));
        assertTrue(e.getMessage().contains("links.length"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
            () -> LinkChain.of(new DhRow[] {new DhRow(Double.NaN, 0, 0, 0)}, new LinkInertia[] {l}));
        assertTrue(e.getMessage().contains("dh[0].a"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
            () -> LinkChain.of(new DhRow[] {row}, new LinkInertia[] {new LinkInertia(-1, new double[3], new double[6])}));
        assertTrue(e.getMessage().contains("links[0].mass"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
            () -> LinkChain.of(new DhRow[] {row}, new LinkInertia[] {l}, new boolean[] {false}, new double[1]));
        assertTrue(e.getMessage().contains("active joint"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> LinkChain.of(new DhRow[0], new LinkInertia[0]));
    }
}
