package org.handsim.tradeoff;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.handsim.mesh.TriangleMesh;
import org.handsim.model.SceneGeometry;
import org.handsim.scenario.SceneMeshes;

/**
 * A contact tolerance turned into a tessellation resolution ({@code handsim run --tolerance}),
 * from chart 2's data: the committed resource {@value #RESOURCE} is the CSV of a full run of
 * {@link TessellationStudy} (regenerate: {@code handsim tradeoff --only 2}, then copy
 * {@code 2-tessellation.csv} over it; a test checks that it agrees with a recomputation).
 *
 * <p>For each divisions the table gives the worst contact-centre error relative to the radius
 * of a Sphere and of a Cylinder. The expected error of an object at divisions d is
 * {@code size × max(sphere(d), cylinder(d))}, where size is the radius of the object's bounding
 * sphere (scaled): an upper bound for the radius of any curved primitive in it, and the worse of
 * the two curves (a Cone, not measured, is covered by that bound too) — so the estimate errs on
 * the safe side. The chosen divisions is the smallest in the table whose expected error is at
 * most the tolerance; a divisions where the coarse polyhedron missed the contact in some pose is
 * never chosen. An object whose mesh is the same at the coarsest and the finest divisions (a
 * pre-tessellated IndexedFaceSet, a Box) is a fixed mesh: the tolerance cannot change it.
 */
public final class Resolution {
    /** Classpath resource (next to this class): a copy of {@code 2-tessellation.csv}. */
    public static final String RESOURCE = "tessellation-error.csv";
    /** The curved shapes whose curves bound the error. */
    static final String[] CURVED = {"sphere", "cylinder"};

    private Resolution() {}

    /** One row of the table: divisions and the worst relative centre error (+∞ where the contact was missed). */
    public record Entry(int divisions, double sphere, double cylinder) {
        /** The bound used: the worse of the two shapes. */
        public double relativeError() { return Math.max(sphere, cylinder); }
    }

    /**
     * What a tolerance chose for an object.
     *
     * @param fixedMesh     the object's mesh does not depend on divisions (nothing to choose)
     * @param triangles     triangles of the object's mesh (at the chosen divisions, or the fixed mesh)
     * @param sizeM         the object's bounding-sphere radius, m (scaled)
     * @param met           whether some divisions of the table meets the tolerance
     * @param divisions     the chosen divisions (when met), else the table's best
     * @param expectedErrorM the expected worst contact-centre error at {@code divisions}, m
     */
    public record Choice(boolean fixedMesh, int triangles, double sizeM, boolean met, int divisions, double expectedErrorM) {}

    private static final Pattern LENGTH = Pattern.compile(
        "\\s*([+-]?(?:\\d+(?:\\.\\d*)?|\\.\\d+)(?:[eE][+-]?\\d+)?)\\s*(mm|cm|um|µm|m)?\\s*");

    /**
     * Parses a length: a number with an optional unit {@code m}, {@code cm}, {@code mm},
     * {@code um}/{@code µm} (space allowed before it); no unit means metres.
     *
     * @return metres, finite and &gt; 0
     * @throws IllegalArgumentException with a one-line message naming the value
     */
    public static double parseLength(String text) {
        Matcher m = LENGTH.matcher(text == null ? "" : text);
        if (!m.matches()) {
            throw new IllegalArgumentException("'" + text + "' is not a length (e.g. 0.5mm, 0.5 mm, 0.0005m, or 1e-3 in metres)");
        }
        double v = Double.parseDouble(m.group(1));
        String unit = m.group(2) == null ? "m" : m.group(2);
        double f;
        switch (unit) {
            case "cm": f = 1e-2; break;
            case "mm": f = 1e-3; break;
            case "um": case "µm": f = 1e-6; break;
            default: f = 1;
        }
        double metres = v * f;
        if (!(metres > 0) || !Double.isFinite(metres)) throw new IllegalArgumentException("'" + text + "' must be a positive length");
        return metres;
    }

