package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import org.handsim.chart.ChartExport;
import org.handsim.trace.Recorder;
import org.handsim.files.DeviceNodes;
import org.handsim.files.Folders;
import org.jfree.chart.ChartFactory;
import org.jfree.chart.JFreeChart;
import org.junit.jupiter.api.Test;

/**
 * The window's exports (screenshot, trace export, chart export; they need no display to write)
 * given a character device write into it and leave it a device; given a link to a file, they
 * replace the file and leave the link.
 */
class WindowExportsTest {
    @Test
    void exportsToADeviceLeaveItADevice() throws Exception {
        Path dir = Files.createTempDirectory("handsim-exports");
        try {
            Path nul = DeviceNodes.charDevice(dir, "null", 1, 3);
            assumeTrue(nul != null, "mknod needs root (CI runs as root)");
            HandSimWindow.writePng(new BufferedImage(8, 8, BufferedImage.TYPE_INT_RGB), nul);
            assertTrue(DeviceNodes.isCharDevice(nul));
            Recorder r = new Recorder();
            r.beginRow(0);
            r.writeCsv(nul);
            assertTrue(DeviceNodes.isCharDevice(nul));
            JFreeChart chart = ChartFactory.createXYLineChart("t", "x", "y", null);
            ChartExport.writeSvg(chart, nul, 100, 80);
            ChartExport.writePng(chart, nul, 100, 80);
            assertTrue(DeviceNodes.isCharDevice(nul));
            Path real = dir.resolve("shot.png"), link = dir.resolve("link.png");
            Files.writeString(real, "old");
            Files.createSymbolicLink(link, Path.of("shot.png"));
            HandSimWindow.writePng(new BufferedImage(8, 8, BufferedImage.TYPE_INT_RGB), link);
            assertTrue(Files.isSymbolicLink(link));
            assertEquals((byte) 0x89, Files.readAllBytes(real)[0], "a PNG now");
            assertEquals(3, dir.toFile().list().length, "no temporary file left");
        } finally {
            Folders.deleteTree(dir);
        }
    }
}
