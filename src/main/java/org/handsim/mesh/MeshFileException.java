package org.handsim.mesh;

import org.handsim.text.SafeText;

/**
 * A mesh file (OBJ, STL) that cannot be read. The message starts with where the problem is:
 * {@code FILE:LINE:COL: message} for text (OBJ, ASCII STL), {@code FILE: byte N: message} for
 * binary STL, so a user can go straight to it. File name and message are made one safe line
 * ({@link SafeText#line}: control characters, C1 included, escaped), as the VRML loader's.
 */
public final class MeshFileException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public MeshFileException(String message) {
        super(message);
    }

    public MeshFileException(String message, Throwable cause) {
        super(message, cause);
    }

    /** {@code FILE:LINE:COL: message} (line and column 1-based). */
    static MeshFileException at(String file, int line, int column, String message) {
        return new MeshFileException(SafeText.line(file + ":" + line + ":" + column + ": " + message));
    }

    /** {@code FILE: byte N: message} (N 0-based, from the start of the file). */
    static MeshFileException atByte(String file, long offset, String message) {
        return new MeshFileException(SafeText.line(file + ": byte " + offset + ": " + message));
    }
}
