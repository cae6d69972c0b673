package org.handsim.dynamics;

import java.util.Locale;

/**
 * The four integrators by name: one place that turns a name ({@code handsim swing --integrator},
 * the series of chart 4-integrators) into a fresh {@link Integrator} for a finger's state
 * y = (q, q̇).
 */
public enum IntegratorKind {
    EULER("euler", "explicit Euler"),
    SEMI_IMPLICIT("semi-implicit", "semi-implicit Euler"),
    RK4("rk4", "RK4"),
    DOPRI("dopri", "Dormand-Prince 5(4)");

    private final String cliName, label;

    IntegratorKind(String cliName, String label) {
        this.cliName = cliName;
        this.label = label;
    }

    /** The name {@code handsim swing --integrator} takes. */
    public String cliName() { return cliName; }

    /** The name in charts and messages. */
    public String label() { return label; }

    /**
     * A fresh integrator for {@code dof} joints (state length 2·dof).
     *
     * @param tolerance absolute and relative tolerance of Dormand–Prince (ignored by the others)
     */
    public Integrator create(int dof, double tolerance) {
        switch (this) {
            case EULER: return new ExplicitEuler(2 * dof);
            case SEMI_IMPLICIT: return new SemiImplicitEuler(dof);
            case RK4: return new RungeKutta4(2 * dof);
            default: return new DormandPrince54(2 * dof, tolerance, tolerance);
        }
    }

    /** The kind with this CLI name or label. */
    public static IntegratorKind named(String name) {
        for (IntegratorKind k : values()) if (k.cliName.equals(name) || k.label.equals(name)) return k;
        throw new IllegalArgumentException(String.format(Locale.ROOT, "unknown integrator '%s' (euler, semi-implicit, rk4 or dopri)", name));
    }
}
