package org.handsim.chart;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
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
 * image's {@code int[]}, each row gets the filter Sub or Up (whichever leaves the smaller sum of
 * absolute bytes, the usual heuristic of the PNG specification, 12.8), and zlib deflates them.
 * The decoded pixels are exactly the image's.
 */
public final class PngEncoder {
    private static final byte[] SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    /** zlib level: charts are mostly flat colour, so the fast levels lose little (about 10 %). */
    static final int LEVEL = 4;

    private PngEncoder() {}

    /** The PNG file of an image of type {@code TYPE_INT_ARGB} or {@code TYPE_INT_RGB} (others are converted first). */
    public static byte[] encode(BufferedImage image) {
        BufferedImage img = image;
        if (img.getType() != BufferedImage.TYPE_INT_ARGB && img.getType() != BufferedImage.TYPE_INT_RGB) {
            img = new BufferedImage(image.getWidth(), image.getHeight(), BufferedImage.TYPE_INT_ARGB);
            java.awt.Graphics2D g = img.createGraphics();
            g.drawImage(image, 0, 0, null);
            g.dispose();
        }
        int w = img.getWidth(), h = img.getHeight();
        int[] px = ((DataBufferInt) img.getRaster().getDataBuffer()).getData();
        boolean alpha = false;
        if (img.getType() == BufferedImage.TYPE_INT_ARGB) {
            for (int p : px) {
                if (p >>> 24 != 0xff) {
                    alpha = true;
                    break;
                }
            }
        }
        int bpp = alpha ? 4 : 3;
        int stride = w * bpp;
        byte[] prev = new byte[stride], cur = new byte[stride], sub = new byte[stride + 1], up = new byte[stride + 1];
        sub[0] = 1;
        up[0] = 2;
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
                int o = y * w;
                for (int x = 0, i = 0; x < w; x++) {
                    int p = px[o + x];
                    cur[i++] = (byte) (p >> 16);
                    cur[i++] = (byte) (p >> 8);
                    cur[i++] = (byte) p;
                    if (alpha) cur[i++] = (byte) (p >>> 24);
                }
                long sumSub = 0, sumUp = 0;
                for (int i = 0; i < stride; i++) {
                    byte s = (byte) (cur[i] - (i >= bpp ? cur[i - bpp] : 0));
                    byte u = (byte) (cur[i] - prev[i]);
                    sub[i + 1] = s;
                    up[i + 1] = u;
                    sumSub += Math.abs(s);
                    sumUp += Math.abs(u);
                }
                z.setInput(sumUp <= sumSub ? up : sub);
                while (!z.needsInput()) {
                    int n = z.deflate(buf);
                    idat.write(buf, 0, n);
                }
                byte[] t = prev;
                prev = cur;
                cur = t;
            }
            z.finish();
            while (!z.finished()) {
                int n = z.deflate(buf);
                idat.write(buf, 0, n);
            }
        } finally {
            z.end();
        }
        byte[] data = idat.toByteArray();
        chunk(out, "IDAT", data, data.length);
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
