package org.handsim.plan;

import org.handsim.math.SymmetricEigen3;
import org.handsim.mesh.TriangleMesh;

/**
 * The object's size and shape as the planner samples for them: its centroid, its principal axes
 * (the eigenvectors of the covariance of the solid the mesh bounds, about the centroid) ordered
 * by the object's extent along them, largest first, and those extents; and the support along any
 * direction (how far the object reaches from the centroid that way), from the vertices. All in the
 * world frame, metres.
 *
 * <p>The covariance is that of the solid ({@link TriangleMesh#secondMoments()} over the volume,
 * less c·cᵀ) when the mesh encloses a volume, else that of its vertices (an open or flat mesh).
 * Its eigen-decomposition ({@link SymmetricEigen3}: plane rotations, square roots and the four
 * operations only) gives the same bits on every JVM, so every engine samples the same trials. A
 * body of revolution has two equal eigenvalues: the axes in that plane are then whichever the
 * rotations give, the same every time.
 */
public final class ObjectFrame {
    private final double[] centroid;
    private final double[][] axes = new double[3][];
    private final double[] extents = new double[3];
    private final double[] vertices;   // world frame, minus the centroid

    /**
     * @param mesh            the object's mesh in its own frame, metres
     * @param worldFromObject 12 row-major values, world ← object
     * @param centroid        the centroid, world frame (the grasp evaluation's torque origin)
     */
    public ObjectFrame(TriangleMesh mesh, double[] worldFromObject, double[] centroid) {
        this.centroid = centroid.clone();
        double[] w = worldFromObject, v = mesh.vertices();
        vertices = new double[v.length];
        for (int i = 0; i < v.length; i += 3) {
            for (int r = 0; r < 3; r++) {
                vertices[i + r] = w[4 * r] * v[i] + w[4 * r + 1] * v[i + 1] + w[4 * r + 2] * v[i + 2] + w[4 * r + 3] - centroid[r];
            }
        }
        double[] cov = covarianceInObject(mesh);
        // to the world: R C Rᵀ
        double[] rc = new double[9], world = new double[9];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                double s = 0;
                for (int k = 0; k < 3; k++) s += w[4 * i + k] * cov[3 * k + j];
                rc[3 * i + j] = s;
            }
        }
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                double s = 0;
                for (int k = 0; k < 3; k++) s += rc[3 * i + k] * w[4 * j + k];
                world[3 * i + j] = s;
            }
        }
        double[] values = new double[3], vectors = new double[9];
        if (!SymmetricEigen3.decompose(world, values, vectors)) vectors = new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1};
        double[][] e = new double[3][];
        double[] ext = new double[3];
        for (int j = 0; j < 3; j++) {
            e[j] = new double[] {vectors[j], vectors[3 + j], vectors[6 + j]};
            ext[j] = support(e[j]) + support(new double[] {-e[j][0], -e[j][1], -e[j][2]});
        }
        Integer[] order = {0, 1, 2};
        java.util.Arrays.sort(order, (a, b) -> Double.compare(ext[b], ext[a]));   // stable: ties keep the eigen order
        for (int j = 0; j < 3; j++) {
            axes[j] = e[order[j]];
            extents[j] = ext[order[j]];
        }
    }

    /** The covariance (9 values, row-major) of the solid, or of the vertices, in the object's frame. */
    private static double[] covarianceInObject(TriangleMesh m) {
        double vol = m.signedVolume();
        double d = m.diagonal();
        double[] c = m.centroid();
        double[] s;
        if (vol > 1e-9 * d * d * d) {
            double[] q = m.secondMoments();
            s = new double[] {q[0] / vol, q[1] / vol, q[2] / vol, q[1] / vol, q[3] / vol, q[4] / vol, q[2] / vol, q[4] / vol, q[5] / vol};
        } else {
            double[] v = m.vertices();
            int n = Math.max(1, v.length / 3);
            s = new double[9];
            for (int i = 0; i < v.length; i += 3) {
                for (int a = 0; a < 3; a++) for (int b = 0; b < 3; b++) s[3 * a + b] += v[i + a] * v[i + b] / n;
            }
        }
        for (int a = 0; a < 3; a++) for (int b = 0; b < 3; b++) s[3 * a + b] -= c[a] * c[b];
        return s;
    }

    /** The centroid, world frame, metres (a new array). */
    public double[] centroid() { return centroid.clone(); }

    /** Principal axis j (0: the one the object is longest along), a unit vector in the world frame (a new array). */
    public double[] axis(int j) { return axes[j].clone(); }

    /** The object's extent along principal axis j, metres (largest first). */
    public double extent(int j) { return extents[j]; }

    /** How far the object reaches from its centroid along the unit direction u: max over vertices of (v − c)·u, metres. */
    public double support(double[] u) {
        double best = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < vertices.length; i += 3) {
            double s = vertices[i] * u[0] + vertices[i + 1] * u[1] + vertices[i + 2] * u[2];
            if (s > best) best = s;
        }
        return vertices.length == 0 ? 0 : best;
    }
}
