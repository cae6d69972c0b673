package org.handsim.sim;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Where HandSim's data folders are ({@code vrml/}, {@code scenarios/}): the system property
 * {@code handsim.home} (the {@code ./handsim} launcher sets it), else {@code handsim.root} (the
 * tests), else the current directory or the nearest parent that holds {@code vrml/hand/}.
 */
public final class Home {
    private Home() {}

    public static Path dir() {
        for (String prop : new String[] {"handsim.home", "handsim.root"}) {
            String p = System.getProperty(prop);
            if (p != null && Files.isDirectory(Path.of(p, "vrml", "hand"))) return Path.of(p);
        }
        Path d = Path.of("").toAbsolutePath();
        for (Path p = d; p != null; p = p.getParent()) {
            if (Files.isDirectory(p.resolve("vrml").resolve("hand"))) return p;
        }
        return d;
    }

    /** {@code vrml/hand/} */
    public static Path handModels() { return dir().resolve("vrml").resolve("hand"); }

    /** {@code scenarios/} */
    public static Path scenarios() { return dir().resolve("scenarios"); }

    /** The paper's experiment, the default scenario. */
    public static Path paperScenario() { return scenarios().resolve("paper-breakaway.json"); }
}
