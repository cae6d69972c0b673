package org.handsim.vrml;

import java.io.IOException;
import java.net.URLDecoder;
import java.nio.charset.StandardCharsets;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import org.jogamp.java3d.loaders.Loader;

/**
 * State of one {@code load} call: options and limits, the warnings collected so far, the files
 * read (each parsed once, even when Inlined or EXTERNPROTO'd several times), and the URL policy.
 *
 * <h2>URL policy (Inline, EXTERNPROTO, ImageTexture)</h2>
 * A URL is accepted only if it is a relative reference to a local file that, resolved against
 * the folder of the file that names it, lies inside the <em>allowed folder</em>: the folder of
 * the top-level file unless the caller chose another ({@link VrmlLoader#allowFolder}). Refused,
 * with the reason in the message: any scheme ({@code http:}, {@code https:}, {@code ftp:},
 * {@code urn:}, {@code file:}, ...), absolute paths (including {@code C:\...}), and paths whose
 * {@code ..} or symbolic links lead outside the allowed folder. Nothing is ever fetched from the
 * network.
 */
final class LoadSession {
    /** Deepest node nesting accepted (parser, PROTO expansion and scene building). */
    int maxDepth = 1000;
    /** Most nodes that PROTO expansion may create in one load. */
    long maxExpandedNodes = 2_000_000;
    long expandedNodes;
    /** Most points one generated geometry (Extrusion, ElevationGrid) may have. */
    long maxGeneratedPoints = 20_000_000;
    /** Nesting depth of the parser(s) that are currently running (EXTERNPROTO files nest). */
    int activeDepth;
    /** Most files open at once in an Inline/EXTERNPROTO chain. */
    static final int MAX_FILE_NESTING = 32;

    int divisions = 32;
    boolean normals = true;
    int lodLevel = 0;
    int flags = Loader.LOAD_ALL;
    /** Real path of the folder that URLs may reach; null: no relative URL can be resolved. */
    Path sandbox;

    final List<String> warnings = new ArrayList<>();
    final Map<Path, ParsedFile> parsed = new HashMap<>();
    private final ArrayDeque<Path> parsing = new ArrayDeque<>();
    final List<String> files = new ArrayList<>();
    long ifsTriangles;
    /** Nodes parsed, Shape nodes parsed and triangles described so far in this load (mesh.MeshLimits). */
    long nodes, shapes, triangles;

    /** A parsed file. */
    record ParsedFile(VrmlText text, List<VrmlNode> roots, Map<String, VrmlNode> defs, List<ProtoDecl> protos) {}

    /** A URL resolved to a local file. */
    record Resolved(Path real, String display, String fragment) {}

    private final java.util.Set<String> warned = new java.util.HashSet<>();

    /** Adds a warning (the same line twice, e.g. from every instance of a PROTO, is kept once). */
    void warn(VrmlText t, int offset, String message) {
        String w = t.warning(offset, message);
        if (warned.add(w)) warnings.add(w);
    }

    /** Parses text that is already in memory (the top-level file or a Reader). */
    ParsedFile parse(VrmlText t) {
        int start = t.checkHeader();
        VrmlParser p = new VrmlParser(t, start, this);
        List<VrmlNode> roots = p.parseScene();
        ifsTriangles += p.ifsTriangles;
        files.add(t.name);
        ParsedFile f = new ParsedFile(t, roots, p.topDefs(), p.topProtos);
        if (t.path != null) parsed.put(t.path, f);
        return f;
    }

    /**
     * Reads and parses a file named by a URL in {@code from} (cached by real path).
     *
     * @throws VrmlParseException at {@code from:offset} for a cycle or an unreadable file, or from
     *         inside the file for its own errors
     */
    ParsedFile parseFile(Resolved r, VrmlText from, int offset) {
        ParsedFile f = parsed.get(r.real());
        if (f != null) return f;
        if (parsing.contains(r.real())) {
            throw from.error(offset, "'" + r.display() + "' includes itself (EXTERNPROTO/Inline cycle)");
        }
        if (parsing.size() >= MAX_FILE_NESTING) {
            throw from.error(offset, "files nested more than " + MAX_FILE_NESTING + " levels deep through EXTERNPROTO/Inline");
        }
        VrmlText t;
        try {
            t = VrmlText.read(r.display(), r.real());
        } catch (IOException e) {
            throw from.error(offset, "cannot read '" + r.display() + "': " + e);
        }
        parsing.push(r.real());
        try {
            return parse(t);
        } finally {
            parsing.pop();
        }
    }

    private static final Pattern SCHEME = Pattern.compile("^[A-Za-z][A-Za-z0-9+.\\-]*:.*", Pattern.DOTALL);

