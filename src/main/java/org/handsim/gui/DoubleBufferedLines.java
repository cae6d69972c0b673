package org.handsim.gui;

import org.jogamp.java3d.Appearance;
import org.jogamp.java3d.GeometryArray;
import org.jogamp.java3d.LineArray;
import org.jogamp.java3d.Shape3D;

/**
 * A {@link Shape3D} of lines that change every frame (the contact normals, the friction cones),
 * drawn from one of two {@link LineArray}s: the caller writes the next lines into the
 * {@link #spare()} one, which is not in the live scene graph, and {@link #swap()} makes the
 * shape draw it. A live {@code LineArray} is never written.
 *
 * <p>Why: in Java3D 1.7.2 every write to a live geometry array ({@code setCoordinates},
 * {@code setColors}, {@code setValidVertexCount}, {@code updateData}) ends in
 * {@code GeometryArrayRetained.sendDataChangedMessage}, which reuses one {@code J3dMessage}
 * per geometry array without checking that Java3D's threads are done with it (its
 * {@code m[k]}; {@code TransformGroupRetained.setTransform} does check, through
 * {@code getRefcount() == 0}). The renderer's and the rendering-attributes structure's threads
 * each release the message when they have read it, and the last release clears its arguments
 * ({@code J3dMessage.decRefcount}). A write that fills the message's arguments while the last
 * reader of the previous write is releasing it has them wiped before it sends the message; the
 * rendering-attributes thread then reads a null geometry
 * ({@code RenderingAttributesStructure.processMessages}, case {@code GEOMETRY_CHANGED},
 * {@code geo.cachedChangedFrequent = val}: a NullPointerException), and the thread dies. Java3D
 * waits for it for ever afterwards: the view stops and {@code SimpleUniverse.cleanup()} never
 * returns. The window hits it rarely, when a thread is descheduled at the wrong instant on a
 * loaded machine. A geometry array that is not live sends no message at all (its writes only
 * mark its bounds for recomputation, done when it becomes live), and
 * {@link Shape3D#setGeometry} sends a new message each time; so the view writes only into the
 * spare array and swaps.
 *
 * <p>The array swapped out may still be drawn once, until the renderer learns of the swap;
 * writing it then only shows the newer lines a frame early. Event dispatch thread only (one
 * writer).
 */
final class DoubleBufferedLines {
    private final LineArray[] buffers = new LineArray[2];
    private final Shape3D shape;
    private int shown;

    /**
     * @param vertices most vertices drawn (two per line)
     * @param format   {@link GeometryArray#COORDINATES}, with {@link GeometryArray#COLOR_3} for per-vertex colours
     * @param look     the lines' appearance
     */
    DoubleBufferedLines(int vertices, int format, Appearance look) {
        for (int i = 0; i < 2; i++) {
            LineArray g = new LineArray(vertices, format);
            g.setCapability(GeometryArray.ALLOW_COORDINATE_WRITE);
            g.setCapability(GeometryArray.ALLOW_COUNT_WRITE);
            if ((format & GeometryArray.COLOR_3) != 0) g.setCapability(GeometryArray.ALLOW_COLOR_WRITE);
            g.setValidVertexCount(2);
            buffers[i] = g;
        }
        shape = new Shape3D(buffers[0], look);
        shape.setCapability(Shape3D.ALLOW_GEOMETRY_WRITE);
    }

    /** The shape to put in the scene graph. */
    Shape3D shape() { return shape; }

    /** The array to write the next lines into: not live, not drawn. */
    LineArray spare() { return buffers[1 - shown]; }

    /** The array the shape draws. */
    LineArray shown() { return buffers[shown]; }

    /** Makes the shape draw what was written into {@link #spare()}; the shown array becomes the spare. */
    void swap() {
        shown = 1 - shown;
        shape.setGeometry(buffers[shown]);
    }
}
