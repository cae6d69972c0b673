package org.handsim.hand;

/** A hand description file that is missing a field or holds an invalid value; the message names it. */
public final class HandDescriptionException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public HandDescriptionException(String message) {
        super(message);
    }
}
