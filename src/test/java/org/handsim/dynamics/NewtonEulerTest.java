package org.handsim.dynamics;

/** {@link NewtonEuler} against the {@link ChainDynamics} contract, cross-checked with {@link LagrangeEuler}. */
class NewtonEulerTest extends AbstractChainDynamicsTest {
    @Override
    ChainDynamics create(LinkChain chain) {
        return new NewtonEuler(chain);
    }

    @Override
    ChainDynamics reference(LinkChain chain) {
        return new LagrangeEuler(chain);
    }
}
