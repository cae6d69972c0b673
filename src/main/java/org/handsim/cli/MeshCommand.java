package org.handsim.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.handsim.text.SafeText;
import org.handsim.mesh.MeshLimits;
import org.handsim.mesh.MeshWelder;
import org.handsim.mesh.ObjWriter;
import org.handsim.mesh.StlWriter;
import org.handsim.mesh.TriangleMesh;
import org.handsim.scenario.MeshFiles;
import org.handsim.scenario.Scenario;
import org.handsim.scenario.UnitRule;
import org.handsim.scenario.ScenarioException;
import org.handsim.files.AtomicFile;
import org.handsim.text.JsonWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code handsim mesh FILE [--units auto|mm|cm|m] [--divisions N] [--scale S] [--obj OUT.obj] [--stl OUT.stl]}: loads a
 * VRML97, OBJ or STL file as scenarios do ({@link MeshFiles}: VrmlLoader or Java3D's ObjectFile ⇒
 * BranchGroup ⇒ TessellationWalk, or the STL reader ⇒ TriangleMesh), welds coincident vertices
 * and prints one JSON line:
 *
 * <pre>{"file":..,"shapes":n,"triangles":n,"vertices":n,"degenerate":n,"area_m2":A,
 *  "volume_m3":V|null,"closed":bool,"bounds":[[xmin,ymin,zmin],[xmax,ymax,zmax]],"load_ms":t,"units":u}</pre>
 *
 * shapes = Shape3D instances with surface geometry (each USE counted; OBJ: one per group; STL: 1); triangles, vertices,
 * area, bounds: of the welded mesh; degenerate = zero-area triangles dropped (by the walk, plus
 * those whose corners the weld merged); volume: the enclosed volume if the welded mesh is closed
 * (every edge shared by exactly two oppositely oriented triangles), else null; load_ms: parse,
 * scene building and tessellation walk; units: the unit of the file's coordinates ({@link UnitRule}:
 * {@code --units}, by default judged from the size, with a notice on standard error). Warnings go to
 * standard error, one per line.
 */
@Command(name = "mesh", mixinStandardHelpOptions = true,
    description = {"Loads a VRML97, OBJ or STL file and prints its triangle mesh statistics.",
        "Formats by extension: .wrl (VRML97, also gzipped), .obj (Wavefront), .stl",
        "(ASCII or binary).",
        "Prints one JSON line (volume_m3 is null unless the mesh is closed):",
        "  {\"file\":..,\"shapes\":n,\"triangles\":n,\"vertices\":n,\"degenerate\":n,",
        "   \"area_m2\":A,\"volume_m3\":V|null,\"closed\":bool,",
        "   \"bounds\":[[xmin,ymin,zmin],[xmax,ymax,zmax]],\"load_ms\":t,\"units\":u}",
        "in metres: the file's coordinates times its unit (--units) times --scale.",
        "Coincident vertices are welded before the closed-ness test. Warnings go to",
        "standard error. Exit codes: 0 ok, 2 bad arguments, 3 file cannot be loaded",
        "(FILE:LINE:COL: message; binary STL: FILE: byte N: message)."})
