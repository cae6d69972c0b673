package org.handsim.vrml;

import java.io.IOException;
import java.io.Reader;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import org.handsim.files.InputFile;
import org.jogamp.java3d.BranchGroup;
import org.jogamp.java3d.loaders.LoaderBase;

/**
 * HandSim's VRML97 loader for Java3D: reads a {@code .wrl} file (plain or gzip) and builds a
 * Java3D scene graph, implementing Java3D's {@link org.jogamp.java3d.loaders.Loader} interface.
 *
 * <pre>{@code
 * VrmlScene scene = new VrmlLoader().divisions(48).load(Path.of("vrml/objects/mug.wrl"));
 * scene.warnings().forEach(System.err::println);
 * BranchGroup bg = scene.getSceneGroup();
 * TriangleMesh mesh = new TessellationWalk().run(bg).merged();   // org.handsim.mesh
 * }</pre>
 *
 * <h2>Pipeline</h2>
 * <ol>
 *   <li>{@link VrmlText}: bytes (gunzipped if they start 1f 8b), header check (VRML 1.0,
 *       Inventor, X3D or no header: refused with a message saying which);</li>
 *   <li>{@link VrmlLexer} + {@link VrmlParser}: VRML97 grammar ⇒ {@link VrmlNode} graph, DEF/USE
 *       shared, PROTOs expanded ({@link ProtoExpander}), EXTERNPROTOs read from local files
 *       when possible (else a warning and their instances are skipped), ROUTEs and Scripts
 *       parsed and ignored;</li>
 *   <li>{@link SceneBuilder} + {@link GeometryBuilder} + {@link Primitives}: nodes ⇒ Java3D
 *       (Group, TransformGroup, Switch, Shape3D with IndexedTriangleArray geometry, SharedGroup
 *       + Link for USE and Inline).</li>
 * </ol>
 *
 * <h2>Errors and warnings</h2>
 * Anything that makes the file unloadable raises {@link VrmlParseException}, whose message is
 * {@code FILE:LINE:COL: message} (also for unreadable files: line 1, column 1). Sloppy but
 * usable input gives warnings, collected in {@link VrmlScene#warnings()}, never thrown.
 * Limits protect against hostile files: node nesting ({@link #maxDepth}, default 1000; no
 * recursion beyond it, so no StackOverflowError with a 1 MB thread stack), PROTO expansion
 * size, gzip expansion, and no array is ever sized from a count written in the file.
 *
 * <h2>Files the scene may reach</h2>
 * Inline, EXTERNPROTO and texture URLs must be relative paths to files inside the folder of
 * the top-level file, or inside the folder given to {@link #allowFolder}; remote URLs, absolute
 * paths and {@code ..} escapes are refused (see {@link LoadSession}).
 *
 * <p>A loader may be reused; each {@code load} is independent. Not thread-safe: use one
 * loader per thread. The Java3D classes need {@code -Dj3d.rend=noop} on a machine without a
 * display (DESIGN.md, "Headless").
 */
public final class VrmlLoader extends LoaderBase {
    private int divisions = 32;
    private int maxDepth = 1000;
    private boolean normals = true;
    private int lodLevel;
    private Path allowed;

    /** A loader that loads everything (Loader.LOAD_ALL). */
    public VrmlLoader() {
        super(LOAD_ALL);
    }

    /** A loader with Java3D's load flags (LOAD_LIGHT_NODES, LOAD_VIEW_GROUPS, ...). */
    public VrmlLoader(int flags) {
        super(flags);
    }

    /**
     * Resolution of Sphere, Cylinder and Cone: segments around the axis (default 32).
     *
     * @throws IllegalArgumentException unless 3 ≤ n ≤ 100 000
     */
    public VrmlLoader divisions(int n) {
        if (n < 3 || n > 100_000) throw new IllegalArgumentException("divisions must be in [3, 100000], got " + n);
        this.divisions = n;
        return this;
    }

    /** Current primitive resolution. */
    public int divisions() { return divisions; }

    /** Deepest node nesting accepted (default 1000). */
    public VrmlLoader maxDepth(int depth) {
        if (depth < 1) throw new IllegalArgumentException("maxDepth must be at least 1, got " + depth);
        this.maxDepth = depth;
        return this;
    }

    /** Whether the Java3D geometry gets normals (for lit rendering; default true). */
    public VrmlLoader normals(boolean on) {
        this.normals = on;
        return this;
    }

    /** Which LOD level to show: 0 (default) is the finest; larger values are clamped to the coarsest. */
    public VrmlLoader lodLevel(int level) {
        if (level < 0) throw new IllegalArgumentException("lodLevel must be >= 0, got " + level);
        this.lodLevel = level;
        return this;
    }

    /**
     * The folder whose files Inline/EXTERNPROTO/texture URLs may reach, instead of the top-level
     * file's folder. Also the base folder for relative URLs of a scene read from a Reader.
     */
    public VrmlLoader allowFolder(Path folder) {
        this.allowed = folder;
        return this;
    }

    /**
     * Loads a file.
     *
     * @throws VrmlParseException {@code FILE:LINE:COL: message} if it cannot be loaded
     */
    public VrmlScene load(Path file) {
        return onWorker(() -> loadHere(file));
    }

    /**
     * Loads a file whose bytes the caller has read (through the input gate, with its limit), so
     * the file is not read again: the same scene as {@link #load(Path)}; Inline and EXTERNPROTO
     * URLs resolve against the file's folder.
     *
     * @throws VrmlParseException {@code FILE:LINE:COL: message} if it cannot be loaded
     */
    public VrmlScene load(Path file, byte[] bytes) {
        return onWorker(() -> loadHere(file, bytes));
    }

