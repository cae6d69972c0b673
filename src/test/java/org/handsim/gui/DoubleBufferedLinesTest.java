package org.handsim.gui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jogamp.java3d.Appearance;
import org.jogamp.java3d.BranchGroup;
import org.jogamp.java3d.GeometryArray;
import org.jogamp.java3d.LineArray;
import org.jogamp.java3d.Locale;
import org.jogamp.java3d.Shape3D;
import org.jogamp.java3d.VirtualUniverse;
import org.junit.jupiter.api.Test;

/**
 * {@link DoubleBufferedLines} in a live scene graph (a universe without a view: Java3D's
 * structure threads run, nothing renders): what is written is what the shape then draws, and
 * no write ever reaches a live geometry array — no data-changed message is ever sent, where a
 * single write to a plain live {@link LineArray} sends one (so the probe can tell).
 */
class DoubleBufferedLinesTest {
    @Test
    void writesGoToTheSpareArrayWhichTheSwapShowsAndNoLiveArrayIsEverWritten() {
        VirtualUniverse u = new VirtualUniverse();
        try {
            Locale locale = new Locale(u);
            DoubleBufferedLines lines = new DoubleBufferedLines(8, GeometryArray.COORDINATES | GeometryArray.COLOR_3, new Appearance());
            lines.shape().setCapability(Shape3D.ALLOW_GEOMETRY_READ);
            LineArray plain = new LineArray(8, GeometryArray.COORDINATES);
            plain.setCapability(GeometryArray.ALLOW_COORDINATE_WRITE);
            BranchGroup bg = new BranchGroup();
            bg.addChild(lines.shape());
            bg.addChild(new Shape3D(plain));
            locale.addBranchGraph(bg);
            assertTrue(lines.shown().isLive());
            assertFalse(lines.spare().isLive());
            assertNotSame(lines.shown(), lines.spare());

            float[] xyz = new float[24], rgb = new float[24], back = new float[24];
            for (int round = 1; round <= 200; round++) {
                LineArray g = lines.spare();
                assertFalse(g.isLive(), "round " + round + ": the array written is not live");
                int v = 2 + 2 * (round % 4);
                for (int i = 0; i < 3 * v; i++) {
                    xyz[i] = round + 0.001f * i;
                    rgb[i] = (i % 3) / 3f;
                }
                g.setCoordinates(0, xyz, 0, v);
                g.setColors(0, rgb, 0, v);
                g.setValidVertexCount(v);
                lines.swap();
                assertSame(g, lines.shown());
                assertSame(g, lines.shape().getGeometry(), "round " + round + ": the shape draws what was written");
                assertTrue(g.isLive());
                assertEquals(v, g.getValidVertexCount());
                g.getCoordinates(0, back);
                assertEquals(round + 0.001f * (3 * v - 1), back[3 * v - 1]);
            }
            assertFalse(Java3dMessages.sentDataChanged(lines.shown()), "no data-changed message from the shown array");
            assertFalse(Java3dMessages.sentDataChanged(lines.spare()), "no data-changed message from the spare array");

            assertFalse(Java3dMessages.sentDataChanged(plain), "nothing written to the plain array yet");
            plain.setCoordinates(0, xyz, 0, 2);
            assertTrue(Java3dMessages.sentDataChanged(plain), "one write to a live array sends a data-changed message");
        } finally {
            u.removeAllLocales();
        }
    }
}
