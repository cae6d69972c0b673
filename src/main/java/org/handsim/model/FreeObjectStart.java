package org.handsim.model;

import org.handsim.body.BodyContacts;
import org.handsim.body.BoxMesh;
import org.handsim.body.MeshTopology;
import org.handsim.body.ProximityContacts;
import org.handsim.collision.KdopTree;
import org.handsim.mesh.TriangleMesh;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.ScenarioException;
import org.handsim.scenario.SceneMeshes;
import org.handsim.scenario.Support;
import org.handsim.text.Decimal;

/**
 * Refuses a free object that starts inside a support (DESIGN.md decision 7): its contacts with
 * each support at the start, by the step's own proximity query ({@link ProximityContacts}), must
 * not penetrate by more than {@link #TOLERANCE_M}; the error names the support, the depth and
 * where.
 */
public final class FreeObjectStart {
    /** A start penetration this shallow is a resting contact's rounding (single-precision vertices), not an overlap. */
    public static final double TOLERANCE_M = 1e-5;
    /** How deep below a support's face the query looks, m. */
    static final double DEPTH_M = 0.05;

    private FreeObjectStart() {}

    /**
     * @param scenario        a scenario with a free object
     * @param objectMesh      the object's mesh, its own frame, metres
     * @param worldFromObject the object's pose at the start (12 values, {@code RigidTransform.toArray})
     * @throws ScenarioException naming {@code supports[i]} and the depth
     */
    public static void check(Scenario scenario, TriangleMesh objectMesh, double[] worldFromObject) {
        if (scenario.supports().isEmpty()) return;
        KdopTree objectTree = KdopTree.build(objectMesh, SceneGeometry.DEFAULT_K);
        MeshTopology objectTopology = new MeshTopology(objectMesh);
        BodyContacts contacts = new BodyContacts();
        for (int i = 0; i < scenario.supports().size(); i++) {
            Support s = scenario.supports().get(i);
            TriangleMesh mesh = s.boxM() != null ? BoxMesh.of("supports[" + i + "]", s.boxM()[0], s.boxM()[1], s.boxM()[2])
                : SceneMeshes.mesh(s.file(), Scenario.DEFAULT_DIVISIONS, 1.0);
            ProximityContacts q = new ProximityContacts(KdopTree.build(mesh, SceneGeometry.DEFAULT_K), new MeshTopology(mesh), objectTree,
                objectTopology);
            contacts.clear();
            q.find(s.worldFromSupport().toArray(), worldFromObject, ProximityContacts.DEFAULT_MARGIN, DEPTH_M, 0.5, null, i, contacts);
            int deepest = -1;
            for (int c = 0; c < contacts.size(); c++) {
                if (contacts.gap(c) < -TOLERANCE_M && (deepest < 0 || contacts.gap(c) < contacts.gap(deepest))) deepest = c;
            }
            if (deepest >= 0) {
                double[] p = contacts.point(deepest, new double[3]);
                throw new ScenarioException(scenario.file() + ": field supports[" + i + "]: the object starts inside it, "
                    + Decimal.format(-contacts.gap(deepest) * 1000) + " mm deep at (" + Decimal.format(p[0]) + ", " + Decimal.format(p[1])
                    + ", " + Decimal.format(p[2]) + ") m: move the object or the support apart");
            }
        }
    }
}
