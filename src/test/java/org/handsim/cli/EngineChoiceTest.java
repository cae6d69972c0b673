package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.ServerSocket;
import org.handsim.TestPaths;
import org.junit.jupiter.api.Test;

/**
 * A Spark master HandSim cannot use is refused before Spark is loaded (here Spark is not even on
 * the class path): one line, exit 2, saying which forms are accepted — where {@code garbage},
 * {@code local[0]}, {@code local[-1]}, {@code ''} and {@code yarn} printed a 17-line stack trace,
 * and an unreachable {@code spark://} master 113–186 lines over 63–66 s.
 */
class EngineChoiceTest {
    @Test
    void theMastersHandSimCanUse() {
        for (String ok : new String[] {"local", "local[1]", "local[*]", "local[2,3]", "local[*,4]", "local[1024]", "spark://127.0.0.1:7077",
            "spark://node-a:7077,node-b:7077", "spark://[::1]:7077"}) {
            assertNull(EngineChoice.masterProblem(ok), ok);
        }
        assertTrue(EngineChoice.masterProblem("").startsWith("is empty: use local, local[N]"));
        assertEquals("asks for 0 threads: N must be 1..1024", EngineChoice.masterProblem("local[0]"));
        assertEquals("asks for 99999999999 threads: N must be 1..1024", EngineChoice.masterProblem("local[99999999999]"));
        assertEquals("asks for 0 attempts per task: F must be 1..9999", EngineChoice.masterProblem("local[2,0]"));
        assertTrue(EngineChoice.masterProblem("local[-1]").startsWith("is not a Spark master: use local"));
        assertTrue(EngineChoice.masterProblem("garbage").startsWith("is not a Spark master: use local"));
        assertTrue(EngineChoice.masterProblem("yarn").startsWith("is a cluster manager HandSim does not support"));
        assertTrue(EngineChoice.masterProblem("k8s://https://h:443").startsWith("is a cluster manager HandSim does not support"));
        assertEquals("is not spark://HOST:PORT (port 1..65535)", EngineChoice.masterProblem("spark://host"));
        assertEquals("is not spark://HOST:PORT (port 1..65535)", EngineChoice.masterProblem("spark://host:99999"));
    }

    @Test
    void aBadMasterIsOneLineBeforeSparkIsLoaded() {
        String cube = TestPaths.root().resolve("vrml/objects/cube.wrl").toString();
        for (String m : new String[] {"garbage", "local[0]", "local[-1]", "", "yarn"}) {
            CliTesting.Run r = CliTesting.run("plan", cube, "--engine", "spark", "--master", m, "--trials", "1");
            assertEquals(2, r.code(), r.err());
            assertTrue(r.err().startsWith("handsim: --master '" + m + "' "), r.err());
            assertFalse(r.err().contains("\n") || r.err().contains("Exception") || r.err().contains("class path"), r.err());
            CliTesting.Run s = CliTesting.run("sweep", TestPaths.root().resolve("scenarios/sweeps/cube-offsets.json").toString(),
                "--engine", "spark", "--master", m);
            assertEquals(r.err(), s.err(), "sweep says the same");
        }
    }

    /** A port nobody listens on: refused within seconds with the URL and the reason. */
    @Test
    void anUnreachableMasterIsNamedWithItsReasonInSeconds() throws Exception {
        int port;
        try (ServerSocket s = new ServerSocket(0)) {
            port = s.getLocalPort();
        }
        String url = "spark://127.0.0.1:" + port;
        long t0 = System.nanoTime();
        assertEquals("127.0.0.1:" + port + ": Connection refused", EngineChoice.unreachable(url));
        CliTesting.Run r = CliTesting.run("plan", TestPaths.root().resolve("vrml/objects/cube.wrl").toString(), "--engine", "spark",
            "--master", url, "--trials", "1");
        double s = (System.nanoTime() - t0) / 1e9;
        assertEquals(2, r.code(), r.err());
        assertEquals("handsim: --master " + url + ": cannot connect (127.0.0.1:" + port + ": Connection refused); is the cluster running?"
            + " (tools/spark-cluster start prints its URL)", r.err());
        assertTrue(s < 60, "a hang guard (Spark would retry for minutes): " + s + " s");
        assertTrue(EngineChoice.unreachable("spark://no-such-host.invalid:7077").endsWith(": unknown host"));
        assertNull(EngineChoice.unreachable("local[2]"));
    }
}
