package org.handsim.hand;

/**
 * Mass properties of one link (paper Table III), expressed in the link's own DH frame {kj}:
 * mass in kg, centre of mass {@code com} in metres, inertia tensor about the centre of mass
 * with axes parallel to {kj}, in kg·m², as the symmetric matrix entries
 * {@code (Ixx, Ixy, Ixz, Iyy, Iyz, Izz)} (DESIGN.md, "Conventions").
 */
public record LinkInertia(double mass, double[] com, double[] inertia) {
    /** Index of Ixx, Ixy, Ixz, Iyy, Iyz, Izz in {@link #inertia()}. */
    public static final int XX = 0, XY = 1, XZ = 2, YY = 3, YZ = 4, ZZ = 5;

    public LinkInertia {
        com = com.clone();
        inertia = inertia.clone();
    }

    @Override
    public double[] com() { return com.clone(); }

    @Override
    public double[] inertia() { return inertia.clone(); }
}
