package org.handsim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.net.StandardProtocolFamily;
import java.net.UnixDomainSocketAddress;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.jar.JarOutputStream;
import java.util.zip.ZipEntry;
import org.handsim.TestPaths;
import org.handsim.cli.ChildJvm;
import org.handsim.text.Json;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The resident server against the command run in its own JVM: the same bytes; a client stopped
 * with SIGTERM or SIGKILL mid-run leaves the old set or a whole new one and no private folder;
 * a second client while the server is busy runs in its own JVM; a socket left by a server killed
 * with SIGKILL is found and removed; a server whose build changed refuses and exits. Every JVM
 * here is a child (the client as the launcher starts it, {@code org.handsim.server.Client}; the
 * server started directly, in the same working directory with the same options), with its own
 * server folder, so nothing touches the user's servers.
 */
@Tag("slow")
class ServerTest {
    /** A command's end: exit code, standard output, standard error without the client's report line, and that line. */
    record Ran(int code, String out, String err, String how) {}

    /** A test's folder: {@code work/} (the working directory), {@code srv/} (the servers' folder), and the JVM options of both sides. */
    static final class Setup implements AutoCloseable {
        final Path dir, work, srv;
        final List<String> jvm = new ArrayList<>();
        String classPath = System.getProperty("java.class.path");
        final List<Process> started = new ArrayList<>();

        Setup(String name, String... extraJvm) throws Exception {
            dir = Files.createTempDirectory("handsim-server-" + name);
            work = Files.createDirectories(dir.resolve("work"));
            srv = dir.resolve("srv");
            // a loaded machine may take more than 2 s to answer: the tests that do not time answers give 20
            jvm.addAll(List.of("-Xss16m", "-Xmx1g", "-Djava.awt.headless=true", "-Dj3d.rend=noop", "-Djava.io.tmpdir=" + dir,
                "-Dhandsim.home=" + TestPaths.root(), "-Dhandsim.cache=" + dir.resolve("cache"), "-Dhandsim.server.dir=" + srv,
                "-Dhandsim.server.idle=300", "-Dhandsim.server.answerMs=20000"));
            jvm.addAll(List.of(extraJvm));
        }

        private List<String> command(String main, List<String> more, String... args) {
            List<String> cmd = new ArrayList<>();
            cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
            cmd.addAll(jvm);
            cmd.add("-Dhandsim.server.jvm=" + String.join(" ", jvm));
            cmd.addAll(more);
            cmd.add("-cp");
            cmd.add(classPath);
            cmd.add(main);
            cmd.addAll(List.of(args));
            return cmd;
        }

        /** The command line of a JVM with this test's options running {@code main}. */
        List<String> jvmCommand(String main, String... args) {
            return command(main, List.of(), args);
        }

        /** Starts a server here and waits until it listens; returns its process. */
        Process server() throws Exception {
            Path log = Files.createTempFile(dir, "server", ".log");
            Process p = new ProcessBuilder(command(WatchedServer.class.getName(), List.of())).directory(work.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new java.io.File("/dev/null"))).redirectErrorStream(true)
                .redirectOutput(log.toFile()).start();
            started.add(p);
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(90);
            while (System.nanoTime() < end) {
                // ServerAdmin looks in the folder the servers use: srv, or its short stand-in in a deep checkout (never made)
                for (ServerAdmin.Status s : ServerAdmin.servers(srv)) if (s.field("pid").equals(Long.toString(p.pid()))) return p;
                if (!p.isAlive()) fail("the server ended: " + Files.readString(log));
                Thread.sleep(50);
            }
            fail("the server did not listen within 90 s: " + Files.readString(log));
            return p;
        }

        /** Starts a client (the launcher's entry point) with the command {@code args}; {@code inProcess}: with HANDSIM_SERVER=0. */
        ChildJvm.Started client(boolean inProcess, String... args) throws Exception {
            return client(work, List.of(), inProcess, args);
        }

        /** As {@link #client(boolean, String...)}, in the folder {@code in}, its command line after {@code wrapper} (nice, a shell setting a limit ...). */
        ChildJvm.Started client(Path in, List<String> wrapper, boolean inProcess, String... args) throws Exception {
            List<String> cmd = new ArrayList<>(wrapper);
            cmd.addAll(command(Client.class.getName(), List.of("-Dhandsim.server.report=on"), args));
            ProcessBuilder pb = new ProcessBuilder(cmd).directory(in.toFile());
            pb.environment().remove("HANDSIM_SERVER");
            if (inProcess) pb.environment().put("HANDSIM_SERVER", "0");
            Path out = Files.createTempFile(dir, "client", ".out"), err = Files.createTempFile(dir, "client", ".err");
            Process p = pb.redirectOutput(out.toFile()).redirectError(err.toFile()).redirectInput(ProcessBuilder.Redirect.from(new java.io.File("/dev/null"))).start();
            return new ChildJvm.Started(p, out, err);
        }

