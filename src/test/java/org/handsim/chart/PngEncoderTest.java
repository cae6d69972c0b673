package org.handsim.chart;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;

/** What the PNG writer wrote decodes (by ImageIO) to the image's own pixels, a sub-image's too. */
class PngEncoderTest {
    /** A w × h image of the type whose every pixel differs (alpha 0xff unless {@code clearAt} is inside). */
    static BufferedImage image(int type, int w, int h, int clearX, int clearY) {
        BufferedImage img = new BufferedImage(w, h, type);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) img.setRGB(x, y, 0xff000000 | (x * 7 & 0xff) << 16 | (y * 11 & 0xff) << 8 | x * y & 0xff);
        }
        if (clearX >= 0) img.setRGB(clearX, clearY, 0x40102030);
        return img;
    }

    static void decodesTo(BufferedImage want, boolean alpha) throws Exception {
        BufferedImage got = ImageIO.read(new ByteArrayInputStream(PngEncoder.encode(want)));
        assertEquals(want.getWidth(), got.getWidth());
        assertEquals(want.getHeight(), got.getHeight());
        assertEquals(alpha, got.getColorModel().hasAlpha());
        for (int y = 0; y < want.getHeight(); y++) {
            for (int x = 0; x < want.getWidth(); x++) assertEquals(want.getRGB(x, y), got.getRGB(x, y), "pixel " + x + ", " + y);
        }
    }

    @Test
    void aWholeImageDecodesToItsPixels() throws Exception {
        decodesTo(image(BufferedImage.TYPE_INT_RGB, 37, 23, -1, -1), false);
        decodesTo(image(BufferedImage.TYPE_INT_ARGB, 37, 23, -1, -1), false);
        decodesTo(image(BufferedImage.TYPE_INT_ARGB, 37, 23, 3, 4), true);
    }

    /** Before: the sub-image's rows were read from the start of its parent's array, one parent row apart. */
    @Test
    void aSubImageDecodesToItsOwnPixels() throws Exception {
        decodesTo(image(BufferedImage.TYPE_INT_RGB, 40, 30, -1, -1).getSubimage(5, 7, 20, 10), false);
        // the parent's only translucent pixel lies outside the sub-image: no alpha channel
        decodesTo(image(BufferedImage.TYPE_INT_ARGB, 40, 30, 1, 1).getSubimage(5, 7, 20, 10), false);
        decodesTo(image(BufferedImage.TYPE_INT_ARGB, 40, 30, 9, 9).getSubimage(5, 7, 20, 10), true);
    }
}
