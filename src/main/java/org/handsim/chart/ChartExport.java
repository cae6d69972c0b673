package org.handsim.chart;

import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.handsim.util.AtomicFile;
import org.jfree.chart.JFreeChart;
import org.jfree.svg.SVGGraphics2D;

/** Writes a chart as PNG and SVG, each atomically (temporary file, then rename). */
public final class ChartExport {
    private ChartExport() {}

    /** Writes {@code base}.png and {@code base}.svg at the given size in pixels. */
    public static void write(JFreeChart chart, Path base, int width, int height) throws IOException {
        writePng(chart, Path.of(base + ".png"), width, height);
        writeSvg(chart, Path.of(base + ".svg"), width, height);
    }

    public static void writePng(JFreeChart chart, Path file, int width, int height) throws IOException {
        BufferedImage img = chart.createBufferedImage(width, height);
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ImageIO.write(img, "png", bytes);
        try (AtomicFile f = new AtomicFile(file)) {
            bytes.writeTo(f.stream());
            f.commit();
        }
    }

    public static void writeSvg(JFreeChart chart, Path file, int width, int height) throws IOException {
        SVGGraphics2D g2 = new SVGGraphics2D(width, height);
        chart.draw(g2, new Rectangle(0, 0, width, height));
        String svg = g2.getSVGDocument();
        try (AtomicFile f = new AtomicFile(file)) {
            f.stream().write(svg.getBytes(StandardCharsets.UTF_8));
            f.commit();
        }
    }
}
