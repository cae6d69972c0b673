package org.handsim.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.handsim.TestPaths;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * A file that does not parse as a model is never quoted beyond its name and the position of the
 * first bad token: a scenario whose object is /etc/shadow once printed its first line
 * ({@code found 'root:*:20228:0:99999:7:::'}). The rule (README, "Exit codes"): text from a file
 * is quoted only once the file is recognised as a model of its type — VRML97 by its header line,
 * ASCII STL by {@code solid}, binary STL by a size that fits its triangle count, OBJ by a first
 * known statement — and then only the bad token, escaped and shortened to 60 characters.
 */
class NotAModelIsNotQuotedTest {
    static Path dir;
    static final String SECRET = "root:*:20228:0:99999:7:::\nsecret-token-XYZ\n";

    @BeforeAll
    static void folder() throws Exception {
        dir = Files.createTempDirectory("handsim-quote");
    }

    @AfterAll
    static void clean() throws Exception {
        ChildJvm.deleteTree(dir);
    }

    static void quotesNothingOf(String content, CliTesting.Run r, String file) {
        assertEquals(3, r.code(), r.err());
        assertTrue(r.err().contains(file), r.err());
        for (String line : content.split("\n")) {
            for (String word : line.split("[:/,\\s]+")) {
                if (word.length() >= 3 && !word.matches("[0-9]+")) assertFalse(r.err().contains(word), "'" + word + "' quoted: " + r.err());
            }
        }
        assertFalse(r.err().contains("20228") || r.err().contains("99999"), r.err());
    }

    @Test
    void aSecretFileUnderEveryModelNameIsNotQuoted() throws Exception {
        for (String ext : new String[] {"wrl", "wrz", "obj", "stl", "json"}) {
            Path f = Files.writeString(dir.resolve("secret." + ext), SECRET);
            String name = f.toString();
            if (!ext.equals("json")) {
                quotesNothingOf(SECRET, CliTesting.run("mesh", name), name);
                quotesNothingOf(SECRET, CliTesting.run("collide", name, name), name);
                quotesNothingOf(SECRET, CliTesting.run("plan", name, "--trials", "1", "--out", dir.resolve("o").toString()), name);
            }
            Path scenario = Files.writeString(dir.resolve("uses-" + ext + ".json"), Files.readString(
                TestPaths.root().resolve("scenarios/paper-breakaway.json")).replaceFirst("\"file\": *\"[^\"]*\"", "\"file\": \"secret." + ext + "\""));
            quotesNothingOf(SECRET, CliTesting.run("run", scenario.toString(), "--out", dir.resolve("o").toString()), "secret." + ext);
        }
        // binary: the four bytes at 80 taken as a triangle count would be content too
        byte[] bin = new byte[300];
        for (int i = 0; i < bin.length; i++) bin[i] = (byte) ("secretXYZ".charAt(i % 9) ^ (i % 3));
        Path b = Files.write(dir.resolve("blob.stl"), bin);
        CliTesting.Run r = CliTesting.run("mesh", b.toString());
        assertEquals(b + ": byte 80: not an STL file: not ASCII STL (text starting with 'solid') and its size, 300 bytes,"
            + " is far from 84 + 50 × the triangle count a binary STL has at byte 80", r.err());
    }

    /** /etc/passwd and a relative ../ path out of the scenario's folder, as the battery tried them. */
    @Test
    void systemFilesAreNamedNotQuoted() throws Exception {
        Path passwd = Path.of("/etc/passwd");
        if (!Files.isReadable(passwd)) return;
        String content = Files.readString(passwd).lines().findFirst().orElse("");   // the line the battery saw quoted
        Path deep = Files.createDirectories(dir.resolve("a/b/c"));
        String up = "../".repeat(deep.getNameCount()) + "etc/passwd";
        Path scenario = Files.writeString(deep.resolve("s.json"), Files.readString(
            TestPaths.root().resolve("scenarios/paper-breakaway.json")).replaceFirst("\"file\": *\"[^\"]*\"", "\"file\": \"" + up + "\""));
        CliTesting.Run r = CliTesting.run("run", scenario.toString(), "--out", dir.resolve("o").toString());
        assertEquals("/etc/passwd:1:1: not a VRML97 file: the first line is not the header '#VRML V2.0 utf8'", r.err());
        quotesNothingOf(content, r, "/etc/passwd");
    }

    /** A real model with a bad token still names the token (short, escaped): that is what a modeller needs. */
    @Test
    void aModelsBadTokenIsNamed() throws Exception {
        Path wrl = Files.writeString(dir.resolve("typo.wrl"), "#VRML V2.0 utf8\nShape { geometry Bxo { } }\n");
        assertTrue(CliTesting.run("mesh", wrl.toString()).err().startsWith(wrl + ":2:18: unknown node type 'Bxo'"),
            CliTesting.run("mesh", wrl.toString()).err());
        Path obj = Files.writeString(dir.resolve("typo.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nfx 1 2 3\n");
        assertTrue(CliTesting.run("mesh", obj.toString()).err().startsWith(obj + ":4:1: unknown statement 'fx'"),
            CliTesting.run("mesh", obj.toString()).err());
        Path stl = Files.writeString(dir.resolve("typo.stl"), "solid t\nfacet normal 0 0 1\n outer lop\n");
        assertEquals(stl + ":3:8: expected 'loop', found 'lop'", CliTesting.run("mesh", stl.toString()).err());
        Path first = Files.writeString(dir.resolve("first.obj"), "# a comment\nhello world\n");
        assertEquals(first + ":2:1: not a Wavefront OBJ file: its first statement is none of v, vn, vt, f, fo, l, p, g, o, s, mtllib,"
            + " usemtl, maplib, usemap", CliTesting.run("mesh", first.toString()).err());
    }
}
