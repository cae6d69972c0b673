package org.handsim.model;

import org.handsim.body.MassProperties;
import org.handsim.mesh.TriangleMesh;
import org.handsim.scenario.FreeObject;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.ScenarioException;

/**
 * A free object's mass properties (DESIGN.md decision 7) from the scenario's fields and the
 * object's mesh as the run loads it (scaled, in the object frame): given in full
 * ({@code mass_kg}, {@code inertia_kg_m2}, {@code com_m}), or those of the solid the closed mesh
 * bounds with the given mass or density. A mesh that bounds no solid — open, enclosing no
 * volume, facing inwards — is refused naming the scenario and the mesh's file, and what to add.
 */
public final class FreeObjectMass {
    private FreeObjectMass() {}

    /**
     * @param scenario a scenario whose {@link Scenario#freeObject()} is not null
     * @param mesh     the object's mesh in its own frame, metres
     * @throws ScenarioException naming the scenario's file, the field and the mesh's file
     */
    public static MassProperties of(Scenario scenario, TriangleMesh mesh) {
        FreeObject f = scenario.freeObject();
        try {
            if (!f.fromMesh()) return MassProperties.of(f.massKg(), f.comM(), f.inertiaKgM2());
            return Double.isNaN(f.massKg()) ? MassProperties.ofSolid(mesh, f.densityKgM3()) : MassProperties.ofSolidWithMass(mesh, f.massKg());
        } catch (IllegalArgumentException e) {
            throw new ScenarioException(scenario.file() + ": field object.free: " + e.getMessage(), e);
        }
    }
}
