package org.handsim.vrml;

import org.handsim.mesh.MeshLimits;
import org.handsim.text.SafeText;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;

/**
 * Recursive-descent parser for the VRML97 grammar (ISO/IEC 14772-1, Annex A) producing
 * {@link VrmlNode} graphs.
 *
 * <pre>
 * vrmlScene     ::= statement*
 * statement     ::= node | PROTO ... | EXTERNPROTO ... | ROUTE id.id TO id.id
 * node          ::= [DEF id] TypeName { (fieldName value | fieldName IS id | PROTO.. | EXTERNPROTO.. | ROUTE..)* }
 *                 | USE id
 * PROTO         ::= PROTO id [ (field|exposedField|eventIn|eventOut) type id [default] ... ] { statement+ }
 * EXTERNPROTO   ::= EXTERNPROTO id [ (field|exposedField|eventIn|eventOut) type id ... ] MFString
 * </pre>
 *
 * <p><b>Types.</b> Every built-in node's interface comes from {@link Builtins}; the value of a
 * field is parsed according to its declared type, so {@code radius "abc"} or
 * {@code coordIndex [0 1 2.5]} fails at once with the position of the bad token.
 *
 * <p><b>Names.</b> DEF names live in a scope: the file, each PROTO body and each PROTO field
 * default value has its own (clause 4.6.2 and 4.8.3). A name is bound after its node is complete,
 * so {@code USE} can never create a cycle; a {@code USE} of an unbound name is an error. PROTO
 * names are visible from the point of declaration on, in nested bodies too; using a PROTO
 * inside its own body is the error "recursive PROTO".
 *
 * <p><b>PROTO expansion.</b> Instances outside PROTO bodies are expanded as soon as they are
 * parsed ({@link ProtoExpander}); instances inside a body stay as they are until the enclosing
 * PROTO is itself instantiated, because their values may still be {@code IS} references.
 *
 * <p><b>Leniency.</b> An unknown field on a known node (an X3D field, a typo) is a warning and
 * its value is skipped by shape (a bracketed list, a string, a run of numbers, a node); an
 * unknown node type is an error, since its children would be lost.
 *
 * <p><b>Limits.</b> Node nesting is limited to {@link LoadSession#maxDepth} levels (an error, never
 * a {@link StackOverflowError}); nothing is ever allocated from a count written in the file
 * (lists grow as they are read).
 */
final class VrmlParser {
    private final VrmlLexer lx;
    private final VrmlText text;
    private final LoadSession session;
    private final ProtoExpander expander;
    private Scope scope;
    private int depth;
    /** Depth of the parser that made this one read an EXTERNPROTO file (limits add up). */
    private final int baseDepth;
    /** PROTO declarations at the top level of this file, in order (for EXTERNPROTO lookup). */
    final List<ProtoDecl> topProtos = new ArrayList<>();
    /** IndexedFaceSet triangles as written (n-gon = n-2), for statistics. */
    long ifsTriangles;

    /** Names in one DEF scope, and the PROTO names visible from it. */
    static final class Scope {
        final Scope parent;
        final HashMap<String, VrmlNode> defs = new HashMap<>();
        final HashMap<String, NodeType> protos = new HashMap<>();
        /** DEF names whose node is still being parsed (a USE of one would make a cycle). */
        final java.util.HashSet<String> open = new java.util.HashSet<>();
        /** The PROTO whose body (or nested default) this scope belongs to; IS refers to it. */
        final ProtoDecl inProto;
        /** True in a PROTO body (instances are not expanded yet). */
        final boolean inBody;

        Scope(Scope parent, ProtoDecl inProto, boolean inBody) {
            this.parent = parent;
            this.inProto = inProto;
            this.inBody = inBody;
        }

        NodeType findProto(String name) {
            for (Scope s = this; s != null; s = s.parent) {
                NodeType t = s.protos.get(name);
                if (t != null) return t;
            }
            return null;
        }
    }

    VrmlParser(VrmlText text, int start, LoadSession session) {
        this.text = text;
        this.lx = new VrmlLexer(text, start);
        this.session = session;
        this.expander = new ProtoExpander(session);
        this.scope = new Scope(null, null, false);
        this.baseDepth = session.activeDepth;
    }