    /** The committed table, by increasing divisions. */
    public static List<Entry> table() {
        try (InputStream in = Resolution.class.getResourceAsStream(RESOURCE)) {
            if (in == null) throw new IllegalStateException("resource " + RESOURCE + " missing from the class path");
            return parse(new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8)).lines().toList(), RESOURCE);
        } catch (IOException e) {
            throw new IllegalStateException("cannot read " + RESOURCE + ": " + e, e);
        }
    }

    /** Reads the centre rows of the curved shapes from the lines of a {@code 2-tessellation.csv}. */
    static List<Entry> parse(List<String> lines, String name) {
        if (lines.isEmpty()) throw new IllegalStateException(name + ": empty");
        List<String> header = Arrays.asList(lines.get(0).split(","));
        int cSeries = column(header, "series", name), cDiv = column(header, "divisions", name),
            cErr = column(header, "centre_error_rel", name), cMissed = column(header, "missed", name);
        TreeMap<Integer, double[]> byDiv = new TreeMap<>();
        for (int i = 1; i < lines.size(); i++) {
            if (lines.get(i).isBlank()) continue;
            String[] f = lines.get(i).split(",");
            for (int s = 0; s < CURVED.length; s++) {
                if (!f[cSeries].equals(CURVED[s] + " centre")) continue;
                int d = (int) Double.parseDouble(f[cDiv]);
                double e = Double.parseDouble(f[cMissed]) > 0 ? Double.POSITIVE_INFINITY : Double.parseDouble(f[cErr]);
                double[] v = byDiv.computeIfAbsent(d, x -> new double[] {Double.NaN, Double.NaN});
                v[s] = e;
            }
        }
        List<Entry> out = new ArrayList<>();
        byDiv.forEach((d, v) -> {
            if (!Double.isNaN(v[0]) && !Double.isNaN(v[1])) out.add(new Entry(d, v[0], v[1]));
        });
        if (out.isEmpty()) throw new IllegalStateException(name + ": no rows of " + String.join(" and ", CURVED) + " centre");
        return out;
    }

    private static int column(List<String> header, String c, String name) {
        int i = header.indexOf(c);
        if (i < 0) throw new IllegalStateException(name + ": no column " + c);
        return i;
    }

    /**
     * Chooses the divisions of an object file for a tolerance (see the class comment).
     *
     * @param file      the object's VRML file
     * @param scale     the scenario's scale of it
     * @param tolerance metres, &gt; 0
     * @throws org.handsim.scenario.ScenarioException if the file cannot be loaded
     */
    public static Choice choose(Path file, double scale, double tolerance) {
        return choose(table(), file, scale, tolerance);
    }

    static Choice choose(List<Entry> table, Path file, double scale, double tolerance) {
        int coarsest = table.get(0).divisions(), finest = table.get(table.size() - 1).divisions();
        TriangleMesh fine = SceneMeshes.mesh(file, finest, scale), coarse = SceneMeshes.mesh(file, coarsest, scale);
        double size = SceneGeometry.boundingSphere(fine)[3];
        if (fine.sameTrianglesAs(coarse)) {
            return new Choice(true, fine.triangleCount(), size, true, -1, Double.NaN);
        }
        return choose(table, size, tolerance, d -> SceneMeshes.mesh(file, d, scale).triangleCount());
    }

    /** The choice for an object of bounding radius {@code size} (metres). */
    static Choice choose(List<Entry> table, double size, double tolerance, java.util.function.IntUnaryOperator triangles) {
        Entry best = null;
        for (Entry e : table) {
            if (best == null || e.relativeError() < best.relativeError()) best = e;
            if (e.relativeError() * size <= tolerance) {
                return new Choice(false, triangles.applyAsInt(e.divisions()), size, true, e.divisions(), e.relativeError() * size);
            }
        }
        return new Choice(false, triangles.applyAsInt(best.divisions()), size, false, best.divisions(), best.relativeError() * size);
    }

    /** A length for messages: millimetres with three significant digits. */
    public static String mm(double metres) {
        return String.format(Locale.ROOT, "%.3g mm", metres * 1e3);
    }
}
