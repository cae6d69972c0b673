package org.handsim.scenario;

import org.handsim.body.MassProperties;
import org.handsim.text.JsonObject;

/**
 * The scenario's free object (DESIGN.md decision 7): {@code "object": {"free": true, ...}}. Its
 * mass is {@code mass_kg} or the mesh's volume times {@code density_kg_m3} (one of them); its
 * inertia (3×3 about the centre of mass, object axes, kg·m²) and centre of mass (object frame,
 * m) are given or, by default, those of the solid the closed mesh bounds; its velocity and
 * angular velocity (world frame, of the centre of mass) are those at release; it is held at its
 * pose until {@code release_s} (0: free from the start).
 *
 * @param massKg               the mass, or NaN when the density gives it
 * @param densityKgM3          the density, or NaN when the mass is given
 * @param inertiaKgM2          9 values row-major, or null (from the mesh)
 * @param comM                 3 values, or null (from the mesh)
 * @param velocityMS           3 values, world, m/s
 * @param angularVelocityRadS  3 values, world, rad/s
 * @param releaseS             ≥ 0, s
 */
public record FreeObject(double massKg, double densityKgM3, double[] inertiaKgM2, double[] comM, double[] velocityMS,
                         double[] angularVelocityRadS, double releaseS) {
    /** The fields that belong to a free object, in {@code object}. */
    static final String[] FIELDS = {"free", "mass_kg", "density_kg_m3", "inertia_kg_m2", "com_m", "velocity_m_s",
        "angular_velocity_rad_s", "release_s"};

    /** @return true when the mass properties come from the mesh (all of them, or the inertia and centre) */
    public boolean fromMesh() { return inertiaKgM2 == null; }

    /**
     * Reads the free object from the scenario's {@code object}; null when it is not free. A
     * free object's field on an object that is not free, both a mass and a density, neither, or
     * a value that is no body is an error naming the field.
     */
    static FreeObject parse(JsonObject o) {
        boolean free = o.bool("free", false);
        if (!free) {
            for (String f : FIELDS) {
                if (!f.equals("free") && o.has(f)) throw o.error(f, "belongs to a free object: add \"free\": true, or remove it");
            }
            return null;
        }
        boolean mass = o.has("mass_kg"), density = o.has("density_kg_m3");
        if (mass && density) throw o.error("density_kg_m3", "give mass_kg or density_kg_m3, not both");
        if (!mass && !density) throw o.error("free", "a free object needs its mass: add \"mass_kg\" or \"density_kg_m3\"");
        double m = mass ? o.positive("mass_kg") : Double.NaN;
        double rho = density ? o.positive("density_kg_m3") : Double.NaN;
        double[] inertia = o.has("inertia_kg_m2") ? matrix3(o, "inertia_kg_m2") : null;
        if (inertia != null) {
            try {
                MassProperties.checkInertia(inertia);
            } catch (IllegalArgumentException e) {
                throw o.error("inertia_kg_m2", e.getMessage().replaceFirst("^inertia_kg_m2 ", ""));
            }
            if (!mass) throw o.error("inertia_kg_m2", "given with density_kg_m3: give mass_kg with it (an inertia fits one mass)");
        }
        double[] com = o.has("com_m") ? o.numbers("com_m", 3) : null;
        if (com != null && inertia == null) {
            throw o.error("com_m", "given without inertia_kg_m2: the mesh's inertia is about its own centre; give both or neither");
        }
        if (inertia != null && com == null) {
            throw o.error("inertia_kg_m2", "given without com_m: the inertia is about the centre of mass; give both or neither");
        }
        double[] v = o.has("velocity_m_s") ? o.numbers("velocity_m_s", 3) : new double[3];
        double[] w = o.has("angular_velocity_rad_s") ? o.numbers("angular_velocity_rad_s", 3) : new double[3];
        double release = o.has("release_s") ? o.nonNegative("release_s") : 0;
        return new FreeObject(m, rho, inertia, com, v, w, release);
    }

    /** Adds this free object's fields to {@code object}'s JSON, as {@link #parse} reads them. */
    void toJson(java.util.Map<String, Object> o) {
        o.put("free", true);
        if (!Double.isNaN(massKg)) o.put("mass_kg", massKg);
        else o.put("density_kg_m3", densityKgM3);
        if (inertiaKgM2 != null) {
            o.put("inertia_kg_m2", java.util.List.of(java.util.Arrays.copyOfRange(inertiaKgM2, 0, 3),
                java.util.Arrays.copyOfRange(inertiaKgM2, 3, 6), java.util.Arrays.copyOfRange(inertiaKgM2, 6, 9)));
            o.put("com_m", comM.clone());
        }
        o.put("velocity_m_s", velocityMS.clone());
        o.put("angular_velocity_rad_s", angularVelocityRadS.clone());
        o.put("release_s", releaseS);
    }

    /** A 3×3 matrix given as three rows of three numbers: 9 values row-major. */
    private static double[] matrix3(JsonObject o, String field) {
        java.util.List<Object> rows = o.list(field);
        if (rows.size() != 3) throw o.error(field, "must be 3 rows of 3 numbers, got " + rows.size() + " rows");
        double[] out = new double[9];
        for (int i = 0; i < 3; i++) {
            if (!(rows.get(i) instanceof java.util.List<?> row) || row.size() != 3) {
                throw o.error(field + "[" + i + "]", "must be a row of 3 numbers");
            }
            for (int j = 0; j < 3; j++) {
                Object x = row.get(j);
                if (!(x instanceof Double d) || !Double.isFinite(d)) {
                    throw o.error(field + "[" + i + "][" + j + "]", "must be a finite number, got " + x);
                }
                out[3 * i + j] = d;
            }
        }
        return out;
    }
}
