package org.handsim.scenario;

import java.nio.file.Path;
import java.util.Locale;
import org.handsim.hand.HandDescription;
import org.handsim.mesh.TriangleMesh;

/**
 * The one rule for the unit of an object file's coordinates, used by every command that reads
 * an object ({@code run}, {@code sweep}, {@code grasp}, {@code plan}, {@code mesh},
 * {@code collide}) and by the window.
 *
 * <p>A file's unit of length is not written in it. It is chosen ({@code object.units} in a
 * scenario, {@code --units} on the command line: mm, cm or m) or, by default ({@code auto}),
 * judged from the model's size: at most {@value #METRES_UP_TO} file units across is metres
 * (the hand is 0.3 m long), larger is millimetres, GraspIt!'s unit and most CAD programs'.
 * Centimetres only by choice. When the size decided, one line says so ({@link #notice}), the
 * same line everywhere but for how to choose otherwise.
 *
 * <p>Whatever the unit, an object far larger than the hand can reach ({@link #sizeWarning}) is
 * almost always a unit mistake (a millimetre file read as metres is 1000 times its size and
 * runs without a contact), so the run says so.
 */
public final class UnitRule {
    private UnitRule() {}

    /** Largest extent, in file units, of a model taken to be in metres. */
    public static final double METRES_UP_TO = 2.0;
    /**
     * How many times the hand's reach an object may measure before it is called far larger than
     * the hand's workspace: 20 × about 0.2 m is 4 m, far beyond any object the hand grasps and
     * well below a millimetre model read as metres (a 100 mm mug becomes 100 m).
     */
    public static final double FAR_LARGER = 20.0;

    /** The word for "judge by size" in {@code --units} and {@code object.units}. */
    public static final String AUTO = "auto";

    /**
     * A unit and whether the file's size chose it.
     *
     * @param units  the unit of the file's coordinates
     * @param bySize true when {@code auto} judged it from the size (then {@link #notice} says so)
     */
    public record Choice(Scenario.Units units, boolean bySize) {}

    /** The unit a model is probably in, from its size in file units (see the class comment). */
    public static Scenario.Units bySize(TriangleMesh inFileUnits) {
        return largestExtent(inFileUnits) <= METRES_UP_TO ? Scenario.Units.M : Scenario.Units.MM;
    }

    /**
     * The unit of {@code file}: {@code chosen} when not null, else judged by its size (the file is
     * loaded at scale 1, through the shared cache of {@link SceneMeshes#mesh}).
     *
     * @throws ScenarioException if the file must be loaded and cannot be
     */
    public static Choice resolve(Path file, int divisions, Scenario.Units chosen) {
        if (chosen != null) return new Choice(chosen, false);
        return new Choice(bySize(SceneMeshes.mesh(file, divisions, 1.0)), true);
    }

    /** The unit of a mesh read at scale 1: {@code chosen} when not null, else judged by its size. */
    public static Choice resolve(TriangleMesh inFileUnits, Scenario.Units chosen) {
        return chosen != null ? new Choice(chosen, false) : new Choice(bySize(inFileUnits), true);
    }

    /**
     * {@code mm}, {@code cm}, {@code m} as the unit, {@code auto} as null.
     *
     * @throws IllegalArgumentException naming the accepted words, for anything else
     */
    public static Scenario.Units parse(String text) {
        if (AUTO.equals(text)) return null;
        Scenario.Units u = Scenario.Units.of(text);
        if (u == null) throw new IllegalArgumentException("must be auto, mm, cm or m, got '" + text + "'");
        return u;
    }

    /**
     * The line that says the size chose the unit, e.g.
     * {@code handsim plan: mug_mm.stl: units mm by its size (--units to choose)}.
     *
     * @param who       the command, e.g. {@code handsim plan}
     * @param file      the object file
     * @param units     the unit its size gave
     * @param howToPick how the user chooses instead: {@code --units} or {@code object.units}
     */
    public static String notice(String who, Path file, Scenario.Units units, String howToPick) {
        return who + ": " + file.getFileName() + ": units " + units.id() + " by its size (" + howToPick + " to choose)";
    }

    /**
     * A warning when the object, in metres, is far larger than the hand's workspace (more than
     * {@link #FAR_LARGER} times the reach of a fingertip from the palm centre), or null.
     *
     * @param file     the object file, named in the warning
     * @param inMetres the object's mesh as placed (units × scale applied)
     * @param units    the unit its coordinates were read in (named in the warning)
     */
    public static String sizeWarning(Path file, TriangleMesh inMetres, Scenario.Units units) {
        double extent = largestExtent(inMetres), reach = handReach(HandDescription.barrettHand());
        if (!(extent > FAR_LARGER * reach)) return null;
        return String.format(Locale.ROOT, "the object %s is %s m across, far larger than the hand's workspace (%.2f m reach):"
            + " its coordinates were read as %s; check object.units (mm, cm or m)", file.getFileName(),
            extent >= 100 ? String.format(Locale.ROOT, "%.0f", extent) : String.format(Locale.ROOT, "%.1f", extent),
            reach, unitName(units));
    }

    /** The farthest a fingertip gets from the palm centre: finger base offset plus the three links, m. */
    public static double handReach(HandDescription h) {
        return Math.abs(h.palmAw()) + h.a1() + h.a2() + h.a3();
    }

    private static String unitName(Scenario.Units u) {
        return switch (u) {
            case MM -> "millimetres";
            case CM -> "centimetres";
            case M -> "metres";
        };
    }

    private static double largestExtent(TriangleMesh m) {
        double[][] b = m.bounds();
        return Math.max(b[1][0] - b[0][0], Math.max(b[1][1] - b[0][1], b[1][2] - b[0][2]));
    }
}
