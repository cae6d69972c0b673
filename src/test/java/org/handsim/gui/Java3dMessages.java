package org.handsim.gui;

import java.lang.reflect.Field;
import org.jogamp.java3d.GeometryArray;
import org.jogamp.java3d.SceneGraphObject;

/**
 * What Java3D 1.7.2 keeps inside a geometry array, read by reflection for tests: whether a write
 * to it while it was live ever sent Java3D's threads a data-changed message (the message
 * {@code GeometryArrayRetained.sendDataChangedMessage} creates on the first such write and
 * reuses afterwards: its field {@code m}; {@link DoubleBufferedLines} says why such writes must
 * not happen).
 */
final class Java3dMessages {
    private Java3dMessages() {}

    /** True when a write to {@code g} while it was live has sent a data-changed message. */
    static boolean sentDataChanged(GeometryArray g) {
        try {
            Field retained = SceneGraphObject.class.getDeclaredField("retained");
            retained.setAccessible(true);
            Object r = retained.get(g);
            Field m = Class.forName("org.jogamp.java3d.GeometryArrayRetained").getDeclaredField("m");
            m.setAccessible(true);
            return m.get(r) != null;
        } catch (ReflectiveOperationException e) {
            throw new AssertionError("Java3D's internals changed (this probe reads 1.7.2's): " + e, e);
        }
    }
}
