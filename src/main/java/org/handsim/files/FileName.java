package org.handsim.files;

/**
 * Names that become a file or folder name (a scenario's or a sweep's name is its output folder
 * {@code out/<name>/}): letters, digits, {@code .}, {@code _} and {@code -}, and not made of dots
 * only, so a name never climbs out of {@code out/} ({@code ..}), never names {@code out/} itself
 * ({@code .}), never holds a separator or a control character.
 */
public final class FileName {
    private FileName() {}

    /** What {@link #problem} asks of a name, for messages. */
    public static final String RULE = "letters, digits, '.', '_' or '-', not only dots (it names the output folder)";

    /** Null when {@code name} is safe as a file name, else what is wrong with it. */
    public static String problem(String name) {
        if (name.isEmpty()) return "must not be empty";
        if (!name.matches("[A-Za-z0-9._-]+")) return "must be " + RULE;
        if (name.matches("\\.+")) return "must not be '.' or '..' (or only dots): " + RULE;
        return null;
    }
}
