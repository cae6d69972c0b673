package org.handsim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.handsim.TestPaths;
import org.handsim.cli.ChildJvm;
import org.handsim.cli.HandSim;
import org.junit.jupiter.api.Test;

/**
 * The default path of every short command, in the quick suite: a resident server in this JVM
 * (its socket, protocol, streams, cancellation context and the clean-up between commands, all as
 * a served command meets them) runs several different commands one after another, twice, and
 * each gives the bytes and exit code the same command gives run in-process, and in the second
 * round what it gave in the first — so a static that one command leaves behind for the next
 * shows here. Output files of {@code run} are compared too
 * (the summary without its timing fields, masked as {@link ServedAsInProcessTest} masks them,
 * which runs each README example through a client and a server JVM once). The slow
 * {@code ServerTest} covers signals and a killed server.
 */
class ServedLikeInProcessTest {
    record Ran(int code, byte[] out, byte[] err) {
        String text() { return "exit " + code + "\nout: " + new String(out, StandardCharsets.UTF_8) + "\nerr: " + new String(err, StandardCharsets.UTF_8); }
    }

    static Ran inProcess(String... args) {
        ByteArrayOutputStream o = new ByteArrayOutputStream(), e = new ByteArrayOutputStream();
        PrintWriter ow = new PrintWriter(new java.io.OutputStreamWriter(o, StandardCharsets.UTF_8), true);
        PrintWriter ew = new PrintWriter(new java.io.OutputStreamWriter(e, StandardCharsets.UTF_8), true);
        int code = HandSim.execute(ow, ew, List.of(ServerCommand.class), args);
        ow.flush();
        ew.flush();
        return new Ran(code, o.toByteArray(), e.toByteArray());
    }

