package org.handsim.vrml;

import java.util.HashMap;
import java.util.Map;

/**
 * The interface of a node type: its fields and events with their types and default values. The
 * built-in VRML97 nodes are described this way ({@link Builtins}), and so is every PROTO and
 * EXTERNPROTO declaration (then {@link #proto} tells how to expand an instance).
 */
final class NodeType {
    /** Access kinds of an interface member (clause 4.7). */
    static final int FIELD = 0, EXPOSED_FIELD = 1, EVENT_IN = 2, EVENT_OUT = 3;
    static final String[] KIND_NAMES = {"field", "exposedField", "eventIn", "eventOut"};

    final String name;
    final String[] names;
    final FieldType[] types;
    final int[] kinds;
    /** Default per field (null for events and for SFNode NULL). */
    final Object[] defaults;
    private final Map<String, Integer> index = new HashMap<>();
    /** Non-null for PROTO and EXTERNPROTO types. */
    ProtoDecl proto;
    /** Script nodes may declare their own fields and events in their body. */
    final boolean allowsDeclarations;

    NodeType(String name, String[] names, FieldType[] types, int[] kinds, Object[] defaults) {
        this.name = name;
        this.names = names;
        this.types = types;
        this.kinds = kinds;
        this.defaults = defaults;
        this.allowsDeclarations = name.equals("Script");
        for (int i = 0; i < names.length; i++) index.put(names[i], i);
    }

    /** Number of interface members. */
    int size() {
        return names.length;
    }

    /**
     * Index of a field or event named {@code n}, also accepting {@code set_x} and {@code x_changed}
     * for an exposedField {@code x} (clause 4.7); -1 if none.
     */
    int indexOf(String n) {
        Integer i = index.get(n);
        if (i != null) return i;
        if (n.startsWith("set_")) {
            Integer j = index.get(n.substring(4));
            if (j != null && kinds[j] == EXPOSED_FIELD) return j;
        } else if (n.endsWith("_changed")) {
            Integer j = index.get(n.substring(0, n.length() - 8));
            if (j != null && kinds[j] == EXPOSED_FIELD) return j;
        }
        return -1;
    }

    /** Index of a field that must exist (used by the scene builder for built-in nodes). */
    int require(String n) {
        Integer i = index.get(n);
        if (i == null) throw new IllegalStateException(name + " has no field " + n);
        return i;
    }

    /** True if member {@code i} carries a value (field or exposedField). */
    boolean hasValue(int i) {
        return kinds[i] == FIELD || kinds[i] == EXPOSED_FIELD;
    }

    @Override
    public String toString() {
        return name;
    }
}