public final class MeshCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "FILE", description = "VRML97 (.wrl, plain or gzip), OBJ (.obj) or STL (.stl) file")
    Path file;

    @Option(names = "--divisions", paramLabel = "N", defaultValue = "32",
        description = "VRML: segments around the axis of Sphere, Cylinder and Cone (3..100000; default ${DEFAULT-VALUE})")
    int divisions;

    @Option(names = "--scale", paramLabel = "S", defaultValue = "1",
        description = {"multiply the coordinates by S after the units (default 1;",
            "--scale alone, without --units, converts to metres by itself)"})
    double scale;

    @Option(names = "--units", paramLabel = "auto|mm|cm|m", defaultValue = "auto",
        description = {Args.UNITS_HELP_1, Args.UNITS_HELP_2, Args.UNITS_HELP_3})
    String units;

    /** Metres per file unit times --scale: what the coordinates are multiplied by. */
    private double factor = 1;

    @Option(names = "--obj", paramLabel = "OUT.obj", description = "also write the welded triangles as Wavefront OBJ")
    Path obj;

    @Option(names = "--stl", paramLabel = "OUT.stl", description = "also write the welded triangles as binary STL (float32)")
    Path stl;

    /**
     * Whether the mesh changes with --divisions: the file loaded again at other divisions gives
     * other triangles (only VRML's Sphere, Cylinder and Cone depend on them).
     */
    private boolean dependsOnDivisions(MeshFiles.Loaded r) {
        if (r.format() != MeshFiles.Format.VRML) return false;
        int other = divisions == 3 ? 4 : 3;
        TriangleMesh a = r.mesh(), b;
        try {
            b = MeshFiles.load(file, other, factor).mesh();
        } catch (RuntimeException e) {
            return true;   // cannot tell: say nothing
        }
        return !a.sameTrianglesAs(b);
    }

    @Override
    public Integer call() throws IOException {
        if (divisions < 3 || divisions > 100_000) throw CliError.usage("handsim mesh: --divisions must be in 3..100000, got " + divisions);
        String scaleWhy = MeshLimits.scaleProblem(scale);
        if (scaleWhy != null) throw CliError.usage("handsim mesh: --scale " + scaleWhy);
        Args.notTheInput(file, "FILE", Args.outputFile("--obj", obj), "--obj");
        Args.notTheInput(file, "FILE", Args.outputFile("--stl", stl), "--stl");
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Scenario.Units chosen = Args.units(units);
        // --scale alone keeps its old meaning (the whole conversion to metres): no judging by size
        if (chosen == null && spec.commandLine().getParseResult().hasMatchedOption("--scale")) chosen = Scenario.Units.M;
        long t0 = System.nanoTime();
        MeshFiles.Loaded r;
        UnitRule.Choice unit;
        try {
            r = MeshFiles.load(file, divisions, chosen != null ? chosen.metres() * scale : 1.0);
            unit = UnitRule.resolve(r.mesh(), chosen);
            factor = unit.units().metres() * scale;
            if (chosen == null && factor != 1.0) r = MeshFiles.load(file, divisions, factor);
        } catch (ScenarioException e) {
            throw new CliError(CliError.LOAD, e.getMessage(), e);
        }
        if (unit.bySize()) err.println(UnitRule.notice("handsim mesh", file, unit.units(), "--units"));
        for (String w : r.warnings()) err.println(w);
        double loadMs = (System.nanoTime() - t0) / 1e6;
        if (spec.commandLine().getParseResult().hasMatchedOption("--divisions") && !dependsOnDivisions(r)) {
            err.println("handsim mesh: --divisions has no effect: " + SafeText.escape(file.toString()) + " has no Sphere, Cylinder or Cone (a fixed mesh)");
        }
        MeshWelder welder = new MeshWelder();
        TriangleMesh mesh = welder.weld(r.mesh());
        boolean closed = mesh.isClosed();
        Map<String, Object> json = new LinkedHashMap<>();
        json.put("file", file.toString());
        json.put("shapes", r.shapes());
        json.put("triangles", mesh.triangleCount());
        json.put("vertices", mesh.vertexCount());
        json.put("degenerate", r.degenerate() + welder.lastCollapsed());
        json.put("area_m2", mesh.area());
        json.put("volume_m3", closed ? mesh.signedVolume() : null);
        json.put("closed", closed);
        json.put("bounds", mesh.bounds());
        json.put("load_ms", Math.round(loadMs * 10) / 10.0);
        json.put("units", unit.units().id());
        if (obj != null) {
            try (AtomicFile f = Args.atomicOutput("--obj", obj)) {
                ObjWriter.write(f.writer(), List.of(mesh));
                f.commit();
            }
        }
        if (stl != null) {
            try (AtomicFile f = Args.atomicOutput("--stl", stl)) {
                StlWriter.writeBinary(f.stream(), mesh, 1.0);
                f.commit();
            }
        }
        out.println(JsonWriter.write(json));
        out.flush();
        return 0;
    }
}