    /** Skips white space and comments; returns the offset of the next token. */
    private int skipPos() {
        lx.skip();
        return lx.pos;
    }

    /** Parses the whole file; returns the top-level nodes (expanded, unresolved instances dropped). */
    List<VrmlNode> parseScene() {
        List<VrmlNode> out = new ArrayList<>();
        while (!lx.atEnd()) {
            int c = lx.skip();
            if (c == '}' || c == ']') throw lx.error("unexpected '" + (char) c + "' (unbalanced brackets)");
            statement(out, true);
        }
        return out;
    }

    /** The DEF names bound at the top level of the file. */
    HashMap<String, VrmlNode> topDefs() {
        return scope.defs;
    }

    private void statement(List<VrmlNode> out, boolean top) {
        if (lx.atWord("PROTO")) {
            proto(top);
        } else if (lx.atWord("EXTERNPROTO")) {
            externProto(top);
        } else if (lx.atWord("ROUTE")) {
            route();
        } else {
            VrmlNode n = node();
            if (n != null) out.add(n);
        }
    }

    // ------------------------------------------------------------------ nodes

    /** node ::= [DEF id] Type { body } | USE id. Returns null for an unresolved EXTERNPROTO instance. */
    private VrmlNode node() {
        int start = skipPos();
        if (!lx.atIdentifier()) {
            int c = lx.skip();
            if (c == '{' || c == '[') throw lx.error("expected a node type name before '" + (char) c + "'");
            throw lx.error("expected a node, found " + lx.describe());
        }
        String word = lx.identifier("a node");
        if (++session.nodes > MeshLimits.MAX_NODES) {
            throw text.error(start, "more than " + MeshLimits.MAX_NODES + " nodes (the limit of nodes per object file)");
        }
        if (word.equals("USE")) {
            int at = lx.skip() >= 0 ? lx.pos : start;
            String name = lx.identifier("a DEF name after USE");
            VrmlNode n = scope.defs.get(name);
            if (n == null) {
                if (scope.defs.containsKey(name)) return null; // DEF of an unresolved EXTERNPROTO instance
                if (scope.open.contains(name)) {
                    throw text.error(at, "USE '" + SafeText.quote(name) + "' inside the node DEF '" + SafeText.quote(name) + "' itself (a node cannot contain itself)");
                }
                throw text.error(at, "USE '" + SafeText.quote(name) + "' before any DEF '" + SafeText.quote(name) + "' in this scope");
            }
            return n;
        }
        String defName = null;
        int defAt = start;
        if (word.equals("DEF")) {
            defName = lx.identifier("a name after DEF");
            start = skipPos();
            word = lx.identifier("a node type after DEF " + defName);
        }
        NodeType type = scope.findProto(word);
        if (type == null) type = Builtins.get(word);
        if (type == null) {
            if (word.equals("NULL")) throw text.error(start, "NULL is not allowed here (only as the value of an SFNode field)");
            if (isKeyword(word)) throw text.error(start, "keyword '" + SafeText.quote(word) + "' where a node was expected");
            throw text.error(start, "unknown node type '" + SafeText.quote(word) + "' (not a VRML97 node, and no PROTO of that name was declared before)");
        }
        if (type.proto != null && type.proto.defining) {
            throw text.error(start, "PROTO '" + SafeText.quote(word) + "' is used inside its own definition (recursive PROTO)");
        }
        if (++depth + baseDepth > session.maxDepth) {
            throw text.error(start, "nodes nested more than " + session.maxDepth + " levels deep (limit of this loader)");
        }
        VrmlNode n = new VrmlNode(type, text, start);
        n.defName = defName;
        lx.expect('{', "after node type " + word);
        boolean opened = defName != null && scope.open.add(defName);
        try {
            body(n);
        } finally {
            if (opened) scope.open.remove(defName);
        }
        depth--;
        if (!scope.inBody) countGeometry(n, start);
        VrmlNode result = n;
        if (type.proto != null && !scope.inBody) {
            result = expander.instantiate(n, depth + baseDepth);
        }
        if (defName != null) {
            if (result != null && result != n) result.defName = defName;
            scope.defs.put(defName, result);
            if (result == null) session.warn(text, defAt, "DEF '" + defName + "' names an instance of an unresolved EXTERNPROTO; USE of it is empty");
        }
        return result;
    }

