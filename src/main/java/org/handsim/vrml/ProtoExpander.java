package org.handsim.vrml;

import java.util.IdentityHashMap;

/**
 * Expands PROTO instances (ISO/IEC 14772-1, 4.8.3): copies the PROTO body, replaces every
 * {@code IS} binding with the instance's value for that interface member (or the declared
 * default), expands nested instances met on the way, and returns the copy of the first body
 * node, which is what the instance is.
 *
 * <p>Sharing is preserved: a node USE'd twice inside the body is copied once and used twice
 * (an identity map per expansion). Values passed in through {@code IS} are not copied; they are
 * the instance's own nodes.
 *
 * <p>Two guards keep hostile files in check: the total number of nodes created by expansion in
 * one load is limited ({@link LoadSession#maxExpandedNodes}), which stops exponential PROTO
 * nesting (a PROTO using another twice, that one using a third twice, ...); and the nesting
 * depth of the expansion is limited like the parser's.
 */
final class ProtoExpander {
    private final LoadSession session;

    ProtoExpander(LoadSession session) {
        this.session = session;
    }

    /**
     * @param inst  an instance whose values contain no IS references (already resolved)
     * @param depth nesting depth of the instance
     * @return the expanded node, or null for an instance of an unresolved EXTERNPROTO
     */
    VrmlNode instantiate(VrmlNode inst, int depth) {
        ProtoDecl decl = inst.type.proto;
        ProtoDecl def = decl.definition();
        if (def.body == null) {
            if (!decl.warnedUnresolved) {
                decl.warnedUnresolved = true;
                session.warn(inst.text, inst.offset, "instance of EXTERNPROTO " + decl.iface.name
                    + " skipped: none of its URLs " + String.join(", ", quote(decl.urls)) + " could be resolved to a local file");
            }
            return null;
        }
        long size = sizeOf(def);
        if (session.expandedNodes + size > session.maxExpandedNodes) {
            throw inst.text.error(inst.offset, "PROTO expansion creates more than " + session.maxExpandedNodes
                + " nodes (an instance of " + inst.type.name + " alone expands to " + (size >= LARGE ? "over " + LARGE : String.valueOf(size))
                + "; exponentially nested PROTOs?); refused");
        }
        NodeType di = def.iface;
        Object[] actual = new Object[di.size()];
        for (int j = 0; j < actual.length; j++) {
            Object v = null;
            if (def == decl) {
                v = inst.values[j];
            } else {
                int i = inst.type.indexOf(di.names[j]);
                if (i >= 0) v = inst.values[i];
            }
            actual[j] = v != null ? v : di.defaults[j];
        }
        Cloner c = new Cloner(def, actual, inst);
        return c.copy(def.body.get(0), depth);
    }

    private static final long LARGE = Long.MAX_VALUE / 4;

    /**
     * Nodes one expansion of {@code def} creates: its body's nodes (each once, as USE inside the
     * body is copied once), where a nested instance counts as its own expansion. Values passed
     * in through IS are not copied and not counted. Computed once per declaration, before any
     * copying, so exponential nesting is refused in O(size of the declarations), not after
     * billions of copies. Saturates at {@link #LARGE}.
     */
    static long sizeOf(ProtoDecl def) {
        if (def.expandedSize >= 0) return def.expandedSize;
        long total = 0;
        IdentityHashMap<VrmlNode, Boolean> seen = new IdentityHashMap<>();
        java.util.ArrayDeque<VrmlNode> stack = new java.util.ArrayDeque<>();
        if (def.body != null && !def.body.isEmpty()) stack.push(def.body.get(0));
        while (!stack.isEmpty()) {
            VrmlNode n = stack.pop();
            if (seen.put(n, Boolean.TRUE) != null) continue;
            total = Math.min(LARGE, total + 1);
            if (n.type.proto != null) {
                ProtoDecl dd = n.type.proto.definition();
                if (dd.body != null) total = Math.min(LARGE, total + sizeOf(dd));
            }
            for (int i = 0; i < n.type.size(); i++) {
                if (n.isRefs != null && n.isRefs[i] != null) continue;
                Object v = n.values[i];
                if (v instanceof VrmlNode) stack.push((VrmlNode) v);
                else if (v instanceof VrmlNode[]) for (VrmlNode c : (VrmlNode[]) v) stack.push(c);
            }
        }
        def.expandedSize = total;
        return total;
    }

    private static String[] quote(String[] s) {
        String[] q = new String[s == null ? 0 : s.length];
        for (int i = 0; i < q.length; i++) q[i] = "\"" + s[i] + "\"";
        return q;
    }

    /** Copies one PROTO body for one instance. */
    private final class Cloner {
        final ProtoDecl def;
        final Object[] actual;
        final VrmlNode inst;
        final IdentityHashMap<VrmlNode, VrmlNode> done = new IdentityHashMap<>();

        Cloner(ProtoDecl def, Object[] actual, VrmlNode inst) {
            this.def = def;
            this.actual = actual;
            this.inst = inst;
        }

        VrmlNode copy(VrmlNode n, int depth) {
            if (done.containsKey(n)) return done.get(n);
            if (depth > session.maxDepth) {
                throw inst.text.error(inst.offset, "PROTO " + inst.type.name + " expands to nodes nested more than "
                    + session.maxDepth + " levels deep (limit of this loader)");
            }
            if (++session.expandedNodes > session.maxExpandedNodes) {
                throw inst.text.error(inst.offset, "PROTO expansion creates more than " + session.maxExpandedNodes
                    + " nodes (exponentially nested PROTOs?); refused");
            }
            VrmlNode c = new VrmlNode(n.type, n.text, n.offset);
            c.defName = n.defName;
            NodeType t = n.type;
            for (int i = 0; i < t.size(); i++) {
                c.valueOffsets[i] = n.valueOffsets[i];
                if (n.isRefs != null && n.isRefs[i] != null) {
                    int j = def.iface.indexOf(n.isRefs[i]);
                    c.values[i] = j >= 0 ? actual[j] : null;
                    continue;
                }
                Object v = n.values[i];
                if (v instanceof VrmlNode) {
                    v = copy((VrmlNode) v, depth + 1);
                } else if (v instanceof VrmlNode[]) {
                    VrmlNode[] a = (VrmlNode[]) v;
                    VrmlNode[] b = new VrmlNode[a.length];
                    int k = 0;
                    for (VrmlNode x : a) {
                        VrmlNode y = copy(x, depth + 1);
                        if (y != null) b[k++] = y;
                    }
                    v = k == b.length ? b : java.util.Arrays.copyOf(b, k);
                }
                c.values[i] = v;
            }
            VrmlNode result = c;
            if (t.proto != null) {
                result = instantiate(c, depth);
                if (result != null && c.defName != null) result.defName = c.defName;
            }
            done.put(n, result);
            return result;
        }
    }
}
