package org.handsim.chart;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.awt.image.SinglePixelPackedSampleModel;
import java.awt.image.WritableRaster;
import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.zip.CRC32;
import java.util.zip.Deflater;

/**
 * A PNG writer for the charts' images (PNG, ISO/IEC 15948: signature, IHDR, IDAT, IEND; 8 bits a
 * channel, truecolour, with alpha only when some pixel is not opaque), in place of ImageIO's.
 *
 * <p>Why not ImageIO: on a chart's first image in a fresh JVM, ImageIO spent most of a chart's
 * time in its PNG writer (the plug-in registry scan, then {@code Raster.getPixels} row by row
 * and five trial filters per row, all running interpreted) — the largest part of
 * {@code handsim run}'s chart phase by JFR's samples. Here the pixels come straight from the
 * image's {@code int[]} and every row gets the filter None, so the work is zlib's: on a
 * 900 × 1100 Fig. 7 that was 3–5 times faster than choosing Sub or Up per row by the
 * specification's heuristic (12.8) and the file 6 % smaller (charts are mostly flat colour, which
 * deflate's matching handles by itself). The decoded pixels are exactly the image's.
 */
public final class PngEncoder {
    private static final byte[] SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    /**
     * zlib level: the fastest of zlib's levels that match greedily (1–3) gives the smallest file
     * of them. Against 4 (the first that defers matches), a paper run's Fig. 7 is 7 % larger and
     * takes about half the time, its Fig. 8 9 % larger and a third; at 6 (the default) a Fig. 7
     * is 10 % smaller and takes 2–3 times as long as at 4. The pixels are the same at every level.
     */
    static final int LEVEL = 3;

    private PngEncoder() {}

    /**
     * The PNG file of an image of type {@code TYPE_INT_ARGB} or {@code TYPE_INT_RGB} (others are
     * converted first), a sub-image ({@link BufferedImage#getSubimage}) included: its own pixels.
     */
    public static byte[] encode(BufferedImage image) {
        BufferedImage img = image;
        if (img.getType() != BufferedImage.TYPE_INT_ARGB && img.getType() != BufferedImage.TYPE_INT_RGB) {
            img = new BufferedImage(image.getWidth(), image.getHeight(), BufferedImage.TYPE_INT_ARGB);
            java.awt.Graphics2D g = img.createGraphics();
            g.drawImage(image, 0, 0, null);
            g.dispose();
        }
        int w = img.getWidth(), h = img.getHeight();
        // pixel (x, y) is px[base + y * scan + x]: a sub-image shares its parent's array, with the
        // parent's row length and an offset to its corner
        WritableRaster raster = img.getRaster();
        DataBufferInt data = (DataBufferInt) raster.getDataBuffer();
        int[] px = data.getData();
        int scan = ((SinglePixelPackedSampleModel) raster.getSampleModel()).getScanlineStride();
        int base = data.getOffset() - raster.getSampleModelTranslateY() * scan - raster.getSampleModelTranslateX();
        boolean alpha = false;
        if (img.getType() == BufferedImage.TYPE_INT_ARGB) {
            for (int y = 0; y < h && !alpha; y++) {
                for (int x = 0, o = base + y * scan; x < w; x++) {
                    if (px[o + x] >>> 24 != 0xff) {
                        alpha = true;
                        break;
                    }
                }
            }
        }
        int stride = w * (alpha ? 4 : 3);
        byte[] row = new byte[stride + 1];   // filter byte 0 (None), then the pixels
        ByteArrayOutputStream out = new ByteArrayOutputStream(64 * 1024);
        out.write(SIGNATURE, 0, SIGNATURE.length);
        byte[] ihdr = new byte[13];
        putInt(ihdr, 0, w);
        putInt(ihdr, 4, h);
        ihdr[8] = 8;                              // bits per channel
        ihdr[9] = (byte) (alpha ? 6 : 2);         // truecolour with alpha / truecolour
        chunk(out, "IHDR", ihdr, ihdr.length);
        Deflater z = new Deflater(LEVEL);
        byte[] buf = new byte[64 * 1024];
        ByteArrayOutputStream idat = new ByteArrayOutputStream(64 * 1024);
        try {
            for (int y = 0; y < h; y++) {
                int o = base + y * scan;
                for (int x = 0, i = 1; x < w; x++) {
                    int p = px[o + x];
                    row[i++] = (byte) (p >> 16);
                    row[i++] = (byte) (p >> 8);
                    row[i++] = (byte) p;
                    if (alpha) row[i++] = (byte) (p >>> 24);
                }
                z.setInput(row);
                while (!z.needsInput()) {
                    int n = z.deflate(buf);
                    idat.write(buf, 0, n);
                }
            }
            z.finish();
            while (!z.finished()) {
                int n = z.deflate(buf);
                idat.write(buf, 0, n);
            }
        } finally {
            z.end();
        }
        byte[] compressed = idat.toByteArray();
        chunk(out, "IDAT", compressed, compressed.length);
        chunk(out, "IEND", new byte[0], 0);
        return out.toByteArray();
    }

    private static void chunk(ByteArrayOutputStream out, String type, byte[] data, int n) {
        byte[] head = new byte[8];
        putInt(head, 0, n);
        byte[] t = type.getBytes(StandardCharsets.US_ASCII);
        System.arraycopy(t, 0, head, 4, 4);
        out.write(head, 0, 8);
        out.write(data, 0, n);
        CRC32 crc = new CRC32();
        crc.update(t);
        crc.update(data, 0, n);
        byte[] c = new byte[4];
        putInt(c, 0, (int) crc.getValue());
        out.write(c, 0, 4);
    }

    private static void putInt(byte[] b, int at, int v) {
        b[at] = (byte) (v >>> 24);
        b[at + 1] = (byte) (v >>> 16);
        b[at + 2] = (byte) (v >>> 8);
        b[at + 3] = (byte) v;
    }
}