    private VrmlScene loadHere(Path file) {
        return loadHere(file, null);
    }

    private VrmlScene loadHere(Path file, byte[] bytes) {
        String name = file.toString();
        LoadSession s = session();
        try {
            Path real = file.toRealPath();
            String why = bytes == null ? InputFile.problem(real) : null;
            if (why != null) throw new VrmlParseException(name, 1, 1, "cannot read the file: " + why);
            if (s.sandbox == null) s.sandbox = real.getParent();
            VrmlText t = bytes == null ? VrmlText.read(name, real) : VrmlText.fromBytes(name, bytes, real);
            return finish(s, s.parse(t));
        } catch (NoSuchFileException e) {
            throw new VrmlParseException(name, 1, 1, "cannot read the file: no such file");
        } catch (IOException e) {
            throw new VrmlParseException(name, 1, 1, "cannot read the file: " + e);
        }
    }

    /** Loads a file named by a path string (Loader interface). */
    @Override
    public VrmlScene load(String fileName) {
        try {
            return load(Path.of(fileName));
        } catch (InvalidPathException e) {
            throw new VrmlParseException(fileName, 1, 1, "not a valid path: " + e.getMessage());
        }
    }

    /** Loads a {@code file:} URL (Loader interface); other schemes are refused. */
    @Override
    public VrmlScene load(URL url) {
        if (!"file".equalsIgnoreCase(url.getProtocol())) {
            throw new VrmlParseException(url.toString(), 1, 1, "only file: URLs are loaded (refused " + url.getProtocol() + ":)");
        }
        try {
            return load(Path.of(url.toURI()));
        } catch (URISyntaxException | IllegalArgumentException e) {
            throw new VrmlParseException(url.toString(), 1, 1, "not a usable file URL: " + e.getMessage());
        }
    }

    /**
     * Loads VRML text from a reader (Loader interface), named {@code <reader>} in messages.
     * Relative URLs resolve against {@link #allowFolder} or {@code setBasePath}, if set.
     */
    @Override
    public VrmlScene load(Reader reader) {
        return load("<reader>", reader);
    }

    /** Loads VRML text from a reader, using {@code name} in messages. */
    public VrmlScene load(String name, Reader reader) {
        return onWorker(() -> loadHere(name, reader));
    }

    private VrmlScene loadHere(String name, Reader reader) {
        StringBuilder sb = new StringBuilder();
        char[] buf = new char[1 << 16];
        try {
            int n;
            while ((n = reader.read(buf)) > 0) {
                sb.append(buf, 0, n);
                if (sb.length() > VrmlText.MAX_BYTES) throw new VrmlParseException(name, 1, 1, "input larger than " + VrmlText.MAX_BYTES + " characters");
            }
        } catch (IOException e) {
            throw new VrmlParseException(name, 1, 1, "cannot read: " + e);
        }
        byte[] b = sb.toString().getBytes(StandardCharsets.UTF_8);
        LoadSession s = session();
        if (s.sandbox == null && getBasePath() != null) {
            try {
                s.sandbox = Path.of(getBasePath()).toRealPath();
            } catch (IOException | InvalidPathException e) {
                throw new VrmlParseException(name, 1, 1, "base path " + getBasePath() + " is not usable: " + e.getMessage());
            }
        }
        try {
            return finish(s, s.parse(VrmlText.fromBytes(name, b)));
        } catch (IOException e) {
            throw new VrmlParseException(name, 1, 1, "cannot read: " + e);
        }
    }

    /** Stack of the thread that parses and builds: enough for {@link #maxDepth} levels whatever the caller's stack. */
    private static final long WORKER_STACK = 64L << 20;

    /**
     * Runs a load on a fresh thread with a large stack and waits for it. Parsing and scene
     * building are recursive (bounded by {@link #maxDepth}); running them on a thread of known
     * stack size means the depth limit, not the caller's thread, decides what loads, and a
     * deeply nested file gives the depth-limit error, never a StackOverflowError.
     */
    private static VrmlScene onWorker(java.util.function.Supplier<VrmlScene> job) {
        Object[] result = new Object[1];
        Thread t = new Thread(null, () -> {
            try {
                result[0] = job.get();
            } catch (Throwable e) {
                result[0] = e;
            }
        }, "vrml-loader", WORKER_STACK);
        t.setDaemon(true);
        t.start();
        boolean interrupted = false;
        while (true) {
            try {
                t.join();
                break;
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) Thread.currentThread().interrupt();
        Object r = result[0];
        if (r instanceof VrmlScene) return (VrmlScene) r;
        if (r instanceof RuntimeException) {
            RuntimeException e = (RuntimeException) r;
            e.addSuppressed(new Exception("rethrown from the vrml-loader thread"));
            throw e;
        }
        if (r instanceof Error) throw (Error) r;
        throw new IllegalStateException("VRML load failed", (Throwable) r);
    }

    private LoadSession session() {
        LoadSession s = new LoadSession();
        s.divisions = divisions;
        s.maxDepth = maxDepth;
        s.normals = normals;
        s.lodLevel = lodLevel;
        s.flags = getFlags();
        if (allowed != null) {
            try {
                s.sandbox = allowed.toRealPath();
            } catch (IOException e) {
                throw new VrmlParseException(allowed.toString(), 1, 1, "allowed folder is not usable: " + e);
            }
        }
        return s;
    }

    private static VrmlScene finish(LoadSession s, LoadSession.ParsedFile top) {
        VrmlScene scene = new VrmlScene();
        BranchGroup bg = new SceneBuilder(s, scene).build(top);
        scene.setSceneGroup(bg);
        scene.finish(s.warnings, s.files, s.ifsTriangles);
        return scene;
    }
}