    /**
     * Resolves {@code url} found in {@code from}.
     *
     * @return a {@link Resolved}, or a String saying why the URL is refused or not found
     */
    Object resolve(VrmlText from, String url) {
        String u = url.trim();
        String fragment = null;
        int hash = u.indexOf('#');
        if (hash >= 0) {
            fragment = u.substring(hash + 1);
            u = u.substring(0, hash);
        }
        if (u.isEmpty()) return "\"" + url + "\" names no file";
        if (u.length() >= 2 && Character.isLetter(u.charAt(0)) && u.charAt(1) == ':' && (u.length() == 2 || u.charAt(2) == '/' || u.charAt(2) == '\\')) {
            return "\"" + url + "\" refused: absolute paths are not allowed (only relative files inside " + sandboxName() + ")";
        }
        if (SCHEME.matcher(u).matches()) {
            String scheme = u.substring(0, u.indexOf(':')).toLowerCase(java.util.Locale.ROOT);
            if (scheme.equals("file")) {
                return "\"" + url + "\" refused: file: URLs are absolute; only relative files inside " + sandboxName() + " are allowed";
            }
            return "\"" + url + "\" refused: " + scheme + ": URLs are never fetched (only relative files inside " + sandboxName() + ")";
        }
        if (u.startsWith("/") || u.startsWith("\\")) {
            return "\"" + url + "\" refused: absolute paths are not allowed (only relative files inside " + sandboxName() + ")";
        }
        if (u.indexOf('%') >= 0) {
            try {
                u = URLDecoder.decode(u.replace("+", "%2B"), StandardCharsets.UTF_8);
            } catch (IllegalArgumentException e) {
                return "\"" + url + "\" has a malformed %-escape";
            }
        }
        if (sandbox == null) {
            return "\"" + url + "\" cannot be resolved: the scene was read from a stream and no folder was allowed (VrmlLoader.allowFolder)";
        }
        Path base = from.path != null ? from.path.toAbsolutePath().getParent() : sandbox;
        Path candidate;
        try {
            candidate = base.resolve(u).normalize();
        } catch (InvalidPathException e) {
            return "\"" + url + "\" is not a valid path: " + e.getMessage();
        }
        if (!candidate.startsWith(sandbox)) {
            return "\"" + url + "\" refused: it leads outside the allowed folder " + sandbox + " (\"..\" escape)";
        }
        Path real;
        try {
            real = candidate.toRealPath();
        } catch (NoSuchFileException e) {
            return "\"" + url + "\" not found (" + candidate + ")";
        } catch (IOException e) {
            return "\"" + url + "\" cannot be read: " + e;
        }
        if (!real.startsWith(sandbox)) {
            return "\"" + url + "\" refused: it resolves (through a symbolic link) outside the allowed folder " + sandbox;
        }
        String why = org.handsim.files.InputFile.problem(real);
        if (why != null) return "\"" + url + "\" " + why;
        String display;
        try {
            display = from.path != null ? Path.of(from.name).resolveSibling(u).normalize().toString() : candidate.toString();
        } catch (InvalidPathException e) {
            display = candidate.toString();
        }
        return new Resolved(real, display, fragment);
    }

    /**
     * The first of {@code urls} that {@link #resolve resolves}, or null if none does; the
     * reasons for the ones refused before it are added to {@code reasons}.
     */
    Resolved resolveFirst(VrmlText from, String[] urls, List<String> reasons) {
        for (String url : urls) {
            Object r = resolve(from, url);
            if (r instanceof Resolved) return (Resolved) r;
            reasons.add((String) r);
        }
        return null;
    }

    private String sandboxName() {
        return sandbox == null ? "the allowed folder" : sandbox.toString();
    }

    /**
     * Resolves an EXTERNPROTO: the first URL that names a local file defining the PROTO (the
     * one named by the {@code #fragment}, else the file's first PROTO). Null, with a warning,
     * if none does.
     */
    ProtoDecl resolveExternProto(VrmlText from, int offset, String name, String[] urls) {
        List<String> reasons = new ArrayList<>();
        for (String url : urls) {
            Object r = resolve(from, url);
            if (r instanceof String) {
                reasons.add((String) r);
                continue;
            }
            Resolved res = (Resolved) r;
            ParsedFile f = parseFile(res, from, offset);
            String want = res.fragment() != null && !res.fragment().isEmpty() ? res.fragment() : null;
            for (ProtoDecl d : f.protos()) {
                if (want == null || d.iface.name.equals(want)) {
                    if (d.body == null) break; // an EXTERNPROTO that is itself unresolved
                    return d;
                }
            }
            reasons.add("\"" + url + "\" defines no PROTO " + (want != null ? want : "at all"));
        }
        warn(from, offset, "EXTERNPROTO " + name + " not resolved (" + String.join("; ", reasons) + "); its instances are skipped");
        return null;
    }
}
