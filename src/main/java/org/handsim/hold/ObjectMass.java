package org.handsim.hold;

import org.handsim.body.MassProperties;
import org.handsim.mesh.TriangleMesh;

/**
 * The mass properties the hold test gives an object whose scenario holds it fixed (it is freed
 * once the fingers have closed): from a given mass or density and the mesh, else from the
 * mesh at {@link #DEFAULT_DENSITY_KG_M3}.
 *
 * <ul>
 *   <li>a closed mesh: the solid it bounds, uniform ({@link MassProperties#ofSolid},
 *       {@link MassProperties#ofSolidWithMass});</li>
 *   <li>an open mesh (a surface that bounds no solid) with a given mass: a thin shell of that
 *       mass spread evenly over its area ({@link #shell}), the one body such a mesh describes;</li>
 *   <li>an open mesh without a mass: refused — its mass cannot be known — naming the mesh and
 *       what to give.</li>
 * </ul>
 */
public final class ObjectMass {
    /**
     * The density of an object given neither mass nor density, kg/m³: water's, which is also
     * MuJoCo's default geom density (MuJoCo XML reference, {@code geom/@density}, default 1000).
     */
    public static final double DEFAULT_DENSITY_KG_M3 = 1000;

    private ObjectMass() {}

    /**
     * @param mesh      the object's mesh (its own frame, metres)
     * @param massKg    the given mass, kg, or NaN
     * @param densityKg the given density, kg/m³, or NaN (not with a mass)
     * @throws IllegalArgumentException naming the mesh or the value when no body follows
     */
    public static MassProperties of(TriangleMesh mesh, double massKg, double densityKg) {
        if (!Double.isNaN(massKg) && !Double.isNaN(densityKg)) {
            throw new IllegalArgumentException("give the object's mass or its density, not both");
        }
        if (!Double.isNaN(massKg)) {
            if (!(massKg > 0) || !Double.isFinite(massKg)) {
                throw new IllegalArgumentException("mass_kg must be a finite number above 0, got " + massKg);
            }
            try {
                return MassProperties.ofSolidWithMass(mesh, massKg);
            } catch (IllegalArgumentException open) {
                return shell(mesh, massKg);
            }
        }
        double rho = Double.isNaN(densityKg) ? DEFAULT_DENSITY_KG_M3 : densityKg;
        try {
            return MassProperties.ofSolid(mesh, rho);
        } catch (IllegalArgumentException e) {
            if (!Double.isNaN(densityKg) || e.getMessage().startsWith("density")) throw e;
            throw new IllegalArgumentException(e.getMessage().replace("give \"mass_kg\"", "its mass cannot be known at the default density"
                + " of " + (int) DEFAULT_DENSITY_KG_M3 + " kg/m³: give \"mass_kg\""), e);
        }
    }

    /**
     * A thin shell of mass m spread evenly over the mesh's triangles, its own frame: centre of
     * mass the area centroid, inertia about it from each triangle's second moment
     * {@code ∫ r rᵀ dA = A/12·(Σ_v v vᵀ + s sᵀ)}, s = a + b + c (exact for a triangle of uniform
     * density; e.g. a cube's surface of side a: I = 5/18·m a² about every axis through its centre).
     *
     * @throws IllegalArgumentException when the surface has no area, or its second moments make no
     *                                  body (every triangle on one line)
     */
    public static MassProperties shell(TriangleMesh mesh, double massKg) {
        double[] v = mesh.vertices(), ar = mesh.areas();
        int[] t = mesh.triangles();
        double area = 0, cx = 0, cy = 0, cz = 0;
        double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
        for (int i = 0; i < t.length; i += 3) {
            int a = 3 * t[i], b = 3 * t[i + 1], c = 3 * t[i + 2];
            double w = ar[i / 3];
            if (!(w > 0)) continue;
            double sx = v[a] + v[b] + v[c], sy = v[a + 1] + v[b + 1] + v[c + 1], sz = v[a + 2] + v[b + 2] + v[c + 2];
            area += w;
            cx += w * sx / 3;
            cy += w * sy / 3;
            cz += w * sz / 3;
            double k = w / 12;
            xx += k * (v[a] * v[a] + v[b] * v[b] + v[c] * v[c] + sx * sx);
            xy += k * (v[a] * v[a + 1] + v[b] * v[b + 1] + v[c] * v[c + 1] + sx * sy);
            xz += k * (v[a] * v[a + 2] + v[b] * v[b + 2] + v[c] * v[c + 2] + sx * sz);
            yy += k * (v[a + 1] * v[a + 1] + v[b + 1] * v[b + 1] + v[c + 1] * v[c + 1] + sy * sy);
            yz += k * (v[a + 1] * v[a + 2] + v[b + 1] * v[b + 2] + v[c + 1] * v[c + 2] + sy * sz);
            zz += k * (v[a + 2] * v[a + 2] + v[b + 2] * v[b + 2] + v[c + 2] * v[c + 2] + sz * sz);
        }
        if (!(area > 0)) throw new IllegalArgumentException(mesh.name() + ": the mesh has no area to spread a mass over");
        double s = massKg / area;
        double[] com = {cx / area, cy / area, cz / area};
        xx *= s; xy *= s; xz *= s; yy *= s; yz *= s; zz *= s;
        double tr = xx + yy + zz, cc = com[0] * com[0] + com[1] * com[1] + com[2] * com[2];
        double m = massKg;
        double[] in = {
            tr - xx - m * (cc - com[0] * com[0]), -xy + m * com[0] * com[1], -xz + m * com[0] * com[2],
            -xy + m * com[0] * com[1], tr - yy - m * (cc - com[1] * com[1]), -yz + m * com[1] * com[2],
            -xz + m * com[0] * com[2], -yz + m * com[1] * com[2], tr - zz - m * (cc - com[2] * com[2])};
        try {
            return MassProperties.of(massKg, com, in);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(mesh.name() + ": a shell of its surface is not a body (" + e.getMessage()
                + "); give \"inertia_kg_m2\"", e);
        }
    }
}
