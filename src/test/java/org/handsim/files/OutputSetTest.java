package org.handsim.files;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * An output set is published whole or not at all: the tables, then the charts, then the files of
 * the previous set the new one lacks are removed, the marker last (the old marker goes first); a
 * failure before publication leaves the folder as it was; files that are not the set's are never
 * touched; a second writer waits for the first; a publication killed half-way is completed by
 * the next writer, an unfinished set is removed.
 */
class OutputSetTest {
    static final OutputSet.Layout RUN = new OutputSet.Layout("summary.json", "trace\\.csv|summary\\.json|fig[78]_finger[1-3]\\.(png|svg)|best/[0-9][0-9]\\.json", "best");

    static Map<String, String> contents(Path dir) throws Exception {
        Map<String, String> m = new TreeMap<>();
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                if (Files.isRegularFile(p)) m.put(dir.relativize(p).toString(), Files.readString(p));
            }
        }
        return m;
    }

    static void write(Path dir, String... nameAndText) throws Exception {
        for (int i = 0; i < nameAndText.length; i += 2) {
            Path p = dir.resolve(nameAndText[i]);
            Files.createDirectories(p.getParent());
            Files.writeString(p, nameAndText[i + 1]);
        }
    }

    static Path oldSet() throws Exception {
        Path dir = Files.createTempDirectory("handsim-set");
        write(dir, "trace.csv", "old trace", "summary.json", "old summary", "fig7_finger1.png", "old chart 1",
            "fig7_finger3.png", "old chart 3", "best/02.json", "old best 2", "notes.txt", "the user's", "best/readme.txt", "the user's too");
        return dir;
    }

    @Test
    void publishesTablesThenChartsThenRemovesTheStaleThenTheMarker() throws Exception {
        Path dir = oldSet();
        try {
            try (OutputSet set = OutputSet.open(dir, RUN, null)) {
                write(set.dir(), "summary.json", "new summary", "trace.csv", "new trace", "fig7_finger3.png", "new chart 3", "best/01.json", "new best 1");
                List<String> steps = new ArrayList<>();
                for (String[] s : set.plannedSteps()) steps.add(s[0] + " " + s[1]);
                assertEquals(List.of("clear summary.json", "move best/01.json", "move trace.csv", "move fig7_finger3.png",
                    "drop best/02.json", "drop fig7_finger1.png", "move summary.json"), steps);
                assertEquals(Map.of("trace.csv", "old trace", "summary.json", "old summary", "fig7_finger1.png", "old chart 1",
                    "fig7_finger3.png", "old chart 3", "best/02.json", "old best 2", "notes.txt", "the user's", "best/readme.txt", "the user's too"),
                    withoutWork(contents(dir)), "nothing published before publish()");
                set.publish();
            }
            assertEquals(Map.of("trace.csv", "new trace", "summary.json", "new summary", "fig7_finger3.png", "new chart 3",
                "best/01.json", "new best 1", "notes.txt", "the user's", "best/readme.txt", "the user's too"), contents(dir));
        } finally {
            Folders.deleteTree(dir);
        }
    }

    static Map<String, String> withoutWork(Map<String, String> m) {
        m.keySet().removeIf(k -> k.startsWith(OutputSet.WORK));
        return m;
    }

    /** An error after the first file (the run fails, the disk fills): the previous set stays exactly as it was, nothing added. */
    @Test
    void aFailureBeforePublicationLeavesThePreviousSet() throws Exception {
        Path dir = oldSet();
        try {
            Map<String, String> before = contents(dir);
            assertThrows(IllegalStateException.class, () -> {
                try (OutputSet set = OutputSet.open(dir, RUN, null)) {
                    write(set.dir(), "trace.csv", "new trace", "fig7_finger3.png", "new chart");
                    throw new IllegalStateException("the run failed after its first files");
                }
            });
            assertEquals(before, contents(dir));
            try (Stream<Path> s = Files.list(dir)) {
                assertFalse(s.anyMatch(p -> p.getFileName().toString().startsWith(".")), "no temporary files");
            }
            Path fresh = dir.resolve("new/deeper");
            try (OutputSet set = OutputSet.open(fresh, RUN, null)) {
                write(set.dir(), "trace.csv", "t");
            }
            assertFalse(Files.exists(dir.resolve("new")), "folders the set created are removed when nothing was published");
        } finally {
            Folders.deleteTree(dir);
        }
    }

    @Test
    void aMemberThatIsAFolderOrTheFolderThatIsAFileIsRefused() throws Exception {
        Path dir = Files.createTempDirectory("handsim-set");
        try {
            Files.createDirectories(dir.resolve("out/trace.csv"));
            OutputSet.Refused e = assertThrows(OutputSet.Refused.class, () -> OutputSet.open(dir.resolve("out"), RUN, null));
            assertTrue(e.getMessage().contains("trace.csv is a folder"), e.getMessage());
            assertEquals(List.of("trace.csv"), List.of(dir.resolve("out").toFile().list()), "nothing added");
            Files.writeString(dir.resolve("file"), "x");
            e = assertThrows(OutputSet.Refused.class, () -> OutputSet.open(dir.resolve("file"), RUN, null));
            assertEquals("exists and is not a folder", e.getMessage());
        } finally {
            Folders.deleteTree(dir);
        }
    }

    /** A second writer of the folder (here another thread) is told once and waits until the first is done. */
    @Test
    void aSecondWriterWaitsForTheFirst() throws Exception {
        Path dir = Files.createTempDirectory("handsim-set");
        try {
            List<String> told = new CopyOnWriteArrayList<>();
            CompletableFuture<String> second;
            try (OutputSet first = OutputSet.open(dir, RUN, told::add)) {
                write(first.dir(), "trace.csv", "first", "summary.json", "first");
                second = CompletableFuture.supplyAsync(() -> {
                    try (OutputSet s = OutputSet.open(dir, RUN, told::add)) {
                        String seen = Files.readString(dir.resolve("summary.json"));
                        write(s.dir(), "trace.csv", "second", "summary.json", "second");
                        s.publish();
                        return seen;
                    } catch (Exception e) {
                        return "failed: " + e;
                    }
                });
                long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
                while (told.isEmpty() && System.nanoTime() < end) Thread.sleep(10);
                Thread.sleep(300);
                assertFalse(second.isDone(), "the second waits");
                first.publish();
            }
            assertEquals("first", second.get(30, TimeUnit.SECONDS), "the second starts after the first's whole set is there");
            assertEquals(1, told.size(), told.toString());
            assertTrue(told.get(0).endsWith("waiting for it"), told.get(0));
            assertEquals(Map.of("trace.csv", "second", "summary.json", "second"), contents(dir));
        } finally {
            Folders.deleteTree(dir);
        }
    }

    /** SIGKILL during the renames: the manifest is there, the marker not; the next writer completes the publication. */
    @Test
    void theNextWriterCompletesAKilledPublicationAndRemovesAnUnfinishedSet() throws Exception {
        Path dir = oldSet();
        try {
            long dead = 4_000_000;
            while (ProcessHandle.of(dead).isPresent()) dead++;
            Path work = dir.resolve(OutputSet.WORK);
            Path killed = work.resolve("stage-" + dead + "-1");
            // killed after: clear summary.json, move trace.csv; before: move fig7_finger3.png, drop fig7_finger1.png, move summary.json
            write(killed, "fig7_finger3.png", "new chart 3", "summary.json", "new summary",
                ".publish", "clear summary.json\nmove trace.csv\nmove fig7_finger3.png\ndrop fig7_finger1.png\nmove summary.json\n");
            Files.delete(dir.resolve("summary.json"));
            Files.writeString(dir.resolve("trace.csv"), "new trace");
            Path unfinished = work.resolve("stage-" + dead + "-2");
            write(unfinished, "trace.csv", "never published");
            write(work, "lock", "pid " + dead + "\n");
            OutputSet.recover(dir);
            assertEquals(Map.of("trace.csv", "new trace", "summary.json", "new summary", "fig7_finger3.png", "new chart 3",
                "best/02.json", "old best 2", "notes.txt", "the user's", "best/readme.txt", "the user's too"), contents(dir));
            assertFalse(Files.exists(work), "nothing left");
            OutputSet.recover(dir);   // nothing to do: nothing changes
            assertEquals(6, contents(dir).size());
        } finally {
            Folders.deleteTree(dir);
        }
    }

    /** A manifest that names a path outside the folder is refused, not followed. */
    @Test
    void aManifestCannotReachOutsideTheFolder() throws Exception {
        Path top = Files.createTempDirectory("handsim-set");
        try {
            Path dir = Files.createDirectories(top.resolve("out"));
            Files.writeString(top.resolve("victim.txt"), "keep");
            write(dir.resolve(OutputSet.WORK).resolve("stage-4000000-9"), ".publish", "drop ../victim.txt\n");
            assertThrows(java.io.IOException.class, () -> OutputSet.recover(dir));
            assertEquals("keep", Files.readString(top.resolve("victim.txt")));
        } finally {
            Folders.deleteTree(top);
        }
    }

    /** Everything under {@code dir}, links listed as links (never followed): what a test compares before and after. */
    static Map<String, String> everything(Path dir) throws Exception {
        Map<String, String> m = new TreeMap<>();
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                String rel = dir.relativize(p).toString();
                if (Files.isSymbolicLink(p)) m.put(rel, "-> " + Files.readSymbolicLink(p));
                else if (Files.isRegularFile(p)) m.put(rel, Files.readString(p));
                else m.put(rel, "<folder>");
            }
        }
        return m;
    }

    /**
     * The battery's crafted manifest: a killed writer's private folder whose manifest moves
     * {@code sub/evil.txt} and drops {@code sub/keep.txt}, {@code sub} a link to a folder beside
     * the output folder. Recovery refuses it (with the manifest's folder named) before any step
     * acts, and nothing outside changes; the same with the link in the private folder, and with
     * names that climb out.
     */
    @Test
    void aCraftedManifestChangesNothingOutsideTheFolder() throws Exception {
        Path top = Files.createTempDirectory("handsim-set");
        try {
            Path victim = Files.createDirectories(top.resolve("victim"));
            write(victim, "keep.txt", "keep", "evil.txt", "the victim's own");
            Path dir = Files.createDirectories(top.resolve("out"));
            Path stage = dir.resolve(OutputSet.WORK).resolve("stage-4000000-1");
            write(stage, "sub/evil.txt", "planted", ".publish", "move sub/evil.txt\ndrop sub/keep.txt\n");
            Files.createSymbolicLink(dir.resolve("sub"), Path.of("../victim"));
            Map<String, String> outside = everything(victim);
            OutputSet.Refused e = assertThrows(OutputSet.Refused.class, () -> OutputSet.recover(dir));
            assertTrue(e.getMessage().startsWith("not completing the publication a stopped writer left in " + stage + ": "
                + dir.resolve("sub") + " is a symbolic link"), e.getMessage());
            assertEquals(outside, everything(victim));
            // the link inside the private folder instead: the victim's file would be moved in
            Folders.deleteTree(dir);
            Files.createDirectories(stage);
            write(stage, ".publish", "move sub/evil.txt\n");
            Files.createSymbolicLink(stage.resolve("sub"), top.resolve("victim"));
            assertThrows(OutputSet.Refused.class, () -> OutputSet.recover(dir));
            assertEquals(outside, everything(victim));
            // names that climb out, an unknown step: refused whole, the good first step not applied either
            for (String manifest : new String[] {"move a.txt\ndrop ../victim/keep.txt\n", "move a.txt\ndrop /tmp/x\n",
                "move a.txt\ndrop ./a.txt\n", "move a.txt\ndrop a//b\n", "move a.txt\nrmdir a\n", "move a.txt\ndrop\n"}) {
                Folders.deleteTree(dir);
                write(stage, ".publish", manifest, "a.txt", "a");
                assertThrows(OutputSet.Refused.class, () -> OutputSet.recover(dir), manifest);
                assertFalse(Files.exists(dir.resolve("a.txt")), manifest);
                assertEquals(outside, everything(victim));
            }
        } finally {
            Folders.deleteTree(top);
        }
    }

    /**
     * The battery's symlinked {@code best/}: a subfolder of the set that is a link is refused when
     * the set is opened, and a link put there after that is refused when it is published; the
     * files it leads to stay as they were.
     */
    @Test
    void aLinkedSubfolderOfTheSetIsNeverWrittenThrough() throws Exception {
        Path top = Files.createTempDirectory("handsim-set");
        try {
            Path victim = Files.createDirectories(top.resolve("victim"));
            write(victim, "01.json", "the victim's");
            Path dir = Files.createDirectories(top.resolve("out"));
            Files.createSymbolicLink(dir.resolve("best"), Path.of("../victim"));
            Map<String, String> outside = everything(victim);
            OutputSet.Refused e = assertThrows(OutputSet.Refused.class, () -> OutputSet.open(dir, RUN, null));
            assertEquals(dir.resolve("best") + " is a symbolic link: an output set is never written through it (it could lead out of"
                + " the output folder)", e.getMessage());
            Files.delete(dir.resolve("best"));
            try (OutputSet set = OutputSet.open(dir, RUN, null)) {
                write(set.dir(), "summary.json", "s", "best/01.json", "new 1", "best/02.json", "new 2");
                Files.createSymbolicLink(dir.resolve("best"), Path.of("../victim"));   // planted while the command ran
                assertThrows(OutputSet.Refused.class, set::publish);
            }
            assertEquals(outside, everything(victim));
            assertEquals(Map.of("", "<folder>", "best", "-> ../victim"), everything(dir), "nothing published, nothing left");
        } finally {
            Folders.deleteTree(top);
        }
    }
}
