package org.handsim.vrml;

/**
 * The twenty VRML97 field types (ISO/IEC 14772-1, clause 5) and how their values are held in
 * memory once parsed. Single-valued types start with SF, multiple-valued with MF.
 *
 * <table>
 *   <caption>Value representation</caption>
 *   <tr><th>type</th><th>Java value</th></tr>
 *   <tr><td>SFBool</td><td>{@link Boolean}</td></tr>
 *   <tr><td>SFInt32, MFInt32, SFImage</td><td>{@code int[]} (SFInt32: length 1; SFImage: width,
 *       height, components, then the pixels)</td></tr>
 *   <tr><td>SFFloat, SFVec2f, SFVec3f, SFColor, SFRotation and their MF forms</td><td>{@code float[]}
 *       with {@link #components} numbers per value, flattened</td></tr>
 *   <tr><td>SFTime, MFTime</td><td>{@code double[]}</td></tr>
 *   <tr><td>SFString</td><td>{@link String}; MFString: {@code String[]}</td></tr>
 *   <tr><td>SFNode</td><td>{@link VrmlNode} or {@code null} (NULL)</td></tr>
 *   <tr><td>MFNode</td><td>{@code VrmlNode[]}</td></tr>
 * </table>
 *
 * <p>Arrays in parsed values are never modified after parsing; defaults are shared.
 */
enum FieldType {
    SFBool(1), SFInt32(1), SFFloat(1), SFTime(1), SFVec2f(2), SFVec3f(3), SFColor(3), SFRotation(4),
    SFString(1), SFImage(1), SFNode(1),
    MFInt32(1), MFFloat(1), MFTime(1), MFVec2f(2), MFVec3f(3), MFColor(3), MFRotation(4),
    MFString(1), MFNode(1);

    /** Numbers per value for the float-based types (SFVec3f: 3, MFRotation: 4, ...). */
    final int components;

    FieldType(int components) {
        this.components = components;
    }

    /** The type named {@code s}, or null if {@code s} is not a VRML97 field type. */
    static FieldType byName(String s) {
        for (FieldType t : values()) {
            if (t.name().equals(s)) return t;
        }
        return null;
    }
}
