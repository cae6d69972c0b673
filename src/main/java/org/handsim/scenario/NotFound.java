package org.handsim.scenario;

import java.nio.file.Files;
import java.nio.file.Path;
import org.handsim.files.InputFile;

/**
 * The message for a file that is not there, saying where it was looked for: a relative path
 * names the folder it was resolved against (the current directory), and when HandSim's own
 * data folder ({@link Home#dir()}: the checkout, or the models unpacked from the runnable jar)
 * is elsewhere, it says where that is, with the file there when it exists — so
 * {@code java -jar handsim-all.jar plan vrml/objects/mug.wrl} run outside a checkout says where
 * the jar's mug is.
 */
public final class NotFound {
    private NotFound() {}

    /**
     * Why {@code file} cannot be read as an input ({@link InputFile#problem}: missing, not a
     * regular file, unreadable), with {@link #where} it was looked for when it is missing; null
     * when it is a readable regular file.
     */
    public static String problem(Path file) {
        String why = InputFile.problem(file);
        return InputFile.NO_SUCH_FILE.equals(why) ? why + where(file) : why;
    }

    /** {@code GIVEN: no such file} and where it was looked for ({@link #where}). */
    public static String message(Path given) {
        return given + ": no such file" + where(given);
    }

    /**
     * Where {@code given} was looked for, as {@code " (looked in DIR; ...)"}, or the empty
     * string for an absolute path outside the jar's folder (the path says it all).
     */
    public static String where(Path given) {
        StringBuilder sb = new StringBuilder();
        Path cwd = Path.of("").toAbsolutePath();
        if (!given.isAbsolute()) sb.append("looked in ").append(cwd);
        Path home = Home.dir().toAbsolutePath().normalize();
        if (!home.equals(cwd)) {
            String what = Home.fromRunnableJar() ? "the models and scenarios of the jar are unpacked in " : "HandSim's models and scenarios are in ";
            Path there = given.isAbsolute() ? null : home.resolve(given).normalize();
            if (there != null && Files.exists(there)) {
                sep(sb).append(what).append(home).append(": ").append(there);
            } else if (Home.fromRunnableJar()) {
                sep(sb).append(what).append(home).append(" (vrml/objects/, scenarios/)");
            }
        }
        return sb.length() == 0 ? "" : " (" + sb + ")";
    }

    private static StringBuilder sep(StringBuilder sb) {
        return sb.length() == 0 ? sb : sb.append("; ");
    }
}
