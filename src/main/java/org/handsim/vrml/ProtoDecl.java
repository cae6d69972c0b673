package org.handsim.vrml;

import java.util.List;

/**
 * A PROTO declaration: its interface (a {@link NodeType} whose defaults are the declared default
 * values) and its body, parsed once with {@code IS} references left in place. Instances are
 * expanded by {@link ProtoExpander}: the body is copied (DEF/USE sharing inside the body is kept),
 * each {@code IS} is replaced by the instance's value or the default, and the first body node
 * becomes the instance (clause 4.8.3: the type of a PROTO is the type of its first node).
 */
final class ProtoDecl {
    final NodeType iface;
    /** Body nodes; the first is the one an instance turns into. Null for an unresolved EXTERNPROTO. */
    List<VrmlNode> body;
    /** Set while the body is being parsed, to detect a PROTO instantiated inside itself. */
    boolean defining;
    /** For an unresolved EXTERNPROTO: whether its warning was already given for an instance. */
    boolean warnedUnresolved;
    /** For an EXTERNPROTO: its URL list, for messages. */
    String[] urls;
    /** For a resolved EXTERNPROTO: the PROTO definition found in the referenced file. */
    ProtoDecl resolvedFrom;
    /** Nodes one instance creates when expanded (computed once; -1: not yet). */
    long expandedSize = -1;

    /** The declaration whose body instances copy: the PROTO an EXTERNPROTO resolved to, else this. */
    ProtoDecl definition() {
        return resolvedFrom != null ? resolvedFrom : this;
    }

    ProtoDecl(NodeType iface) {
        this.iface = iface;
    }
}