    static Ran served(String identity, String... args) throws Exception {
        // the server is busy until it has cleaned up after the last command, a moment after its exit code
        Client.Connection c = Client.connect(identity, args);
        for (long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60); c.outcome == Client.Outcome.BUSY && System.nanoTime() < end; ) {
            Thread.sleep(5);
            c = Client.connect(identity, args);
        }
        assertEquals(Client.Outcome.ACCEPTED, c.outcome, "not served: " + c.reason);
        ByteArrayOutputStream o = new ByteArrayOutputStream(), e = new ByteArrayOutputStream();
        try (java.nio.channels.SocketChannel ch = c.channel) {
            int code = c.relay(o, e);
            return new Ran(code, o.toByteArray(), e.toByteArray());
        }
    }

    /** summary.json without the fields that time the run ({@link ServedAsInProcessTest#masked}). */
    static String withoutTimes(Path summary) throws Exception {
        return ServedAsInProcessTest.masked(Files.readString(summary));
    }

    @Test
    void servedCommandsGiveTheBytesAndExitCodesOfInProcessOnes() throws Exception {
        Path dir = Files.createTempDirectory("handsim-served");
        String root = TestPaths.root().toString();
        List<String[]> commands = List.of(
            new String[] {"fk", "--finger", "1", "--joints", "0.1,0.7,0.4"},
            new String[] {"ik", "--finger", "2", "--target", "0.06,0.0,0.1"},
            new String[] {"id", "--finger", "3", "--q", "0,0.5,0.4", "--qd", "0,0.1,0.2", "--qdd", "0,1,2", "--gravity", "0,0,-9.81"},
            new String[] {"mesh", root + "/vrml/objects/mug.wrl"},
            new String[] {"collide", root + "/vrml/objects/cube.wrl", root + "/vrml/objects/mug.wrl"},
            new String[] {"run", root + "/scenarios/paper-breakaway.json", "--dt", "0.01", "--no-charts", "--out", "OUT"},
            new String[] {"mesh", root + "/vrml/objects/no-such.wrl"},
            new String[] {"fk", "--finger", "7", "--joints", "0,0,0"},
            new String[] {"ik", "--help"});
        String[] props = {"handsim.server.dir", "handsim.server.warmup", "handsim.server.answerMs"};
        String[] before = new String[props.length];
        for (int i = 0; i < props.length; i++) before[i] = System.getProperty(props[i]);
        Thread serving = null;
        Server server = null;
        try {
            System.setProperty("handsim.server.dir", dir.resolve("srv").toString());
            Path srv = Client.effective(dir.resolve("srv"));   // a short stand-in in a deep checkout
            System.setProperty("handsim.server.warmup", "0");
            // a loaded machine (or the other test JVM beside this one) may take more than 2 s to
            // answer: this test does not time answers (ServerTest's tests of the watchdog do)
            System.setProperty("handsim.server.answerMs", "20000");
            assertEquals(null, Client.unsafe(srv, true));
            String identity = Client.identity();
            String key = Client.key(identity);
            server = new Server(identity, srv, key, TimeUnit.MINUTES.toMillis(5));
            Server s = server;
            serving = new Thread(() -> {
                try {
                    s.serve();
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            }, "test-server");
            serving.setDaemon(true);
            serving.start();
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (!Files.exists(Client.socketFile(srv, key)) && System.nanoTime() < end) Thread.sleep(10);
            assertTrue(Files.exists(Client.socketFile(srv, key)), "the server did not listen within 60 s");
            List<String> differ = new ArrayList<>();
            List<String> first = new ArrayList<>();   // round 1's served outputs: round 2 must give them again
            for (int round = 1; round <= 2; round++) {
                for (int n = 0; n < commands.size(); n++) {
                    String[] cmd = commands.get(n);
                    String[] a = cmd.clone(), b = cmd.clone();
                    for (int i = 0; i < cmd.length; i++) {
                        if (cmd[i].equals("OUT")) {
                            a[i] = dir.resolve("in-process").toString();
                            b[i] = dir.resolve("served").toString();
                        }
                    }
                    Ran want = inProcess(a), got = served(identity, b);
                    String what = "round " + round + ": " + String.join(" ", cmd);
                    String wantText = ServedAsInProcessTest.masked(want.text().replace(dir.resolve("in-process").toString(), "OUT"));
                    String gotText = ServedAsInProcessTest.masked(got.text().replace(dir.resolve("served").toString(), "OUT"));
                    if (!wantText.equals(gotText)) differ.add(what + "\nin-process " + wantText + "\nserved " + gotText);
                    if (round == 1) first.add(gotText);
                    else if (!first.get(n).equals(gotText)) differ.add(what + ": not what round 1 gave\n" + first.get(n) + "\n" + gotText);
                    if (Arrays.asList(cmd).contains("OUT") && want.code() == 0) {
                        Path x = dir.resolve("in-process"), y = dir.resolve("served");
                        if (!Arrays.equals(Files.readAllBytes(x.resolve("trace.csv")), Files.readAllBytes(y.resolve("trace.csv")))) differ.add(what + ": trace.csv");
                        String sx = withoutTimes(x.resolve("summary.json")), sy = withoutTimes(y.resolve("summary.json"));
                        if (!sx.equals(sy)) differ.add(what + ": summary.json\nin-process " + sx + "\nserved " + sy);
                    }
                }
            }
            assertEquals(List.of(), differ);
        } finally {
            if (server != null) ServerAdmin.stop(Client.socketFile(Client.effective(dir.resolve("srv")), Client.key(Client.identity())));
            if (serving != null) serving.join(TimeUnit.SECONDS.toMillis(60));
            for (int i = 0; i < props.length; i++) {
                if (before[i] == null) System.clearProperty(props[i]); else System.setProperty(props[i], before[i]);
            }
            if (!Client.effective(dir.resolve("srv")).equals(dir.resolve("srv"))) ChildJvm.deleteTree(Client.effective(dir.resolve("srv")));
            ChildJvm.deleteTree(dir);
        }
    }
}
