package org.handsim.chart;

import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.handsim.files.AtomicFile;
import org.jfree.chart.JFreeChart;
import org.jfree.svg.SVGGraphics2D;

/** Draws a chart as PNG and SVG bytes ({@link PngEncoder}, JFreeSVG) and writes them, each atomically (temporary file, then rename). */
public final class ChartExport {
    private ChartExport() {}

    /** A chart drawn at one size: its PNG file and its SVG document (UTF-8). */
    public record Drawn(byte[] png, byte[] svg) {}

    /** Writes {@code base}.png and {@code base}.svg at the given size in pixels. */
    public static void write(JFreeChart chart, Path base, int width, int height) throws IOException {
        write(draw(chart, width, height), base);
    }

    /** Writes {@code base}.png and {@code base}.svg of a drawn chart. */
    public static void write(Drawn d, Path base) throws IOException {
        writeBytes(Path.of(base + ".png"), d.png());
        writeBytes(Path.of(base + ".svg"), d.svg());
    }

    /** The chart drawn as PNG and as SVG (one chart object: not to be drawn from two threads at once). */
    public static Drawn draw(JFreeChart chart, int width, int height) {
        return new Drawn(png(chart, width, height), svg(chart, width, height));
    }

    public static void writePng(JFreeChart chart, Path file, int width, int height) throws IOException {
        writeBytes(file, png(chart, width, height));
    }

    public static void writeSvg(JFreeChart chart, Path file, int width, int height) throws IOException {
        writeBytes(file, svg(chart, width, height));
    }

    static byte[] png(JFreeChart chart, int width, int height) {
        BufferedImage img = chart.createBufferedImage(width, height);
        return PngEncoder.encode(img);
    }

    static byte[] svg(JFreeChart chart, int width, int height) {
        SVGGraphics2D g2 = new SVGGraphics2D(width, height);
        g2.setGeomDoubleConverter(ChartExport::hundredths);
        chart.draw(g2, new Rectangle(0, 0, width, height));
        return g2.getSVGDocument().getBytes(StandardCharsets.UTF_8);
    }

    /**
     * An SVG coordinate to 0.01 pixel, without trailing zeros ({@code 12.5}, {@code 300}): by
     * default JFreeSVG writes every coordinate with all its digits (shortest round trip), which
     * made half the time of drawing a chart's SVG and a document twice as large, for a precision
     * no one sees.
     */
    static String hundredths(double x) {
        if (!(Math.abs(x) < 1e12)) return org.jfree.svg.SVGUtils.doubleToString(x);   // huge, infinite or NaN: JFreeSVG's own
        long c = Math.round(x * 100);
        if (c == 0) return "0";
        StringBuilder sb = new StringBuilder(16);
        if (c < 0) {
            sb.append('-');
            c = -c;
        }
        sb.append(c / 100);
        int f = (int) (c % 100);
        if (f != 0) {
            sb.append('.').append((char) ('0' + f / 10));
            if (f % 10 != 0) sb.append((char) ('0' + f % 10));
        }
        return sb.toString();
    }

    private static void writeBytes(Path file, byte[] bytes) throws IOException {
        try (AtomicFile f = new AtomicFile(file)) {
            f.stream().write(bytes);
            f.commit();
        }
    }
}
