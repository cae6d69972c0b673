package org.handsim.vrml;

import org.handsim.text.SafeText;
import org.jogamp.java3d.loaders.ParsingErrorException;

/**
 * The one error the VRML97 loader raises for a file it cannot load: a syntax error, a value of
 * the wrong type, an index out of range, a missing or wrong header (VRML 1.0, Inventor), an
 * Inline that the sandbox refuses, nesting deeper than the limit, a recursive PROTO, and so on.
 *
 * <p>{@link #getMessage()} is exactly one line, {@code FILE:LINE:COL: message}, the form
 * compilers use, so editors can jump to the place. Lines and columns count from 1; the column
 * counts characters (not bytes) from the start of the line. The parts are also available
 * separately ({@link #file()}, {@link #line()}, {@link #column()}, {@link #detail()}).
 *
 * <p>It extends Java3D's {@link ParsingErrorException}, so callers that only know the
 * {@code Loader} interface catch it as that.
 */
public final class VrmlParseException extends ParsingErrorException {
    private static final long serialVersionUID = 1L;

    private final String file;
    private final int line;
    private final int column;
    private final String detail;

    /**
     * @param file   the file as the caller named it (or an Inline's resolved path)
     * @param line   1-based line
     * @param column 1-based column in characters
     * @param detail what is wrong, naming the offending token or value
     */
    public VrmlParseException(String file, int line, int column, String detail) {
        super(oneLine(file) + ":" + line + ":" + column + ": " + oneLine(detail));
        this.file = file;
        this.line = line;
        this.column = column;
        this.detail = oneLine(detail);
    }

    /** Control and line-breaking characters escaped (text.SafeText): the message stays one line. */
    private static String oneLine(String s) {
        return SafeText.line(s);
    }

    /** The file as named by the caller (or the Inline/EXTERNPROTO file in which the error is). */
    public String file() { return file; }

    /** 1-based line of the error. */
    public int line() { return line; }

    /** 1-based column (characters) of the error. */
    public int column() { return column; }

    /** The message without the {@code FILE:LINE:COL: } prefix. */
    public String detail() { return detail; }
}