    /**
     * Counts a parsed Shape and the triangles of a geometry node against {@link MeshLimits} as
     * the file is read (PROTO bodies are counted when instantiated, by the expansion's own limit):
     * IndexedFaceSet polygons as written, primitives as {@link Primitives} tessellates them.
     */
    private void countGeometry(VrmlNode n, int at) {
        long t;
        int d = session.divisions;
        switch (n.type.name) {
            case "Shape":
                if (++session.shapes > MeshLimits.MAX_SHAPES) {
                    throw text.error(at, "more than " + MeshLimits.MAX_SHAPES + " Shape nodes (the limit of shapes per object file)");
                }
                return;
            case "Box": t = 12; break;
            case "Sphere": t = 2L * d * Math.max(1, Math.max(2, d / 2) - 1); break;
            case "Cylinder": t = 4L * d; break;
            case "Cone": t = 2L * d; break;
            case "IndexedFaceSet": t = n.values[n.type.indexOf("coordIndex")] instanceof int[] ? countPolygonTriangles((int[]) n.values[n.type.indexOf("coordIndex")]) : 0; break;
            default: return;
        }
        session.triangles += t;
        if (session.triangles > MeshLimits.MAX_TRIANGLES) throw text.error(at, "more than " + MeshLimits.TRIANGLE_LIMIT);
    }

    private static boolean isKeyword(String w) {
        switch (w) {
            case "DEF": case "USE": case "IS": case "PROTO": case "EXTERNPROTO": case "ROUTE": case "TO":
            case "TRUE": case "FALSE": case "eventIn": case "eventOut": case "field": case "exposedField":
                return true;
            default:
                return false;
        }
    }

    /** Field assignments up to the closing brace (the '{' is already consumed). */
    private void body(VrmlNode n) {
        NodeType type = n.type;
        int open = lx.pos - 1;
        while (true) {
            int c = lx.skip();
            if (c == '}') {
                lx.pos++;
                return;
            }
            if (c < 0) throw text.error(open, "node " + type.name + " is not closed: missing '}' before the end of the file");
            if (!lx.atIdentifier()) {
                if (c == '{' || c == '[' || c == ']') throw lx.error("unexpected '" + (char) c + "' in the body of " + type.name + " (unbalanced brackets?)");
                throw lx.error("expected a field name or '}' in " + type.name + ", found " + lx.describe());
            }
            if (lx.atWord("PROTO")) { proto(false); continue; }
            if (lx.atWord("EXTERNPROTO")) { externProto(false); continue; }
            if (lx.atWord("ROUTE")) { route(); continue; }
            int fieldAt = lx.pos;
            String fname = lx.identifier("a field name");
            if (type.allowsDeclarations && kindOf(fname) >= 0) {
                scriptDeclaration(fname, fieldAt);
                continue;
            }
            int i = type.indexOf(fname);
            if (i < 0) {
                session.warn(text, fieldAt, "unknown field '" + SafeText.quote(fname) + "' in " + type.name + (type.proto != null ? " (PROTO)" : " (not a VRML97 field)") + "; skipped");
                skipValue();
                continue;
            }
            if (lx.atWord("IS")) {
                lx.identifier("IS");
                isBinding(n, i, fname);
                continue;
            }
            if (!type.hasValue(i) || !fname.equals(type.names[i])) {
                String kind = fname.equals(type.names[i]) ? NodeType.KIND_NAMES[type.kinds[i]] : fname.startsWith("set_") ? "eventIn" : "eventOut";
                throw text.error(fieldAt, "'" + fname + "' is an " + kind + " of " + type.name
                    + ": it takes no value here (only IS inside a PROTO)");
            }
            int valueAt = skipPos();
            n.values[i] = value(type.types[i], fname, type.name);
            n.valueOffsets[i] = valueAt;
            if (type.types[i] == FieldType.MFInt32 && fname.equals("coordIndex") && type.name.equals("IndexedFaceSet")) {
                ifsTriangles += countPolygonTriangles((int[]) n.values[i]);
            }
        }
    }

