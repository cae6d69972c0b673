package org.handsim.dynamics;

import static org.handsim.dynamics.DynamicsTesting.CROSS_CHECK;
import static org.handsim.dynamics.DynamicsTesting.SEED;
import static org.handsim.dynamics.DynamicsTesting.STATES;
import static org.handsim.dynamics.DynamicsTesting.randomState;
import static org.handsim.dynamics.DynamicsTesting.relative;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.handsim.hand.DhRow;
import org.handsim.hand.LinkInertia;
import org.junit.jupiter.api.Test;

/**
 * The generated closed form ({@link BarrettFingerKernel} behind {@link ClosedFormFinger}) against
 * the {@link ChainDynamics} contract, cross-checked with the general {@link LagrangeEuler} it was
 * derived from, and with {@link NewtonEuler}.
 */
class ClosedFormFingerTest extends AbstractChainDynamicsTest {
    @Override
    ChainDynamics create(LinkChain chain) {
        return new ClosedFormFinger(chain);
    }

    @Override
    ChainDynamics reference(LinkChain chain) {
        return new LagrangeEuler(chain);
    }

    @Test
    void agreesWithNewtonEulerToo() {
        for (int k = 1; k <= 3; k++) {
            LinkChain chain = LinkChain.finger(k);
            ChainDynamics a = create(chain), b = new NewtonEuler(chain);
            Random r = new Random(SEED + 10 + k);
            double worst = 0;
            for (int s = 0; s < STATES; s++) {
                DynamicsTesting.State st = randomState(chain, r);
                worst = Math.max(worst, relative(a.inverseDynamics(st.q, st.qd, st.qdd, st.g, null),
                    b.inverseDynamics(st.q, st.qd, st.qdd, st.g, null)));
            }
            assertTrue(worst <= CROSS_CHECK, "finger " + k + ": " + worst);
        }
    }

    /**
     * Other lengths, offsets, masses and a fixed joint elsewhere: the constants follow the chain,
     * and the three algorithms still agree (each handles fixed joints its own way).
     */
    @Test
    void followsAModifiedChainOfTheSameStructure() {
        Random r = new Random(SEED);
        for (int trial = 0; trial < 20; trial++) {
            DhRow[] dh = new DhRow[3];
            LinkInertia[] links = new LinkInertia[3];
            for (int j = 0; j < 3; j++) {
                dh[j] = new DhRow(0.02 + 0.1 * r.nextDouble(), j == 0 ? Math.PI / 2 : 0, 0, r.nextDouble() - 0.5);
                double ixx = 1e-5 + 1e-4 * r.nextDouble(), iyy = 1e-5 + 1e-4 * r.nextDouble(), izz = 1e-5 + 1e-4 * r.nextDouble();
                links[j] = LinkInertia.aboutCentreOfMass(0.01 + 0.2 * r.nextDouble(),
                    new double[] {0.05 * r.nextGaussian(), 0.02 * r.nextGaussian(), 0.02 * r.nextGaussian()},
                    new double[] {ixx, 1e-6 * r.nextGaussian(), 1e-6 * r.nextGaussian(), iyy, 1e-6 * r.nextGaussian(), izz});
            }
            boolean[] active = {true, true, true};
            if (trial % 3 == 1) active[0] = false;
            if (trial % 3 == 2) active[2] = false;
            LinkChain chain = LinkChain.of(dh, links, active, new double[] {0.3, -0.2, 0.4});
            ChainDynamics a = create(chain), b = new LagrangeEuler(chain), c = new NewtonEuler(chain);
            for (int s = 0; s < 200; s++) {
                DynamicsTesting.State st = randomState(chain, r);
                double[] tb = b.inverseDynamics(st.q, st.qd, st.qdd, st.g, null);
                assertTrue(relative(a.inverseDynamics(st.q, st.qd, st.qdd, st.g, null), tb) <= CROSS_CHECK);
                assertTrue(relative(c.inverseDynamics(st.q, st.qd, st.qdd, st.g, null), tb) <= CROSS_CHECK);
                assertTrue(Math.abs(a.potentialEnergy(st.q, st.g) - b.potentialEnergy(st.q, st.g)) <= 1e-15);
            }
        }
    }

    @Test
    void refusesAChainOfAnotherStructure() {
        LinkChain f = LinkChain.finger(1);
        DhRow[] dh = {f.dh(0), new DhRow(0.07, 0.1, 0, 0), f.dh(2)};
        LinkInertia[] links = {f.link(0), f.link(1), f.link(2)};
        LinkChain other = LinkChain.of(dh, links);
        assertFalse(ClosedFormFinger.supports(other));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new ClosedFormFinger(other));
        assertTrue(e.getMessage().contains("dh[1].alpha"), e.getMessage());
        assertFalse(ClosedFormFinger.supports(LinkChain.of(new DhRow[] {f.dh(0)}, new LinkInertia[] {f.link(0)})));
        assertTrue(ClosedFormFinger.supports(f));
    }
}
