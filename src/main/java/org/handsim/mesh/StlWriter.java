package org.handsim.mesh;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;

/**
 * Writes a triangle mesh as binary STL (the layout in {@link StlReader}): an 80-byte header that
 * does not start with "solid" (so no reader takes it for ASCII), the triangle count, and per
 * triangle its unit normal and three vertices as float32, attribute 0. Coordinates are rounded
 * to float32 (about 7 significant digits: 0.1 µm on a 1 m object), which is what the format holds;
 * {@link StlReader} reads the file back to exactly those floats.
 */
public final class StlWriter {
    private StlWriter() {}

    /**
     * Writes {@code mesh} to {@code out} (not closed), coordinates multiplied by {@code scale}
     * (e.g. 1000 to write millimetres).
     */
    public static void writeBinary(OutputStream out, TriangleMesh mesh, double scale) throws IOException {
        byte[] header = new byte[StlReader.HEADER_BYTES];
        byte[] text = ("binary STL written by HandSim (org.handsim.mesh.StlWriter): " + mesh.name())
            .getBytes(StandardCharsets.US_ASCII);
        System.arraycopy(text, 0, header, 0, Math.min(text.length, header.length));
        out.write(header);
        int nt = mesh.triangleCount();
        ByteBuffer b = ByteBuffer.allocate(4 + StlReader.RECORD_BYTES * Math.min(nt, 4096)).order(ByteOrder.LITTLE_ENDIAN);
        b.putInt(nt);
        double[] v = mesh.vertices(), n = mesh.normals();
        int[] t = mesh.triangles();
        for (int i = 0; i < nt; i++) {
            if (b.remaining() < StlReader.RECORD_BYTES) {
                out.write(b.array(), 0, b.position());
                b.clear();
            }
            for (int c = 0; c < 3; c++) b.putFloat((float) n[3 * i + c]);
            for (int k = 0; k < 3; k++) {
                int o = 3 * t[3 * i + k];
                for (int c = 0; c < 3; c++) b.putFloat((float) (v[o + c] * scale));
            }
            b.putShort((short) 0);
        }
        out.write(b.array(), 0, b.position());
    }
}
