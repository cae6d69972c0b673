package org.handsim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.handsim.cli.CliTesting;
import org.junit.jupiter.api.Test;

/**
 * A file that is not there is reported with where it was looked for: a relative path names the
 * folder it was resolved against (and, run from the jar outside a checkout, where the jar's
 * models are: FatJarTest); an absolute path says it all.
 */
class NotFoundTest {
    @Test
    void aRelativePathNamesTheFolderItWasLookedIn() {
        Path cwd = Path.of("").toAbsolutePath();
        boolean home = Home.dir().toAbsolutePath().normalize().equals(cwd);
        String m = NotFound.message(Path.of("no/such/mug.wrl"));
        assertTrue(m.startsWith("no/such/mug.wrl: no such file (looked in " + cwd), m);
        if (home) assertEquals("no/such/mug.wrl: no such file (looked in " + cwd + ")", m);
        assertEquals("/no/such/mug.wrl: no such file", NotFound.message(Path.of("/no/such/mug.wrl")));
        // a relative path that exists in HandSim's folder but not here names it
        if (!home) assertTrue(NotFound.message(Path.of("vrml/objects/mug.wrl")).contains(Home.dir().resolve("vrml/objects/mug.wrl").toString()));
    }

    @Test
    void theCommandsSayWhereTheyLooked() {
        CliTesting.Run plan = CliTesting.run("plan", "no/such/mug.wrl");
        assertEquals(3, plan.code());
        assertTrue(plan.err().startsWith("handsim: no/such/mug.wrl: no such file (looked in "), plan.err());
        CliTesting.Run run = CliTesting.run("run", "no/such/scenario.json");
        assertEquals(3, run.code());
        assertTrue(run.err().startsWith("no/such/scenario.json: no such file (looked in "), run.err());
        CliTesting.Run mesh = CliTesting.run("mesh", "no/such/mug.wrl");
        assertEquals(3, mesh.code());
        assertTrue(mesh.err().contains("no such file (looked in "), mesh.err());
    }
}