        /** Runs a client whose standard output is a pipe this test reads (as {@code handsim ... | head}). */
        Ran piped(boolean inProcess, String... args) throws Exception {
            ProcessBuilder pb = new ProcessBuilder(command(Client.class.getName(), List.of("-Dhandsim.server.report=on"), args)).directory(work.toFile());
            pb.environment().remove("HANDSIM_SERVER");
            if (inProcess) pb.environment().put("HANDSIM_SERVER", "0");
            Path err = Files.createTempFile(dir, "client", ".err");
            Process p = pb.redirectError(err.toFile()).redirectInput(ProcessBuilder.Redirect.from(new java.io.File("/dev/null"))).start();
            byte[] out = p.getInputStream().readAllBytes();
            Path outFile = Files.write(Files.createTempFile(dir, "client", ".out"), out);
            return finish(new ChildJvm.Started(p, outFile, err));
        }

        /** Runs a client to its end. */
        Ran run(boolean inProcess, String... args) throws Exception {
            return finish(client(inProcess, args));
        }

        Ran finish(ChildJvm.Started c) throws Exception {
            if (!c.process().waitFor(3, TimeUnit.MINUTES)) {
                c.process().destroyForcibly().waitFor();
                fail("the client did not end within 3 minutes: " + c.errText());
            }
            String err = c.errText();
            String how = "";
            List<String> rest = new ArrayList<>();
            for (String l : err.split("\n", -1)) {
                if (l.startsWith("handsim-server ")) how = l.substring("handsim-server ".length());
                else rest.add(l);
            }
            return new Ran(c.process().exitValue(), Files.readString(c.out(), StandardCharsets.UTF_8), String.join("\n", rest), how);
        }

