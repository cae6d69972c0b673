package org.handsim.chart;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.math.BigDecimal;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import javax.imageio.ImageIO;
import org.handsim.cli.ChildJvm;
import org.junit.jupiter.api.Test;

/** The chart files: our PNG encoder against ImageIO's decoder, the SVG coordinates, and a set whose drawing fails. */
class ChartOutputTest {
    /** Every pixel decodes as it was encoded: opaque images as RGB, others with alpha (ImageIO as the independent reader). */
    @Test
    void pngDecodesToTheSamePixels() throws Exception {
        Random rnd = new Random(345);
        for (int type : new int[] {BufferedImage.TYPE_INT_RGB, BufferedImage.TYPE_INT_ARGB}) {
            for (boolean translucent : new boolean[] {false, true}) {
                if (translucent && type == BufferedImage.TYPE_INT_RGB) continue;
                BufferedImage img = new BufferedImage(37, 23, type);
                for (int y = 0; y < 23; y++) {
                    for (int x = 0; x < 37; x++) {
                        int a = translucent ? rnd.nextInt(256) : 255;
                        img.setRGB(x, y, a << 24 | rnd.nextInt(1 << 24));
                    }
                }
                BufferedImage back = ImageIO.read(new ByteArrayInputStream(PngEncoder.encode(img)));
                assertEquals(translucent, back.getColorModel().hasAlpha(), "alpha channel only when needed");
                int[] want = img.getRGB(0, 0, 37, 23, null, 0, 37), got = back.getRGB(0, 0, 37, 23, null, 0, 37);
                if (type == BufferedImage.TYPE_INT_RGB) for (int i = 0; i < want.length; i++) want[i] |= 0xff000000;
                assertArrayEquals(want, got, "type " + type + (translucent ? " translucent" : ""));
            }
        }
    }

    /**
     * SVG coordinates: within 0.005 (plus the rounding of x·100) of the exact value of x, at most
     * two decimals, no trailing zeros, no "-0" (the exact decimal expansion of x, by BigDecimal,
     * as the reference); and the worked cases.
     */
    @Test
    void svgCoordinatesToHundredths() {
        assertEquals("0", ChartExport.hundredths(-0.004));
        assertEquals("12.5", ChartExport.hundredths(12.5));
        assertEquals("-12.5", ChartExport.hundredths(-12.5));
        assertEquals("300", ChartExport.hundredths(300.0));
        assertEquals("1.07", ChartExport.hundredths(1.0749));
        Random rnd = new Random(345);
        for (int i = 0; i < 20_000; i++) {
            double x = (rnd.nextDouble() - 0.5) * Math.pow(10, rnd.nextInt(10) - 3);
            String text = ChartExport.hundredths(x);
            BigDecimal got = new BigDecimal(text);
            assertTrue(got.scale() <= 2 && (got.signum() == 0 ? text.equals("0") : got.stripTrailingZeros().toPlainString().equals(text)), text);
            double off = got.subtract(new BigDecimal(x)).abs().doubleValue();
            assertTrue(off <= 0.005 + 1e-13 * Math.abs(x), "x = " + x + " written " + text);
        }
    }

    /** A chart that cannot be drawn: no file of the set is written, the reason and remedy name the cause. */
    @Test
    void aSetThatCannotDrawWritesNothing() throws Exception {
        Path dir = Files.createTempDirectory("handsim-charts");
        try {
            ChartSet set = ChartSet.start(PaperCharts::warmUp);
            set.add(dir.resolve("good"), 300, 200, PaperCharts::warmUp);
            set.add(dir.resolve("bad"), 300, 200, () -> {
                throw new UnsatisfiedLinkError("/jdk/lib/libfontmanager.so: libharfbuzz.so.0: cannot open shared object file");
            });
            String reason = set.finish();
            assertEquals("UnsatisfiedLinkError: /jdk/lib/libfontmanager.so: libharfbuzz.so.0: cannot open shared object file", reason);
            assertTrue(ChartSet.remedy(set.failure()).contains("apt-get install"), ChartSet.remedy(set.failure()));
            try (var s = Files.list(dir)) {
                assertFalse(s.findAny().isPresent(), "nothing written");
            }
            ChartSet ok = ChartSet.start(null);
            ok.add(dir.resolve("good"), 300, 200, PaperCharts::warmUp);
            assertNull(ok.finish());
            assertTrue(Files.size(dir.resolve("good.png")) > 1000 && Files.readString(dir.resolve("good.svg")).contains("<svg"));
            assertTrue(ChartSet.remedy(new IllegalStateException("x")).contains("bug"));
        } finally {
            ChildJvm.deleteTree(dir);
        }
    }
}