    /** Σ (n−2) over faces with n ≥ 3 vertices, a last face without -1 included. */
    static long countPolygonTriangles(int[] idx) {
        long t = 0;
        int run = 0;
        for (int v : idx) {
            if (v == -1) {
                if (run >= 3) t += run - 2;
                run = 0;
            } else {
                run++;
            }
        }
        if (run >= 3) t += run - 2;
        return t;
    }

    private void isBinding(VrmlNode n, int i, String fname) {
        int at = skipPos();
        String target = lx.identifier("an interface name after IS");
        ProtoDecl p = scope.inProto;
        if (p == null || !scope.inBody) throw text.error(at, "IS is only allowed inside a PROTO body ('" + fname + " IS " + target + "')");
        int j = p.iface.indexOf(target);
        if (j < 0) throw text.error(at, "IS '" + target + "': PROTO " + p.iface.name + " declares no field or event of that name");
        if (p.iface.types[j] != n.type.types[i]) {
            throw text.error(at, "IS type mismatch: " + n.type.name + "." + fname + " is " + n.type.types[i] + " but "
                + p.iface.name + "." + target + " is " + p.iface.types[j]);
        }
        if (n.isRefs == null) n.isRefs = new String[n.type.size()];
        n.isRefs[i] = target;
        n.valueOffsets[i] = at;
    }

    /** In a Script body: eventIn/eventOut/field declarations (parsed, then ignored). */
    private void scriptDeclaration(String kind, int at) {
        String tname = lx.identifier("a field type after " + kind);
        FieldType t = FieldType.byName(tname);
        if (t == null) throw text.error(at, "unknown field type '" + tname + "' in Script declaration");
        String name = lx.identifier("a name for the Script " + kind);
        if (lx.atWord("IS")) {
            lx.identifier("IS");
            int isAt = skipPos();
            lx.identifier("an interface name after IS");
            if (scope.inProto == null || !scope.inBody) throw text.error(isAt, "IS is only allowed inside a PROTO body");
            return;
        }
        if (kind.equals("field") || kind.equals("exposedField")) value(t, name, "Script");
    }

    // ------------------------------------------------------------------ values

    /** Parses one field value of type {@code t}. */
    Object value(FieldType t, String field, String node) {
        switch (t) {
            case SFBool: return bool(field, node);
            case SFInt32: return new int[] {lx.readInt(what(field, node, t))};
            case SFTime: return new double[] {lx.readDouble(what(field, node, t))};
            case SFFloat: case SFVec2f: case SFVec3f: case SFColor: case SFRotation: {
                String w = what(field, node, t);
                float[] v = new float[t.components];
                for (int k = 0; k < v.length; k++) v[k] = lx.readFloat(w);
                return v;
            }
            case SFString: return lx.string(what(field, node, t));
            case SFImage: return image(what(field, node, t));
            case SFNode: {
                if (lx.atWord("NULL")) {
                    lx.identifier("NULL");
                    return null;
                }
                int c = lx.skip();
                if (c == '[') throw lx.error("field '" + field + "' of " + node + " is SFNode: a single node or NULL, not a list");
                return node();
            }
            case MFInt32: return mfInt(what(field, node, t));
            case MFFloat: case MFVec2f: case MFVec3f: case MFColor: case MFRotation:
                return mfFloat(t.components, what(field, node, t));
            case MFTime: return mfTime(what(field, node, t));
            case MFString: return mfString(what(field, node, t));
            case MFNode: return mfNode(field, node);
            default: throw new AssertionError(t);
        }
    }

    private static String what(String field, String node, FieldType t) {
        return "field '" + field + "' of " + node + " (" + t + ")";
    }

    private Boolean bool(String field, String node) {
        if (lx.atWord("TRUE")) { lx.identifier("TRUE"); return Boolean.TRUE; }
        if (lx.atWord("FALSE")) { lx.identifier("FALSE"); return Boolean.FALSE; }
        throw lx.error("expected TRUE or FALSE for " + what(field, node, FieldType.SFBool) + ", found " + lx.describe());
    }