        /** Stops every server of this folder and waits for the processes this test started. */
        @Override
        public void close() throws Exception {
            try {
                for (Process p : started) if (p.isAlive()) new ProcessBuilder("kill", "-CONT", Long.toString(p.pid())).start().waitFor();
                for (ServerAdmin.Status s : ServerAdmin.servers(srv)) {   // in srv or its short stand-in
                    ServerAdmin.stop(s.socket());
                    long pid = Long.parseLong(s.field("pid"));
                    ProcessHandle.of(pid).ifPresent(h -> {
                        try {
                            h.onExit().get(30, TimeUnit.SECONDS);
                        } catch (Exception e) {
                            h.destroyForcibly();   // a server this test started (directly or through its client)
                        }
                    });
                }
                for (Process p : started) {
                    if (!p.waitFor(30, TimeUnit.SECONDS)) p.destroyForcibly().waitFor();
                }
            } finally {
                ChildJvm.deleteTree(dir);
                Path shortFolder = Client.effective(srv);
                if (!shortFolder.equals(srv)) ChildJvm.deleteTree(shortFolder);
            }
        }
    }

    @Test
    void servedCommandsGiveTheBytesOfInProcessOnes() throws Exception {
        try (Setup s = new Setup("same")) {
            Ran ref = s.run(true, "run", "--dt", "0.005", "--out", "ref");
            assertEquals(0, ref.code(), ref.err());
            assertTrue(ref.how().startsWith("in-process (not_tried"), ref.how());
            Process server = s.server();
            for (int round = 1; round <= 2; round++) {
                Ran served = s.run(false, "run", "--dt", "0.005", "--out", "served");
                assertEquals(0, served.code(), served.err());
                assertEquals("served", served.how());
                assertEquals(ServedAsInProcessTest.masked(ref.err()), ServedAsInProcessTest.masked(served.err()), "apart from progress reports, whose number depends on the speed");
                assertEquals(lastLine(ref.out()), lastLine(served.out()).replace("served", "ref"));
                Path a = s.work.resolve("ref"), b = s.work.resolve("served");
                for (String f : List.of("trace.csv", "fig7_finger3.png", "fig8_finger3.png")) {
                    assertTrue(Arrays.equals(Files.readAllBytes(a.resolve(f)), Files.readAllBytes(b.resolve(f))), f + " differs in round " + round);
                }
                for (String f : List.of("fig7_finger3.svg", "fig8_finger3.svg")) {   // apart from JFreeSVG's clip ids, made of the clock in any JVM
                    assertEquals(svg(a.resolve(f)), svg(b.resolve(f)), f + " differs in round " + round);
                }
                assertEquals(withoutTimes(a.resolve("summary.json")), withoutTimes(b.resolve("summary.json")), "summary.json, round " + round);
                assertEquals(List.of(), hidden(b));
            }
            // errors: the same line and exit code
            Ran refBad = s.run(true, "run", "no-such.json");
            Ran bad = s.run(false, "run", "no-such.json");
            assertEquals("served", bad.how());
            assertEquals(3, refBad.code());
            assertEquals(refBad.code(), bad.code());
            assertEquals(refBad.err(), bad.err());
            // a command it does not serve runs in-process
            Ran help = s.run(false, "tradeoff", "--help");
            assertEquals(0, help.code());
            assertTrue(help.how().startsWith("in-process (not_tried"), help.how());
            assertTrue(server.isAlive(), "the server serves on");
        }
    }

    @Test
    void sigtermOrSigkillOfTheClientLeavesTheOldSetOrAWholeNewOne() throws Exception {
        for (String phase : List.of("half-run", "manifest")) {
            for (boolean kill : new boolean[] {false, true}) {
                try (Setup s = new Setup("stop", "-Dhandsim.phases=on", "-Dhandsim.phases.pause=" + phase)) {
                    Path resume = s.dir.resolve("resume");
                    s.jvm.add("-Dhandsim.phases.resume=" + resume);
                    Files.writeString(resume, "");
                    Ran old = s.run(true, "run", "--dt", "0.01", "--out", "out");
                    assertEquals(0, old.code(), old.err());
                    Map<String, byte[]> before = snapshot(s.work.resolve("out"));
                    Files.delete(resume);
                    Process server = s.server();
                    ChildJvm.Started c = s.client(false, "run", "--dt", "0.005", "--out", "out");
                    waitFor(c, "handsim-phase " + phase + "\n");
                    if (kill) c.process().destroyForcibly(); else c.process().destroy();
                    assertTrue(c.process().waitFor(60, TimeUnit.SECONDS), "the client ends after its signal");
                    String where = (kill ? "SIGKILL" : "SIGTERM") + " at " + phase;
                    if (!kill) assertEquals(143, c.process().exitValue(), where + ": the exit status of a JVM stopped by SIGTERM");
                    waitIdle(s, server);   // after SIGKILL the server notices the closed socket by itself
                    Path out = s.work.resolve("out");
                    assertEquals(List.of(), hidden(out), where + ": no private folder or lock left");
                    Map<String, byte[]> after = snapshot(out);
                    if (phase.equals("half-run")) {
                        assertTrue(same(before, after), where + ": the old set, byte for byte: " + after.keySet());
                    } else {   // the publication had begun: it is completed
                        @SuppressWarnings("unchecked")
                        Map<String, Object> summary = (Map<String, Object>) Json.parse("summary.json", new String(after.get("summary.json"), StandardCharsets.UTF_8));
                        assertEquals(0.005, ((Number) summary.get("dt_s")).doubleValue(), 1e-15, where + ": the whole new set");
                        long steps = ((Number) summary.get("steps")).longValue();
                        assertEquals(steps + 2, Files.readAllLines(out.resolve("trace.csv")).size(), where + ": the new trace (header, start, steps)");
                    }
                    assertTrue(server.isAlive(), where + ": the server serves on");
                    Files.writeString(resume, "");
                    Ran next = s.run(false, "run", "--dt", "0.005", "--out", "out");
                    assertEquals(0, next.code(), where + ": the next command: " + next.err());
                    assertEquals("served", next.how(), where);
                    assertEquals(List.of(), hidden(out));
                }
            }
        }
    }

    @Test
    void aBusyServerSendsTheSecondClientToItsOwnJvm() throws Exception {
        try (Setup s = new Setup("busy", "-Dhandsim.phases=on", "-Dhandsim.phases.pause=half-run")) {
            Path resume = s.dir.resolve("resume");
            s.jvm.add("-Dhandsim.phases.resume=" + resume);
            s.server();
            ChildJvm.Started first = s.client(false, "run", "--dt", "0.005", "--out", "out");
            waitFor(first, "handsim-phase half-run\n");
            Ran second = s.run(false, "fk", "--finger", "1", "--joints=0.1,0.2,0.3");
            assertEquals(0, second.code(), second.err());
            assertEquals("in-process (busy: busy)", second.how());
            Ran ref = s.run(true, "fk", "--finger", "1", "--joints=0.1,0.2,0.3");
            assertEquals(ref.out(), second.out());
            Files.writeString(resume, "");
            Ran firstDone = s.finish(first);
            assertEquals(0, firstDone.code(), firstDone.err());
            assertEquals("served", firstDone.how());
        }
    }

    @Test
    void aSocketLeftByAKilledServerIsRemoved() throws Exception {
        try (Setup s = new Setup("stale")) {
            Process server = s.server();
            Path socket = ServerAdmin.servers(s.srv).get(0).socket();
            server.destroyForcibly().waitFor();
            assertTrue(Files.exists(socket), "SIGKILL leaves the socket");
            Ran r = s.run(false, "fk", "--finger", "2", "--joints=0,0.5,0.5");
            assertEquals(0, r.code(), r.err());
            assertEquals("in-process (no_server: stale socket)", r.how());
            // the client removed it and started a server for next time: the socket is a live one now, or none yet
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(90);
            List<ServerAdmin.Status> live = List.of();
            while (System.nanoTime() < end && (live = ServerAdmin.servers(s.srv)).isEmpty()) Thread.sleep(100);
            assertEquals(1, live.size(), "the client started a new server");
            assertNotEquals(Long.toString(server.pid()), live.get(0).field("pid"));
            Ran next = s.run(false, "fk", "--finger", "2", "--joints=0,0.5,0.5");
            assertEquals("served", next.how());
            assertEquals(r.out(), next.out());
        }
    }

    @Test
    void aServerWhoseJarChangedRefusesAndExits() throws Exception {
        try (Setup s = new Setup("jar")) {
            Path jar = s.dir.resolve("extra.jar");
            writeJar(jar, 1);
            s.classPath = s.classPath + java.io.File.pathSeparator + jar;
            Process server = s.server();
            assertEquals("served", s.run(false, "fk", "--finger", "1", "--joints=0,0,0").how());
            ServerAdmin.Status st = ServerAdmin.servers(s.srv).get(0);
            String identity = identityOf(s.srv, st.socket());
            writeJar(jar, 2);   // a new build: another size
            // a client of the old identity (as one that looked just before the rebuild) is refused
            String answer = request(st.socket(), identity);
            assertTrue(answer == null || answer.startsWith("refused: the build changed"), answer);
            assertTrue(server.waitFor(30, TimeUnit.SECONDS), "the server exits");
            assertFalse(Files.exists(st.socket()), "and removes its socket");
        }
    }

    /**
     * The battery's {@code mesh --obj /dev/stdout | head}: served, the OBJ went into the server's
     * log and the pipe got nothing. A path naming the client's own descriptors — as given, or
     * through a link — is run by the client itself: the pipe gets the OBJ as with
     * {@code HANDSIM_SERVER=0}; {@code /dev/stderr} no longer ends the server.
     */
    @Test
    void aPathNamingTheClientsOwnDescriptorsIsRunByTheClient() throws Exception {
        try (Setup s = new Setup("own", "-Dhandsim.server.warmup=0")) {
            Files.createSymbolicLink(s.work.resolve("vrml"), TestPaths.root().resolve("vrml"));
            Files.createSymbolicLink(s.work.resolve("to-stdout.obj"), Path.of("/dev/stdout"));
            Process server = s.server();
            Ran ref = s.piped(true, "mesh", "vrml/objects/cube.wrl", "--obj", "/dev/stdout");
            assertEquals(0, ref.code(), ref.err());
            assertTrue(ref.out().contains("\nf 1 "), "the OBJ on the pipe: " + ref.out());
            for (String target : List.of("/dev/stdout", "to-stdout.obj", "/dev/fd/1", "/proc/self/fd/1")) {
                Ran r = s.piped(false, "mesh", "vrml/objects/cube.wrl", "--obj", target);
                assertEquals(0, r.code(), target + ": " + r.err());
                assertTrue(r.how().startsWith("in-process (here: '" + target + "' "), target + ": " + r.how());
                assertEquals(ServedAsInProcessTest.masked(ref.out()), ServedAsInProcessTest.masked(r.out()), target);
                assertEquals(ref.err(), r.err(), target + ": the client says nothing about it");
            }
            Ran err = s.run(false, "mesh", "vrml/objects/cube.wrl", "--obj", "/dev/stderr");
            assertEquals(0, err.code(), err.err());
            assertTrue(err.err().contains("\nf 1 "), "the OBJ on the client's standard error");
            assertTrue(server.isAlive(), "the server serves on");
            assertEquals("served", s.run(false, "fk", "--finger", "1", "--joints=0,0,0").how());
            String note = ServerAdmin.lastNotServed(s.srv);
            assertTrue(note != null && note.endsWith(" here: '/dev/stderr' names a device or this process's own files"), "server status says why: " + note);
        }
    }

    /**
     * The battery's clients in another context than the server's: under {@code ulimit -f 100} a
     * served run exited 0 where in-process it fails; under {@code nice} the nice level did not
     * apply; in another mount namespace the server wrote where the client cannot see. Each now
     * runs as with {@code HANDSIM_SERVER=0} in the same context: the same exit code, output and
     * files (the server of the test's own context never gets the command).
     */
    @Test
    void aClientUnderAnotherFileLimitNiceLevelOrMountNamespaceGetsTheInProcessResult() throws Exception {
        try (Setup s = new Setup("context", "-Dhandsim.server.warmup=0", "-Dhandsim.server.max=10")) {
            Process server = s.server();
            List<List<String>> wrappers = new ArrayList<>(List.of(List.of("bash", "-c", "ulimit -f 100 && exec \"$@\"", "bash"),
                List.of("nice", "-n", "7")));
            Files.createDirectories(s.work.resolve("ns"));
            boolean unshare = new ProcessBuilder("unshare", "-m", "true").start().waitFor() == 0;
            if (unshare) wrappers.add(List.of("unshare", "-m", "bash", "-c", "mount -t tmpfs tmpfs ns && exec \"$@\"", "bash"));
            else System.out.println("ServerTest: unshare -m does not work here: the mount namespace case is not run");
            int n = 0;
            for (List<String> w : wrappers) {
                String out = w.get(0).equals("unshare") ? "ns/paper" : "out" + n++;
                Ran ref = s.finish(s.client(s.work, w, true, "run", "--dt", "0.005", "--out", out));
                Map<String, byte[]> refFiles = Files.exists(s.work.resolve(out)) ? snapshot(s.work.resolve(out)) : Map.of();
                if (Files.exists(s.work.resolve(out))) ChildJvm.deleteTree(s.work.resolve(out));
                Ran r = s.finish(s.client(s.work, w, false, "run", "--dt", "0.005", "--out", out));
                String where = String.join(" ", w);
                assertTrue(r.how().startsWith("in-process (no_server"), where + ": " + r.how());
                assertEquals(ref.code(), r.code(), where + ": " + r.err());
                assertEquals(ServedAsInProcessTest.masked(withoutLog(ref.err())), ServedAsInProcessTest.masked(withoutLog(r.err())), where);
                assertEquals(ServedAsInProcessTest.masked(ref.out()), ServedAsInProcessTest.masked(r.out()), where);
                Map<String, byte[]> files = Files.exists(s.work.resolve(out)) ? snapshot(s.work.resolve(out)) : Map.of();
                assertEquals(refFiles.keySet(), files.keySet(), where);
                if (w.get(0).equals("bash")) assertEquals(1, r.code(), "a trace beyond 100 blocks fails: " + r.err());
                if (w.get(0).equals("unshare")) assertEquals(Map.of(), files, "nothing where the client's namespace did not write");
            }
            assertTrue(server.isAlive());
            for (ServerAdmin.Status st : ServerAdmin.servers(s.srv)) {
                if (st.field("pid").equals(Long.toString(server.pid()))) assertEquals("0", st.field("commands"), "the test's server ran none of them");
            }
        }
    }

    /** A log file's name differs between two runs: "(stack trace in ...)" without it. */
    private static String withoutLog(String err) {
        return err.replaceAll("\\(stack trace in [^)]*\\)", "(stack trace in LOG)");
    }

    /**
     * The battery's SIGSTOPped server hung every client for ever. Now a client waits at most 2 s
     * for it to start answering, then runs the command itself with one line saying why: a
     * client costs at most 3 s more than one that finds no server.
     */
    @Test
    void aStoppedServerCostsAClientAtMostThreeSeconds() throws Exception {
        try (Setup s = new Setup("stopped", "-Dhandsim.server.warmup=0", "-Dhandsim.server.answerMs=2000")) {
            Process server = s.server();
            long t0 = System.nanoTime();
            ChildJvm.Started ref = s.client(true, "fk", "--finger", "1", "--joints=0.1,0.2,0.3");
            waitFor(ref, "handsim-server in-process");
            double startUp = (System.nanoTime() - t0) / 1e9;
            Ran refDone = s.finish(ref);
            new ProcessBuilder("kill", "-STOP", Long.toString(server.pid())).start().waitFor();
            try {
                t0 = System.nanoTime();
                ChildJvm.Started c = s.client(false, "fk", "--finger", "1", "--joints=0.1,0.2,0.3");
                waitFor(c, "handsim-server in-process");
                double cost = (System.nanoTime() - t0) / 1e9 - startUp;
                Ran r = s.finish(c);
                assertEquals("in-process (timeout: no answer within 2000 ms)", r.how());
                assertEquals(0, r.code(), r.err());
                assertEquals(refDone.out(), r.out());
                assertEquals("handsim: the resident server did not serve this command (no answer within 2000 ms); running it here", r.err().trim());
                assertTrue(cost <= 3, "the stopped server cost the client " + cost + " s");
                System.out.println("ServerTest: a stopped server cost a client " + String.format(java.util.Locale.ROOT, "%.2f", cost) + " s");
            } finally {
                new ProcessBuilder("kill", "-CONT", Long.toString(server.pid())).start().waitFor();
            }
        }
    }

    /**
     * The battery's server asked to stop during its warm-up was alive 13 minutes later. A stop, a
     * changed build and a vanished install each end a warming server within a second, and its
     * lock, log, socket and warm-up folder go with it.
     */
    @Test
    void aStopAChangedBuildOrAVanishedInstallEndAWarmingServerWithinASecond() throws Exception {
        for (String how : List.of("stop", "build", "install")) {
            Path home = Files.createTempDirectory("handsim-home");
            for (String d : List.of("vrml", "scenarios")) Files.createSymbolicLink(home.resolve(d), TestPaths.root().resolve(d));
            try (Setup s = new Setup("warm-" + how, "-Dhandsim.home=" + home)) {
                Path jar = s.dir.resolve("extra.jar");
                writeJar(jar, 1);
                s.classPath = s.classPath + java.io.File.pathSeparator + jar;
                Process server = s.server();
                ServerAdmin.Status st = waitForState(s, server, "warming");
                String key = st.socket().getFileName().toString().replace(".sock", "");
                Path dir = st.socket().getParent();
                assertTrue(Files.isDirectory(Client.warmFolder(dir, key)) && Files.exists(Client.lockFile(dir, key)), "warming up beside its lock");
                long t0 = System.nanoTime();
                if (how.equals("stop")) assertTrue(ServerAdmin.stop(st.socket()));
                else if (how.equals("build")) writeJar(jar, 2);
                else ChildJvm.deleteTree(home);
                assertTrue(server.waitFor(10, TimeUnit.SECONDS), how + ": the server ends");
                double took = (System.nanoTime() - t0) / 1e9;
                System.out.println("ServerTest: " + how + " while warming up: the server ended in " + String.format(java.util.Locale.ROOT, "%.2f", took) + " s");
                assertTrue(took <= 1.0, how + ": ended " + took + " s after");
                for (Path f : List.of(st.socket(), Client.warmFolder(dir, key), Client.logFile(dir, key), Client.lockFile(dir, key))) {
                    assertFalse(Files.exists(f), how + ": " + f.getFileName() + " is removed with its server");
                }
            } finally {
                ChildJvm.deleteTree(home);
            }
        }
    }

    /** Waits until the server of {@code p} says it is in {@code state}. */
    private static ServerAdmin.Status waitForState(Setup s, Process p, String state) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < end) {
            for (ServerAdmin.Status st : ServerAdmin.servers(s.srv)) {
                if (st.field("pid").equals(Long.toString(p.pid())) && st.field("state").equals(state)) return st;
            }
            Thread.sleep(20);
        }
        throw new AssertionError("the server was not " + state + " within 60 s");
    }

    /**
     * The battery's 6 directories gave 6 servers of 507–704 MB. Commands in 6 folders now leave
     * at most 2 (the default): each new server stops the least recently used beyond that, which
     * take their files with them; the last two folders' servers are the ones left, and each
     * reports its memory.
     */
    @Test
    void commandsInSixFoldersLeaveAtMostTwoServers() throws Exception {
        try (Setup s = new Setup("six", "-Dhandsim.server.warmup=0")) {
            List<Path> folders = new ArrayList<>();
            for (int i = 0; i < 6; i++) {
                Path in = Files.createDirectories(s.dir.resolve("folder" + i));
                folders.add(in);
                Ran r = s.finish(s.client(in, List.of(), false, "fk", "--finger", "1", "--joints=0,0,0"));
                assertEquals(0, r.code(), r.err());
                assertTrue(r.how().startsWith("in-process (no_server"), r.how());
                long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(90);   // its server is up before the next folder's command
                while (System.nanoTime() < end && ServerAdmin.servers(s.srv).stream().noneMatch(st -> st.field("cwd").startsWith(in + " "))) Thread.sleep(50);
            }
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            List<ServerAdmin.Status> live = ServerAdmin.servers(s.srv);
            while (System.nanoTime() < end && live.size() > 2) {
                Thread.sleep(100);
                live = ServerAdmin.servers(s.srv);
            }
            assertEquals(2, live.size(), "servers left: " + live);
            List<String> where = new ArrayList<>();
            for (ServerAdmin.Status st : live) {
                where.add(st.field("cwd").substring(0, st.field("cwd").lastIndexOf(' ')));
                assertTrue(Long.parseLong(st.field("memory")) > (10L << 20), "memory " + st.field("memory"));
            }
            where.sort(null);
            assertEquals(List.of(folders.get(4).toString(), folders.get(5).toString()), where, "the two used last");
            Thread.sleep(1000);   // the stopped ones' exits
            List<String> files = new ArrayList<>();
            try (var st = Files.list(Client.effective(s.srv))) {
                st.forEach(p -> files.add(p.getFileName().toString()));
            }
            files.removeIf(f -> f.equals(Client.NOT_SERVED));
            assertEquals(6, files.size(), "a socket, lock and log for each of the two: " + files);
        }
    }

    /**
     * {@code handsim server stop} stops this install's servers; {@code --all} reaches every
     * server of the user in the folder, another install's too (a moved checkout's), and
     * {@code status} shows each one's memory and why the last command was not served.
     */
    @Test
    void stopAllReachesTheServersOfEveryInstall() throws Exception {
        Path home = Files.createTempDirectory("handsim-other-install");
        for (String d : List.of("vrml", "scenarios")) Files.createSymbolicLink(home.resolve(d), TestPaths.root().resolve(d));
        try (Setup s = new Setup("all", "-Dhandsim.server.warmup=0")) {
            Process ours = s.server();
            List<String> otherJvm = new ArrayList<>(s.jvmCommand(WatchedServer.class.getName()));
            otherJvm.replaceAll(o -> o.startsWith("-Dhandsim.home=") ? "-Dhandsim.home=" + home : o.startsWith("-Dhandsim.server.jvm=")
                ? o.replace("-Dhandsim.home=" + TestPaths.root(), "-Dhandsim.home=" + home) : o);
            Process other = new ProcessBuilder(otherJvm).directory(s.work.toFile()).redirectErrorStream(true)
                .redirectOutput(s.dir.resolve("other.log").toFile()).start();
            s.started.add(other);
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(90);
            while (System.nanoTime() < end && ServerAdmin.servers(s.srv).size() < 2) Thread.sleep(50);
            assertEquals(2, ServerAdmin.servers(s.srv).size(), Files.readString(s.dir.resolve("other.log")));
            Ran status = s.run(true, "server", "status", "--all");
            assertEquals(0, status.code(), status.err());
            assertEquals(2, status.out().split("\n").length, status.out());
            assertTrue(status.out().matches("(?s)pid [0-9]+: idle, working directory .*, [0-9]+ MB resident, log .*"), status.out());
            Ran stop = s.run(true, "server", "stop");
            assertEquals("stopping pid " + ours.pid() + " (working directory " + s.work + ")", stop.out().trim());
            assertTrue(ours.waitFor(30, TimeUnit.SECONDS));
            assertTrue(other.isAlive(), "another install's server stays");
            stop = s.run(true, "server", "stop", "--all");
            assertEquals("stopping pid " + other.pid() + " (working directory " + s.work + ")", stop.out().trim());
            assertTrue(other.waitFor(30, TimeUnit.SECONDS), "--all reaches it");
        } finally {
            ChildJvm.deleteTree(home);
        }
    }

    /** An exit 1 the command reports (a sweep whose run fails) leaves nothing in doubt: the same server serves the next. */
    @Test
    void aFailingCommandDoesNotEndTheServer() throws Exception {
        try (Setup s = new Setup("exit1", "-Dhandsim.server.warmup=0")) {
            Path sweep = Files.writeString(s.work.resolve("sweep.json"), "{\"name\": \"s\", \"base\": \"" + TestPaths.root().resolve("scenarios/paper-breakaway.json")
                + "\", \"runs\": [{\"label\": \"a\", \"set\": {\"object.file\": \"missing.wrl\"}}]}");
            Process server = s.server();
            Ran r = s.run(false, "sweep", sweep.toString(), "--out", "sw");
            assertEquals("served", r.how());
            assertEquals(1, r.code(), r.err());
            Ran next = s.run(false, "fk", "--finger", "1", "--joints=0,0,0");
            assertEquals("served", next.how());
            assertTrue(server.isAlive(), "the same server");
        }
    }

    /**
     * A servers' folder so deep that a socket in it passes the JDK's 106 bytes (the battery's
     * deep checkout, a long cache path): the servers use a short private folder named after it,
     * mode 700, and serve as usual; it goes when they do.
     */
    @Test
    void aFolderTooDeepForASocketUsesAShortPrivateOne() throws Exception {
        try (Setup s = new Setup("deep")) {
            Path deep = s.dir.resolve("d".repeat(120)).resolve("srv");
            s.jvm.replaceAll(o -> o.startsWith("-Dhandsim.server.dir=") ? "-Dhandsim.server.dir=" + deep : o);
            s.jvm.add("-Dhandsim.server.warmup=0");
            Path shortFolder = Client.effective(deep);
            assertNotEquals(deep, shortFolder);
            assertTrue(shortFolder.toString().length() < 40, shortFolder.toString());
            Process server = new ProcessBuilder(s.jvmCommand(Server.class.getName())).directory(s.work.toFile())
                .redirectErrorStream(true).redirectOutput(s.dir.resolve("deep-server.log").toFile()).start();
            s.started.add(server);
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(90);
            while (System.nanoTime() < end && ServerAdmin.servers(deep).isEmpty()) Thread.sleep(50);
            assertEquals(1, ServerAdmin.servers(deep).size(), Files.readString(s.dir.resolve("deep-server.log")));
            assertEquals("rwx------", java.nio.file.attribute.PosixFilePermissions.toString(Files.getPosixFilePermissions(shortFolder)));
            Ran r = s.run(false, "fk", "--finger", "1", "--joints=0,0,0");
            assertEquals("served", r.how(), r.err());
            assertTrue(ServerAdmin.stop(ServerAdmin.servers(deep).get(0).socket()));
            assertTrue(server.waitFor(30, TimeUnit.SECONDS));
            assertFalse(Files.exists(shortFolder), "the short folder goes with its last server");
        }
    }

    /**
     * The battery's listener that sends a 2^31-1 byte frame killed the client with an uncaught
     * OutOfMemoryError. Frames are bounded: the client ends with one line naming the frame and
     * exit 1, in its usual memory.
     */
    @Test
    void aFrameBeyondTheLimitEndsTheClientNotItsMemory() throws Exception {
        try (Setup s = new Setup("frame", "-Dhandsim.server.warmup=0")) {
            Process server = s.server();
            Path socket = ServerAdmin.servers(s.srv).get(0).socket();
            ServerAdmin.stop(socket);
            assertTrue(server.waitFor(30, TimeUnit.SECONDS));
            assertEquals(null, Client.unsafe(socket.getParent(), true), "the folder again (a short stand-in goes with its last server)");
            try (java.nio.channels.ServerSocketChannel fake = java.nio.channels.ServerSocketChannel.open(StandardProtocolFamily.UNIX)) {
                fake.bind(UnixDomainSocketAddress.of(socket));
                Thread t = new Thread(() -> {
                    try (SocketChannel c = fake.accept()) {
                        DataOutputStream out = new DataOutputStream(Client.out(c));
                        out.writeByte(Client.ACCEPTED);
                        out.writeByte(Client.OUT);
                        out.writeInt(Integer.MAX_VALUE);
                        out.flush();
                        Thread.sleep(5000);
                    } catch (Exception e) {
                        // the client went
                    }
                });
                t.setDaemon(true);
                t.start();
                Ran r = s.run(false, "fk", "--finger", "1", "--joints=0,0,0");
                assertEquals("served", r.how());
                assertEquals(1, r.code(), r.err());
                assertTrue(r.err().startsWith("handsim: the resident server sent a frame of 2147483647 bytes (at most 1048576)"), r.err());
                assertFalse(r.err().contains("OutOfMemoryError"), r.err());
            } finally {
                Files.deleteIfExists(socket);
            }
        }
    }

    /** The identity a server serves (its status after the state lines). */
    private static String identityOf(Path srv, Path socket) throws Exception {
        for (ServerAdmin.Status s : ServerAdmin.servers(srv)) {
            if (!s.socket().equals(socket)) continue;
            try (SocketChannel ch = SocketChannel.open(StandardProtocolFamily.UNIX)) {
                ch.connect(UnixDomainSocketAddress.of(socket));
                DataOutputStream out = new DataOutputStream(Client.out(ch));
                out.writeInt(Client.MAGIC);
                out.writeByte(Client.STATUS);
                String text = Client.readString(new DataInputStream(Client.in(ch)));
                return text.substring(text.indexOf("handsim server 1\n"));
            }
        }
        throw new AssertionError("no server at " + socket);
    }

    /** Sends a RUN request of {@code identity} for {@code fk}; "refused: REASON", "accepted", "busy", or null if nobody listens. */
    private static String request(Path socket, String identity) {
        try (SocketChannel ch = SocketChannel.open(StandardProtocolFamily.UNIX)) {
            ch.connect(UnixDomainSocketAddress.of(socket));
            DataOutputStream out = new DataOutputStream(Client.out(ch));
            DataInputStream in = new DataInputStream(Client.in(ch));
            out.writeInt(Client.MAGIC);
            out.writeByte(Client.RUN);
            Client.writeString(out, identity);
            out.writeBoolean(false);
            Client.writeString(out, "");
            Client.writeString(out, "");
            out.writeInt(1);
            Client.writeString(out, "fk");
            int a = in.read();
            if (a == Client.REFUSED) return "refused: " + Client.readString(in).replaceFirst("^another identity: .*", "the build changed (identity)");
            return a == Client.ACCEPTED ? "accepted" : a == Client.BUSY ? "busy" : null;
        } catch (java.io.IOException e) {
            return null;
        }
    }

    private static void writeJar(Path jar, int entries) throws Exception {
        try (JarOutputStream j = new JarOutputStream(Files.newOutputStream(jar))) {
            for (int i = 0; i < entries; i++) {
                j.putNextEntry(new ZipEntry("handsim-test/" + i + ".txt"));
                j.write(("entry " + i).getBytes(StandardCharsets.UTF_8));
                j.closeEntry();
            }
        }
    }

    private static void waitFor(ChildJvm.Started c, String text) throws Exception {
        long end = System.nanoTime() + TimeUnit.MINUTES.toNanos(3);
        while (System.nanoTime() < end) {
            if (c.errText().contains(text)) return;
            if (!c.process().isAlive()) fail("the client ended before '" + text.trim() + "': " + c.errText());
            Thread.sleep(20);
        }
        fail("'" + text.trim() + "' not seen within 3 minutes: " + c.errText());
    }

    /** Waits until the server says it is idle again (its command ended). */
    private static void waitIdle(Setup s, Process server) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < end) {
            for (ServerAdmin.Status st : ServerAdmin.servers(s.srv)) {
                if (st.field("pid").equals(Long.toString(server.pid())) && st.field("state").equals("idle")) return;
            }
            Thread.sleep(50);
        }
        fail("the server did not end the cancelled command within 60 s");
    }

    private static String svg(Path f) throws Exception {
        return Files.readString(f).replaceAll("_[0-9]+clip-", "_Nclip-");
    }

    private static String lastLine(String text) {
        String[] l = text.trim().split("\n");
        return l[l.length - 1];
    }

    /** summary.json without the keys that are timings. */
    @SuppressWarnings("unchecked")
    private static Object withoutTimes(Path summary) throws Exception {
        Map<String, Object> m = new LinkedHashMap<>((Map<String, Object>) Json.parse("summary.json", Files.readString(summary)));
        for (String k : List.of("wall_time_s", "steps_per_s", "realtime_factor", "setup_time_s", "phase_times")) {
            assertNotNull(m.remove(k), "summary.json has " + k);
        }
        return m;
    }

    private static Map<String, byte[]> snapshot(Path out) throws Exception {
        Map<String, byte[]> m = new java.util.TreeMap<>();
        try (var st = Files.list(out)) {
            for (Path p : (Iterable<Path>) st::iterator) if (Files.isRegularFile(p)) m.put(p.getFileName().toString(), Files.readAllBytes(p));
        }
        return m;
    }

    private static boolean same(Map<String, byte[]> a, Map<String, byte[]> b) {
        if (!a.keySet().equals(b.keySet())) return false;
        for (String k : a.keySet()) if (!Arrays.equals(a.get(k), b.get(k))) return false;
        return true;
    }

    private static List<String> hidden(Path out) throws Exception {
        List<String> h = new ArrayList<>();
        try (var st = Files.list(out)) {
            for (Path p : (Iterable<Path>) st::iterator) if (p.getFileName().toString().startsWith(".")) h.add(p.getFileName().toString());
        }
        h.sort(null);
        return h;
    }
}
