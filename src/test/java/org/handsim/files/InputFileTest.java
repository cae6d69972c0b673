package org.handsim.files;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Map;
import org.handsim.text.Decimal;
import org.junit.jupiter.api.Test;

/**
 * {@link InputFile}: special files refused before they are opened, with what they are; bounded
 * reads; strict UTF-8 with the file, line, column and byte of the first bad byte; one leading
 * byte-order mark dropped. And the number readers people meet: {@link Decimal#parse} (no
 * {@code 0d}) and {@link Decimal#count} (no 9223372036854775807).
 */
class InputFileTest {
    @Test
    void specialFilesAreRefusedAtOnceSayingWhatTheyAre() throws Exception {
        try (SpecialFiles sf = new SpecialFiles()) {
            assertTrue(sf.all.size() >= 2, "at least a directory and /dev/null: " + sf.all);
            for (Map.Entry<String, Path> e : sf.all.entrySet()) {
                Path f = e.getValue();
                assertEquals("is not a regular file (" + e.getKey() + ")", InputFile.problem(f), f.toString());
                // reading is refused before the file is opened: a FIFO would block here forever
                InputFile.InputFileException x = assertTimeoutPreemptively(Duration.ofSeconds(60),
                    () -> assertThrows(InputFile.InputFileException.class, () -> InputFile.readText(f, 1000, "the test's limit")));
                assertEquals(f + ": is not a regular file (" + e.getKey() + ")", x.getMessage());
                assertTimeoutPreemptively(Duration.ofSeconds(60), () -> assertThrows(InputFile.InputFileException.class, () -> new InputFile.Lines(f, 100)));
                assertTimeoutPreemptively(Duration.ofSeconds(60), () -> assertThrows(InputFile.InputFileException.class, () -> InputFile.head(f, 100)));
            }
            assertEquals("no such file", InputFile.problem(sf.dir.resolve("absent")));
        }
    }

    @Test
    void aByteOrderMarkIsDroppedAndNonUtf8NamesLineColumnAndByte() throws Exception {
        Path dir = Files.createTempDirectory("handsim-input");
        try {
            Path bom = Files.write(dir.resolve("bom.json"), "\uFEFF{\"a\": 1}".getBytes(StandardCharsets.UTF_8));
            assertEquals("{\"a\": 1}", InputFile.readText(bom, 100, "x"));
            // line 2 (from offset 3), column 4 (characters: the 2-byte é counts once), the byte at offset 7
            byte[] bad = {'a', 'b', '\n', 'x', (byte) 0xc3, (byte) 0xa9, 'y', (byte) 0xff, 'z'};
            Path f = Files.write(dir.resolve("latin1.csv"), bad);
            InputFile.InputFileException e = assertThrows(InputFile.InputFileException.class, () -> InputFile.readText(f, 100, "x"));
            assertEquals(f + ":2:4: not UTF-8: byte 0xff at offset 7 is not part of a UTF-8 character (save the file as UTF-8)", e.getMessage());
            try (InputFile.Lines lines = new InputFile.Lines(f, 100)) {
                assertEquals("ab", lines.next());
                InputFile.InputFileException le = assertThrows(InputFile.InputFileException.class, lines::next);
                assertEquals(e.getMessage(), le.getMessage(), "the streaming reader says the same");
            }
            Path crlf = Files.write(dir.resolve("crlf.csv"), "\uFEFFh1,h2\r\n1,2\r\n\r\nlast".getBytes(StandardCharsets.UTF_8));
            try (InputFile.Lines lines = new InputFile.Lines(crlf, 100)) {
                assertEquals("h1,h2", lines.next());
                assertEquals("1,2", lines.next());
                assertEquals("", lines.next());
                assertEquals("last", lines.next());
                assertNull(lines.next());
                assertEquals(4, lines.line());
            }
            Path longLine = Files.writeString(dir.resolve("long.csv"), "ok\n" + "x".repeat(1000));
            try (InputFile.Lines lines = new InputFile.Lines(longLine, 100)) {
                lines.next();
                assertEquals(longLine + ":2: line longer than 100 bytes", assertThrows(InputFile.InputFileException.class, lines::next).getMessage());
            }
        } finally {
            ChildFiles.delete(dir);
        }
    }

    @Test
    void readsAreBoundedByTheLimit() throws Exception {
        Path dir = Files.createTempDirectory("handsim-input");
        try {
            Path f = Files.write(dir.resolve("big.wrl"), new byte[1001]);
            assertEquals(f + ": is 1001 bytes, more than the limit of object files (1000 bytes)",
                assertThrows(InputFile.InputFileException.class, () -> InputFile.readBytes(f, 1000, "the limit of object files")).getMessage());
            assertEquals(1001, InputFile.readBytes(f, 1001, "x").length);
            assertEquals(10, InputFile.head(f, 10).length);
        } finally {
            ChildFiles.delete(dir);
        }
    }

    @Test
    void numbersAreDecimalsOnly() {
        assertEquals(0.0, Decimal.parse("0"));
        assertEquals(-0.5, Decimal.parse(" -.5 "));
        assertEquals(250.0, Decimal.parse("2.5E+2"));
        assertEquals(1e-3, Decimal.parse("1e-3"));
        assertEquals(Double.POSITIVE_INFINITY, Decimal.parse("1e400"), "beyond the range: an infinity the callers refuse");
        for (String s : new String[] {"0d", "1f", "1D", "0x1p3", "NaN", "Infinity", "-Infinity", "", "1e", "--1", "1,5", "1.2.3"}) {
            NumberFormatException e = assertThrows(NumberFormatException.class, () -> Decimal.parse(s), s);
            assertEquals("'" + s + "' is not a number", e.getMessage());
        }
    }

    @Test
    void countsReadAsWords() {
        assertEquals("8947", Decimal.count(8947));
        assertEquals("999999", Decimal.count(999_999));
        assertEquals("1 million", Decimal.count(1e6));
        assertEquals("10 million", Decimal.count(10_000_000));
        assertEquals("8.95 billion", Decimal.count(8.946e9));
        assertEquals("1 billion", Decimal.count(999_999_999.9), "rounded to three digits, then the next word");
        assertEquals("12 trillion", Decimal.count(1.2e13));
        assertEquals("1e+303", Decimal.count(1e303));
        assertEquals("9.22e+18", Decimal.count(Long.MAX_VALUE), "never its 19 digits");
    }

    /** Deletes a test folder. */
    static final class ChildFiles {
        static void delete(Path dir) throws java.io.IOException {
            try (var s = Files.walk(dir)) {
                s.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
            }
        }
    }
}