    /**
     * In a list whose '[' is at {@code open}: true if an element follows, false (the ']'
     * consumed) at its end; an error if the file ends first.
     */
    private boolean listContinues(int open, String what) {
        int c = lx.skip();
        if (c == ']') {
            lx.pos++;
            return false;
        }
        if (c < 0) throw text.error(open, "list of " + what + " is not closed: missing ']' before the end of the file");
        return true;
    }

    private int[] mfInt(String what) {
        int open = skipPos();
        if (!lx.accept('[')) return new int[] {lx.readInt(what)};
        int[] a = new int[16];
        int n = 0;
        while (listContinues(open, what)) {
            if (n == a.length) a = Arrays.copyOf(a, n * 2);
            a[n++] = lx.readInt(what);
        }
        return n == a.length ? a : Arrays.copyOf(a, n);
    }

    private float[] mfFloat(int k, String what) {
        int open = skipPos();
        if (!lx.accept('[')) {
            float[] v = new float[k];
            for (int j = 0; j < k; j++) v[j] = lx.readFloat(what);
            return v;
        }
        float[] a = new float[16 * k];
        int n = 0;
        while (listContinues(open, what)) {
            if (n + k > a.length) a = Arrays.copyOf(a, a.length * 2);
            for (int j = 0; j < k; j++) a[n++] = lx.readFloat(what);
        }
        return n == a.length ? a : Arrays.copyOf(a, n);
    }

    private double[] mfTime(String what) {
        int open = skipPos();
        if (!lx.accept('[')) return new double[] {lx.readDouble(what)};
        double[] a = new double[8];
        int n = 0;
        while (listContinues(open, what)) {
            if (n == a.length) a = Arrays.copyOf(a, n * 2);
            a[n++] = lx.readDouble(what);
        }
        return Arrays.copyOf(a, n);
    }

    private String[] mfString(String what) {
        int open = skipPos();
        if (!lx.accept('[')) return new String[] {lx.string(what)};
        List<String> l = new ArrayList<>();
        while (listContinues(open, what)) {
            l.add(lx.string(what));
        }
        return l.toArray(new String[0]);
    }

    private VrmlNode[] mfNode(String field, String node) {
        int open = skipPos();
        if (!lx.accept('[')) {
            if (lx.atWord("NULL")) { lx.identifier("NULL"); return new VrmlNode[0]; }
            VrmlNode n = node();
            return n == null ? new VrmlNode[0] : new VrmlNode[] {n};
        }
        List<VrmlNode> l = new ArrayList<>();
        while (true) {
            int c = lx.skip();
            if (c == ']') { lx.pos++; break; }
            if (c < 0) throw text.error(open, "list of nodes in field '" + field + "' of " + node + " is not closed: missing ']' before the end of the file");
            if (c == '}') throw lx.error("unexpected '}' in the list of nodes of field '" + field + "' of " + node + " (missing ']'?)");
            if (lx.atWord("NULL")) { lx.identifier("NULL"); continue; }
            if (lx.atWord("PROTO") || lx.atWord("EXTERNPROTO") || lx.atWord("ROUTE")) {
                statement(l, false);
                continue;
            }
            VrmlNode n = node();
            if (n != null) l.add(n);
        }
        return l.toArray(new VrmlNode[0]);
    }

    /** SFImage: width height components, then width×height pixels (never preallocated from the claim). */
    private int[] image(String what) {
        int at = skipPos();
        int w = lx.readInt(what), h = lx.readInt(what), comp = lx.readInt(what);
        if (w < 0 || h < 0 || comp < 0 || comp > 4) throw text.error(at, "bad image header " + w + " " + h + " " + comp + " for " + what);
        long pixels = (long) w * h;
        long remaining = lx.end() - lx.pos;
        if (pixels > (remaining + 1) / 2) {
            throw text.error(at, "image claims " + w + "x" + h + " = " + pixels + " pixels but only " + remaining
                + " bytes remain in the file (" + what + ")");
        }
        int[] a = new int[(int) pixels + 3];
        a[0] = w; a[1] = h; a[2] = comp;
        for (int i = 0; i < pixels; i++) a[3 + i] = lx.readInt(what);
        return a;
    }

