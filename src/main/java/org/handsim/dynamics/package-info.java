/**
 * Finger dynamics, paper Section II.C: the inverse dynamic model of eq (8),
 * {@code τk = Dk(Θk)·Θ̈k + Hk(Θk, Θ̇k) + Ck(Θk)}, its inversion for the accelerations, and the
 * integrators that step it in time.
 *
 * <h2>Map</h2>
 * <ul>
 *   <li>{@link org.handsim.dynamics.LinkChain} — a serial chain as data (DH rows, Table III
 *       mass properties, fixed joints such as finger 3's spread); built from the hand
 *       description or by hand for tests.</li>
 *   <li>{@link org.handsim.dynamics.ChainDynamics} — τ, D, H, C and the energies of one chain.
 *       Three implementations:
 *       {@link org.handsim.dynamics.LagrangeEuler} (the reference, Fu–Gonzalez–Lee §3.2, the
 *       algorithm the paper names), {@link org.handsim.dynamics.NewtonEuler} (the independent
 *       cross-check, FGL §3.3), and {@link org.handsim.dynamics.ClosedFormFinger} (closed-form
 *       expressions generated from the Lagrange–Euler formulas by
 *       {@code tools/dynamics/gen_barrett_closed_form.py}: the simulator's fast path).
 *       LagrangeEuler also gives the Coriolis matrix N and Ḋ.</li>
 *   <li>{@link org.handsim.dynamics.HandDynamics} — the three fingers, in the hand's
 *       three-joint layout.</li>
 *   <li>{@link org.handsim.dynamics.ForwardDynamics} — {@code Θ̈ = D⁻¹(τ − H − C)} by Cholesky.</li>
 *   <li>{@link org.handsim.dynamics.Integrator} over an {@link org.handsim.dynamics.Ode}:
 *       {@link org.handsim.dynamics.ExplicitEuler}, {@link org.handsim.dynamics.SemiImplicitEuler},
 *       {@link org.handsim.dynamics.RungeKutta4}, {@link org.handsim.dynamics.DormandPrince54};
 *       {@link org.handsim.dynamics.FingerDynamicsOde} is a finger as an ODE.</li>
 *   <li>{@link org.handsim.dynamics.FreeSwing} — a free finger (zero torque) integrated over a
 *       duration, each step checked by an {@link org.handsim.dynamics.EnergyGuard} (finite
 *       state, no failed step, no energy growth beyond half the energy scale), which stops a
 *       blow-up with an {@link org.handsim.dynamics.IntegrationStoppedException} naming the
 *       step, the time and the value; behind {@code handsim swing}.</li>
 * </ul>
 *
 * <h2>Conventions</h2>
 * SI units, radians; joint vectors hold the active joints of a chain; matrices are row-major
 * flat arrays; gravity is a vector in the chain's base frame ({k0} for a finger), e.g.
 * {@code (0, 0, −9.81)} m/s² when z0 points up. Hot methods are allocation-free with
 * caller-supplied outputs (docs/STYLE.md, item 3); misuse throws {@link java.lang.IllegalArgumentException}
 * naming the argument, numerical failure (D not positive definite, an integrator step that
 * cannot be taken) is a false return. Instances keep scratch: one per thread. Nothing here
 * touches files or the console.
 *
 * <h2>References</h2>
 * K. S. Fu, R. C. Gonzalez, C. S. G. Lee, <i>Robotics: Control, Sensing, Vision, and
 * Intelligence</i>, McGraw-Hill, 1987, ch. 3 (FGL); J. Y. S. Luh, M. W. Walker, R. P. C. Paul,
 * "On-line computational scheme for mechanical manipulators", ASME J. Dyn. Sys. Meas. Control
 * 102 (1980); M. W. Walker, D. E. Orin, "Efficient dynamic computer simulation of robotic
 * mechanisms", ASME J. Dyn. Sys. Meas. Control 104 (1982); R. Featherstone, <i>Rigid Body
 * Dynamics Algorithms</i>, Springer, 2008; E. Hairer, S. P. Nørsett, G. Wanner, <i>Solving
 * Ordinary Differential Equations I</i>, 2nd ed., Springer, 1993; J. R. Dormand, P. J. Prince,
 * "A family of embedded Runge–Kutta formulae", J. Comput. Appl. Math. 6 (1980).
 *
 * <p>May use {@code hand}, {@code math} and {@code process} (docs/DESIGN.md, "Modules").
 */
package org.handsim.dynamics;
