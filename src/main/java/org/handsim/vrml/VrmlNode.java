package org.handsim.vrml;

/**
 * One parsed node: its type and the values of the fields given in the file (the others keep
 * the type's defaults), plus where each came from so that errors found later (an index out of
 * range, a refused Inline) still name the file, line and column.
 *
 * <p>Nodes form a directed acyclic graph: {@code USE} puts the same object in several places.
 * In a PROTO body a node may carry {@code IS} bindings ({@link #isRefs}); nodes outside PROTO
 * bodies never do, and every PROTO instance outside a body has been expanded, so the scene
 * builder only ever sees built-in node types.
 */
final class VrmlNode {
    final NodeType type;
    final VrmlText text;
    /** Offset of the node's type name in {@link #text}. */
    final int offset;
    /** Field values given in the file (null: the default). */
    final Object[] values;
    /** Offset of each given value (for messages). */
    final int[] valueOffsets;
    /** Inside PROTO bodies: name of the interface member a field is bound to with IS, else null. */
    String[] isRefs;
    /** The DEF name, if any. */
    String defName;

    VrmlNode(NodeType type, VrmlText text, int offset) {
        this.type = type;
        this.text = text;
        this.offset = offset;
        this.values = new Object[type.size()];
        this.valueOffsets = new int[type.size()];
    }

    /** The value of field {@code i}: given or default. */
    Object get(int i) {
        Object v = values[i];
        return v != null ? v : type.defaults[i];
    }

    /** The value of the field named {@code name} (must exist). */
    Object get(String name) {
        return get(type.require(name));
    }

    /** Offset of the value of {@code name} if given, else of the node. */
    int offsetOf(String name) {
        int i = type.indexOf(name);
        return i >= 0 && values[i] != null ? valueOffsets[i] : offset;
    }

    float getFloat(String name) {
        return ((float[]) get(name))[0];
    }

    float[] getFloats(String name) {
        return (float[]) get(name);
    }

    int getInt(String name) {
        return ((int[]) get(name))[0];
    }

    int[] getInts(String name) {
        return (int[]) get(name);
    }

    boolean getBool(String name) {
        return (Boolean) get(name);
    }

    String[] getStrings(String name) {
        return (String[]) get(name);
    }

    VrmlNode getNode(String name) {
        return (VrmlNode) get(name);
    }

    VrmlNode[] getNodes(String name) {
        return (VrmlNode[]) get(name);
    }

    /** "Transform" or "Transform 'DEFNAME'" for messages. */
    String describe() {
        return defName == null ? type.name : type.name + " '" + defName + "'";
    }

    @Override
    public String toString() {
        return describe();
    }
}