    /**
     * Skips the value of an unknown field by its shape: a bracketed list, a string, a run of
     * numbers, TRUE/FALSE/NULL, IS name, USE name, or a node (balanced braces). Iterative, so a
     * deeply nested unknown value cannot overflow the stack.
     */
    private void skipValue() {
        int c = lx.skip();
        if (c == '[' || (c >= 0 && lx.atIdentifier() && !lx.atWord("TRUE") && !lx.atWord("FALSE") && !lx.atWord("NULL")
            && !lx.atWord("IS") && !lx.atWord("USE"))) {
            if (c != '[') {
                // a node: [DEF name] Type { ... }
                int save = lx.pos;
                String w = lx.identifier("a value");
                if (w.equals("DEF")) {
                    lx.identifier("a name after DEF");
                    lx.identifier("a node type");
                }
                if (lx.skip() != '{') {
                    lx.pos = save; // not a node: leave the word for the next field
                    return;
                }
            }
            int open = lx.pos;
            int level = 0;
            while (true) {
                int k = lx.skip();
                if (k < 0) throw text.error(open, "value is not closed before the end of the file (unbalanced brackets)");
                if (k == '[' || k == '{') { level++; lx.pos++; }
                else if (k == ']' || k == '}') { level--; lx.pos++; if (level == 0) return; if (level < 0) throw lx.error("unbalanced brackets"); }
                else if (k == '"') lx.string("a string");
                else lx.pos++;
            }
        }
        if (c == '"') { lx.string("a string"); return; }
        if (lx.atWord("TRUE") || lx.atWord("FALSE") || lx.atWord("NULL")) { lx.identifier("a value"); return; }
        if (lx.atWord("IS") || lx.atWord("USE")) { lx.identifier("IS"); lx.identifier("a name"); return; }
        while (lx.atNumber()) lx.readDouble("a number");
    }

    // ------------------------------------------------------------------ PROTO, EXTERNPROTO, ROUTE

    private void proto(boolean top) {
        int at = lx.pos;
        lx.identifier("PROTO");
        String name = lx.identifier("a PROTO name");
        if (Builtins.get(name) != null) {
            session.warn(text, at, "PROTO '" + name + "' redefines the built-in node " + name + " in this file");
        }
        NodeType iface = interfaceOf("PROTO", name, at, true);
        ProtoDecl decl = new ProtoDecl(iface);
        iface.proto = decl;
        decl.defining = true;
        scope.protos.put(name, iface);
        lx.expect('{', "to open the body of PROTO " + name);
        int bodyAt = lx.pos - 1;
        Scope saved = scope;
        scope = new Scope(saved, decl, true);
        List<VrmlNode> body = new ArrayList<>();
        try {
            while (!lx.accept('}')) {
                if (lx.atEnd()) throw text.error(bodyAt, "body of PROTO " + name + " is not closed: missing '}' before the end of the file");
                if (lx.skip() == ']') throw lx.error("unexpected ']' in the body of PROTO " + name + " (unbalanced brackets)");
                statement(body, false);
            }
        } finally {
            scope = saved;
            decl.defining = false;
        }
        if (body.isEmpty()) throw text.error(bodyAt, "body of PROTO " + name + " has no node (clause 4.8.3 requires at least one)");
        decl.body = body;
        if (top) topProtos.add(decl);
    }

    private static int kindOf(String w) {
        for (int k = 0; k < NodeType.KIND_NAMES.length; k++) {
            if (NodeType.KIND_NAMES[k].equals(w)) return k;
        }
        return -1;
    }

