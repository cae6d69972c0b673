package org.handsim.mesh;

import java.io.IOException;
import java.io.Writer;
import org.handsim.text.Decimal;

/**
 * Writes triangle meshes as Wavefront OBJ text: one {@code o name} per mesh, {@code v x y z} per
 * vertex (Java's shortest round-trip decimal form, so reading back gives the same doubles) and
 * {@code f a b c} per triangle with 1-based indices counted over the whole file.
 */
public final class ObjWriter {
    private ObjWriter() {}

    /** Writes the meshes to {@code out} (not closed). */
    public static void write(Writer out, Iterable<TriangleMesh> meshes) throws IOException {
        out.write("# written by HandSim (org.handsim.mesh.ObjWriter), units: metres\n");
        int base = 1;
        StringBuilder sb = new StringBuilder(1 << 16);
        for (TriangleMesh m : meshes) {
            sb.append("o ").append(m.name().replaceAll("\\s+", "_")).append('\n');
            double[] v = m.vertices();
            for (int i = 0; i < v.length; i += 3) {
                Decimal.append(Decimal.append(Decimal.append(sb.append("v "), v[i]).append(' '), v[i + 1]).append(' '), v[i + 2]).append('\n');
                if (sb.length() > 60_000) { out.write(sb.toString()); sb.setLength(0); }
            }
            int[] t = m.triangles();
            for (int i = 0; i < t.length; i += 3) {
                sb.append("f ").append(t[i] + base).append(' ').append(t[i + 1] + base).append(' ').append(t[i + 2] + base).append('\n');
                if (sb.length() > 60_000) { out.write(sb.toString()); sb.setLength(0); }
            }
            base += m.vertexCount();
        }
        out.write(sb.toString());
    }
}
