package org.handsim.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** {@link SafeText}: what a line reader would split on, or could not show, is escaped. */
class SafeTextTest {
    @Test
    void controlAndLineBreakingCharactersAreEscaped() {
        assertEquals("a\\u0000b\\u000ac\\u000dd\\u0009e", SafeText.escape("a\u0000b\nc\rd\te"));
        assertEquals("X\\u0085Y\\u2028Z\\u2029", SafeText.escape("X\u0085Y\u2028Z\u2029"));
        assertEquals("\\u007f\\u0080\\u009f\u00a0", SafeText.escape("\u007f\u0080\u009f\u00a0"), "DEL and C1; NBSP is printable");
        assertEquals("caf\u00e9 \ud83d\ude00", SafeText.escape("caf\u00e9 \ud83d\ude00"), "printable text and surrogate pairs unchanged");
        assertEquals("\\ud83d!", SafeText.escape("\ud83d!"), "a lone surrogate");
        assertEquals("\\ufeff\\ufffd", SafeText.escape("\ufeff\ufffd"));
        String plain = "cube.wrl:12:3: unknown node type 'Foo'";
        assertEquals(plain, SafeText.line(plain));
    }

    @Test
    void longQuotesAreShortened() {
        String s = "A".repeat(40) + "\u0085" + "B".repeat(100) + "END";
        String q = SafeText.quote(s);
        assertTrue(q.startsWith("A".repeat(40)) && q.contains("...") && q.endsWith("BEND"), q);
        assertTrue(q.length() <= SafeText.MAX_QUOTE + 6, q);
        assertEquals("short", SafeText.quote("short"));
        String pairs = "\ud83d\ude00".repeat(50);
        assertTrue(SafeText.quote(pairs).indexOf("\\u") < 0, "a shortened quote never cuts a surrogate pair");
    }

    @Test
    void invalidUtf8BytesAreKeptAsEscapes() {
        byte[] b = {'X', (byte) 0xc2, (byte) 0x85, (byte) 0xff, 'Y', (byte) 0xe2, (byte) 0x80, (byte) 0xa8, (byte) 0xe2, (byte) 0x80, 'Z', (byte) 0xc0, (byte) 0x80};
        assertEquals("X\\u0085\\udcffY\\u2028\\udce2\\udc80Z\\udcc0\\udc80", SafeText.escape(SafeText.decodeUtf8(b, 0, b.length)),
            "valid U+0085 and U+2028 escaped as themselves; a stray byte, a truncated sequence and an overlong form as \\udcNN");
        String ok = "caf\u00e9 \ud83d\ude00 \u4e2d";
        byte[] u = ok.getBytes(StandardCharsets.UTF_8);
        assertEquals(ok, SafeText.decodeUtf8(u, 0, u.length), "valid UTF-8 decodes as Java does");
    }

    @Test
    void jsonStringsEscapeTheSameCharacters() {
        assertEquals("\"a\\u0085b\\u2028c\\u0000\\n\"", JsonWriter.write("a\u0085b\u2028c\u0000\n"));
        assertEquals("\"\ud83d\ude00\"", JsonWriter.write("\ud83d\ude00"));
    }
}