    /**
     * The interface {@code [ (field|exposedField|eventIn|eventOut) type name [default] ... ]} of
     * {@code what} ("PROTO", "EXTERNPROTO", or a built-in node) named {@code name} declared at
     * {@code at}; the defaults of fields are parsed only if {@code withDefaults}, each in its
     * own DEF scope.
     */
    private NodeType interfaceOf(String what, String name, int at, boolean withDefaults) {
        lx.expect('[', "to open the interface of " + what + " " + name);
        List<String> names = new ArrayList<>();
        List<FieldType> types = new ArrayList<>();
        List<Integer> kinds = new ArrayList<>();
        List<Object> defaults = new ArrayList<>();
        while (!lx.accept(']')) {
            if (lx.atEnd()) throw text.error(at, "interface of " + what + " " + name + " is not closed: missing ']'");
            int declAt = skipPos();
            String kind = lx.identifier("field, exposedField, eventIn or eventOut");
            int k = kindOf(kind);
            if (k < 0) throw text.error(declAt, "expected field, exposedField, eventIn or eventOut in " + what + " " + name + ", found '" + kind + "'");
            String tname = lx.identifier("a field type");
            FieldType t = FieldType.byName(tname);
            if (t == null) throw text.error(declAt, "unknown field type '" + tname + "' in " + what + " " + name);
            String fname = lx.identifier("a field name");
            if (names.contains(fname)) throw text.error(declAt, what + " " + name + " declares '" + fname + "' twice");
            Object dflt = null;
            if (withDefaults && (k == NodeType.FIELD || k == NodeType.EXPOSED_FIELD)) {
                Scope saved = scope;
                scope = new Scope(saved, null, false); // a default value has its own DEF scope
                try {
                    dflt = value(t, fname, what + " " + name);
                } finally {
                    scope = saved;
                }
            }
            names.add(fname);
            types.add(t);
            kinds.add(k);
            defaults.add(dflt);
        }
        int[] kindArray = new int[kinds.size()];
        for (int i = 0; i < kindArray.length; i++) kindArray[i] = kinds.get(i);
        return new NodeType(name, names.toArray(new String[0]), types.toArray(new FieldType[0]), kindArray, defaults.toArray());
    }

    private void externProto(boolean top) {
        int at = lx.pos;
        lx.identifier("EXTERNPROTO");
        String name = lx.identifier("an EXTERNPROTO name");
        NodeType iface = interfaceOf("EXTERNPROTO", name, at, false);
        int urlAt = skipPos();
        String[] urls = mfString("the URL list of EXTERNPROTO " + name);
        ProtoDecl decl = new ProtoDecl(iface);
        decl.urls = urls;
        iface.proto = decl;
        int savedDepth = session.activeDepth;
        session.activeDepth = baseDepth + depth;
        ProtoDecl target;
        try {
            target = session.resolveExternProto(text, at, name, urls);
        } finally {
            session.activeDepth = savedDepth;
        }
        if (target != null) {
            // take the defaults and body of the definition; the instance's fields map by name
            for (int i = 0; i < iface.size(); i++) {
                int j = target.iface.indexOf(iface.names[i]);
                if (j < 0) {
                    session.warn(text, urlAt, "EXTERNPROTO " + name + " declares '" + iface.names[i] + "', which the PROTO in the file does not have");
                } else if (target.iface.types[j] != iface.types[i]) {
                    throw text.error(urlAt, "EXTERNPROTO " + name + ": '" + iface.names[i] + "' is " + iface.types[i]
                        + " here but " + target.iface.types[j] + " in the PROTO definition");
                } else {
                    iface.defaults[i] = target.iface.defaults[j];
                }
            }
            decl.body = target.body;
            decl.resolvedFrom = target;
        }
        scope.protos.put(name, iface);
        if (top) topProtos.add(decl);
    }

    private void route() {
        lx.identifier("ROUTE");
        String from = lx.identifier("a node name after ROUTE");
        lx.expect('.', "between node and event in ROUTE");
        lx.identifier("an eventOut name");
        if (!lx.atWord("TO")) throw lx.error("expected TO in ROUTE " + from + ", found " + lx.describe());
        lx.identifier("TO");
        lx.identifier("a node name after TO");
        lx.expect('.', "between node and event in ROUTE");
        lx.identifier("an eventIn name");
    }

    /** Parses the interface text of the built-in nodes ({@link Builtins}): {@code Name [ decls ]*}. */
    static List<NodeType> parseInterfaces(String spec) {
        byte[] b = spec.getBytes(java.nio.charset.StandardCharsets.UTF_8);
        VrmlText t = new VrmlText("<builtins>", b);
        VrmlParser p = new VrmlParser(t, 0, new LoadSession());
        List<NodeType> out = new ArrayList<>();
        while (!p.lx.atEnd()) {
            int at = p.skipPos();
            out.add(p.interfaceOf("built-in node", p.lx.identifier("a node name"), at, true));
        }
        return out;
    }
}
