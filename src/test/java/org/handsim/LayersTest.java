package org.handsim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The rooms and their arrows, checked: the module table of docs/DESIGN.md says which room may
 * use which (rows from the bottom up, each naming only rooms in rows above it, so the arrows
 * point one way and cannot form a cycle), and no source file of a room names a room its row does
 * not allow, by an import or a fully qualified name in code (comments and strings aside).
 *
 * <p>Our own check rather than ArchUnit's layered architecture: the table is the one place the
 * rules live, and reading 400 source files costs some 0.2 s of the quick suite where ArchUnit's
 * class import took seconds (docs/DECISIONS.md, "The layer check").
 */
class LayersTest {
    private static final Path ROOT = TestPaths.root();
    private static final Pattern ROW = Pattern.compile("^\\| `([a-z]+)` \\|.*\\| ([^|]*) \\|\\s*$");
    private static final Pattern NAME = Pattern.compile("`([a-z]+)`");
    private static final Pattern USE = Pattern.compile("\\borg\\.handsim\\.([a-z][a-z0-9]*)\\b");
    private static final String EVERYTHING = "everything listed above it";

    /** The rooms of the table, bottom up, each with the rooms it may use. */
    static Map<String, Set<String>> table(Path design) throws IOException {
        List<String> lines = Files.readAllLines(design, StandardCharsets.UTF_8);
        int start = -1;
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).startsWith("## Modules")) start = i;
        }
        assertTrue(start >= 0, design + ": no \"## Modules\" section");
        Map<String, Set<String>> rooms = new LinkedHashMap<>();
        for (int i = start + 1; i < lines.size() && !lines.get(i).startsWith("## "); i++) {
            Matcher m = ROW.matcher(lines.get(i));
            if (!m.matches()) continue;
            String room = m.group(1), cell = m.group(2);
            Set<String> may = new LinkedHashSet<>();
            String named = cell;
            if (cell.contains(EVERYTHING)) {
                may.addAll(rooms.keySet());
                int but = cell.indexOf(" but ");
                named = but >= 0 ? cell.substring(but) : "";
                Matcher x = NAME.matcher(named);
                while (x.find()) may.remove(x.group(1));
                named = "";
            }
            Matcher x = NAME.matcher(named);
            while (x.find()) {
                String other = x.group(1);
                if (!rooms.containsKey(other)) {
                    throw new AssertionError(design + ":" + (i + 1) + ": `" + room + "` may use `" + other
                        + "`, which is not a room listed above it: the table's arrows must point down");
                }
                may.add(other);
            }
            rooms.put(room, may);
        }
        return rooms;
    }

    /** Every place a source file under {@code sources} (org/handsim/ROOM/...) names a room its table row does not allow. */
    static List<String> violations(Path sources, Map<String, Set<String>> rooms) throws IOException {
        List<String> found = new ArrayList<>();
        Path base = sources.resolve("org/handsim");
        List<Path> files;
        try (Stream<Path> s = Files.walk(base)) {
            files = s.filter(p -> p.toString().endsWith(".java")).sorted().toList();
        }
        for (Path f : files) {
            Path rel = base.relativize(f);
            if (rel.getNameCount() < 2) continue;   // a file of the root package
            String room = rel.getName(0).toString();
            Set<String> may = rooms.get(room);
            if (may == null) {
                found.add(sources.relativize(f) + ": room `" + room + "` has no row in the module table");
                continue;
            }
            String code = codeOnly(Files.readString(f, StandardCharsets.UTF_8));
            Matcher m = USE.matcher(code);
            Set<String> reported = new TreeSet<>();
            while (m.find()) {
                String other = m.group(1);
                if (other.equals(room) || may.contains(other) || !reported.add(other)) continue;
                int line = 1;
                for (int i = 0; i < m.start(); i++) if (code.charAt(i) == '\n') line++;
                found.add(sources.relativize(f) + ":" + line + ": `" + room + "` uses `" + other + "`, which its row does not allow"
                    + (rooms.containsKey(other) && rooms.get(other).contains(room) ? " (a cycle: `" + other + "` uses `" + room + "`)" : ""));
            }
        }
        return found;
    }

    /** The source with comments and string and character literals blanked (line breaks kept). */
    static String codeOnly(String src) {
        StringBuilder out = new StringBuilder(src.length());
        int n = src.length();
        for (int i = 0; i < n; i++) {
            char c = src.charAt(i);
            if (c == '/' && i + 1 < n && src.charAt(i + 1) == '/') {
                while (i < n && src.charAt(i) != '\n') i++;
                if (i < n) out.append('\n');
            } else if (c == '/' && i + 1 < n && src.charAt(i + 1) == '*') {
                int end = src.indexOf("*/", i + 2);
                end = end < 0 ? n : end + 2;
                for (int j = i; j < end; j++) if (src.charAt(j) == '\n') out.append('\n');
                i = end - 1;
            } else if (c == '"' && src.startsWith("\"\"\"", i)) {
                int end = src.indexOf("\"\"\"", i + 3);
                end = end < 0 ? n : end + 3;
                for (int j = i; j < end; j++) if (src.charAt(j) == '\n') out.append('\n');
                out.append("\"\"");
                i = end - 1;
            } else if (c == '"' || c == '\'') {
                int j = i + 1;
                while (j < n && src.charAt(j) != c && src.charAt(j) != '\n') j += src.charAt(j) == '\\' ? 2 : 1;
                out.append(c).append(c);
                i = Math.min(j, n - 1);
            } else {
                out.append(c);
            }
        }
        return out.toString();
    }

    @Test
    void everyRoomUsesOnlyWhatTheModuleTableAllows() throws IOException {
        Map<String, Set<String>> rooms = table(ROOT.resolve("docs/DESIGN.md"));
        assertEquals(List.of(), violations(ROOT.resolve("src/main/java"), rooms));
    }

    @Test
    void everyRoomHasARowAndSaysWhatItHolds() throws IOException {
        Map<String, Set<String>> rooms = table(ROOT.resolve("docs/DESIGN.md"));
        List<String> missing = new ArrayList<>();
        try (Stream<Path> s = Files.list(ROOT.resolve("src/main/java/org/handsim"))) {
            for (Path dir : s.filter(Files::isDirectory).sorted().toList()) {
                String room = dir.getFileName().toString();
                if (!rooms.containsKey(room)) missing.add(room + ": no row in docs/DESIGN.md's module table");
                if (!Files.exists(dir.resolve("package-info.java"))) missing.add(room + ": no package-info.java");
            }
        }
        assertEquals(List.of(), missing);
    }

    /**
     * Each room's package-info says what it may use in a paragraph "May use ...": the rooms the
     * table's row names, or "every room below it" with the same exceptions.
     */
    @Test
    void everyPackageInfoSaysWhatItsRowAllows() throws IOException {
        List<String> lines = Files.readAllLines(ROOT.resolve("docs/DESIGN.md"), StandardCharsets.UTF_8);
        Map<String, String> cells = new LinkedHashMap<>();
        for (String l : lines) {
            Matcher m = ROW.matcher(l);
            if (m.matches()) cells.putIfAbsent(m.group(1), m.group(2));
        }
        List<String> wrong = new ArrayList<>();
        for (Map.Entry<String, String> e : cells.entrySet()) {
            Path info = ROOT.resolve("src/main/java/org/handsim/" + e.getKey() + "/package-info.java");
            if (!Files.exists(info)) continue;   // everyRoomHasARowAndSaysWhatItHolds names it
            String text = Files.readString(info, StandardCharsets.UTF_8).replaceAll("\\s*\\n\\s*\\*\\s*", " ");
            Matcher may = Pattern.compile("<p>May use (.*?)docs/DESIGN\\.md, \"Modules\"\\)").matcher(text);
            if (!may.find()) {
                wrong.add(e.getKey() + ": package-info has no \"<p>May use ... (docs/DESIGN.md, \"Modules\")\"");
                continue;
            }
            String says = may.group(1), cell = e.getValue();
            boolean everything = cell.contains(EVERYTHING);
            Set<String> named = new TreeSet<>(), allowed = new TreeSet<>();
            Matcher c = Pattern.compile("\\{@code ([a-z]+)\\}").matcher(everything && says.contains(" but ") ? says.substring(says.indexOf(" but ")) : everything ? "" : says);
            while (c.find()) named.add(c.group(1));
            Matcher x = NAME.matcher(everything ? (cell.contains(" but ") ? cell.substring(cell.indexOf(" but ")) : "") : cell);
            while (x.find()) allowed.add(x.group(1));
            if (everything != says.startsWith("every room below it") || !named.equals(allowed)) {
                wrong.add(e.getKey() + ": package-info says it may use " + says.trim() + "; the table says " + cell.trim());
            }
        }
        assertEquals(List.of(), wrong);
    }

    @Test
    void anUpwardImportIsCaught() throws IOException {
        Map<String, Set<String>> rooms = table(ROOT.resolve("docs/DESIGN.md"));
        List<String> found = violations(ROOT.resolve("src/test/resources/layers/upward"), rooms);
        assertEquals(List.of("org/handsim/math/Upward.java:3: `math` uses `model`, which its row does not allow"
            + " (a cycle: `model` uses `math`)"), found);
    }

    @Test
    void aFullyQualifiedNameCountsLikeAnImport() throws IOException {
        Map<String, Set<String>> rooms = table(ROOT.resolve("docs/DESIGN.md"));
        List<String> found = violations(ROOT.resolve("src/test/resources/layers/cycle"), rooms);
        assertEquals(List.of("org/handsim/scenario/Back.java:5: `scenario` uses `model`, which its row does not allow"
            + " (a cycle: `model` uses `scenario`)"), found);
    }

    @Test
    void aTableWhoseArrowPointsUpIsRefused() throws IOException {
        Path dir = Files.createTempDirectory("layers");
        try {
            Path design = dir.resolve("DESIGN.md");
            Files.writeString(design, "## Modules\n\n| package | owns | may use |\n|---|---|---|\n"
                + "| `math` | vectors | `text` |\n| `text` | formats | – |\n");
            AssertionError e = org.junit.jupiter.api.Assertions.assertThrows(AssertionError.class, () -> table(design));
            assertTrue(e.getMessage().contains("`math` may use `text`, which is not a room listed above it"), e.getMessage());
        } finally {
            org.handsim.cli.ChildJvm.deleteTree(dir);
        }
    }

    @Test
    void commentsAndStringsAreNotUses() {
        String src = "package org.handsim.math;\n/** {@link org.handsim.model.HandModel} */\n// org.handsim.gui\n"
            + "class A { String s = \"org.handsim.cli.HandSim\"; char c = '\"'; Object o = org.handsim.text.Decimal.class; }\n";
        String code = codeOnly(src);
        Matcher m = USE.matcher(code);
        List<String> uses = new ArrayList<>();
        while (m.find()) uses.add(m.group(1));
        assertEquals(List.of("math", "text"), uses);
        assertEquals(src.split("\n", -1).length, code.split("\n", -1).length);
    }
}
