package org.handsim.text;

/**
 * Input quoted in a message, made safe for tools that read messages line by line. Every error HandSim prints is exactly one line.
 *
 * <p>{@link #escape} replaces, each by {@code \}{@code uXXXX} (lower-case hex):
 * <ul>
 *   <li>C0 controls U+0000–U+001F (NUL, TAB, LF, CR, ...) and DEL U+007F;</li>
 *   <li>C1 controls U+0080–U+009F, among them U+0085 NEXT LINE, which Unicode-aware readers
 *       (Java's {@code BufferedReader} does not, Python's {@code str.splitlines} does) take as
 *       a line break;</li>
 *   <li>U+2028 LINE SEPARATOR and U+2029 PARAGRAPH SEPARATOR (line breaks for Unicode readers
 *       and JavaScript), U+FEFF (an invisible byte-order mark) and U+FFFD (the replacement
 *       character a decoder puts where bytes were not UTF-8);</li>
 *   <li>lone surrogates. Bytes that are not valid UTF-8 are decoded by {@link #decodeUtf8} as
 *       the lone surrogates U+DC80–U+DCFF (Python's "surrogateescape", PEP 383), so an invalid
 *       byte 0xNN is printed as {@code \}{@code udcNN}: distinct from a valid character.</li>
 * </ul>
 * {@link #quote} also shortens: text longer than {@link #MAX_QUOTE} characters keeps its first
 * and last characters around {@code ...}.
 */
public final class SafeText {
    /** The longest quoted text kept whole, in characters. */
    public static final int MAX_QUOTE = 60;

    private SafeText() {}

    /** The text with every character listed in the class comment escaped (never shortened). */
    public static String escape(CharSequence s) {
        if (s == null) return "null";
        int n = s.length();
        int i = 0;
        while (i < n && !unsafe(s, i)) i++;
        if (i == n) return s.toString();
        StringBuilder sb = new StringBuilder(n + 16);
        sb.append(s, 0, i);
        for (; i < n; i++) {
            char c = s.charAt(i);
            if (unsafe(s, i)) {
                sb.append("\\u");
                String h = Integer.toHexString(c);
                for (int z = h.length(); z < 4; z++) sb.append('0');
                sb.append(h);
            } else {
                sb.append(c);
            }
        }
        return sb.toString();
    }

    /**
     * A text cell of a CSV table: {@link #line} (one physical line per row, control characters
     * escaped), quoted when it holds a comma or a double quote; null is the empty cell.
     */
    public static String csvCell(String s) {
        if (s == null) return "";
        s = line(s);
        if (s.indexOf(',') < 0 && s.indexOf('"') < 0) return s;
        return "\"" + s.replace("\"", "\"\"") + "\"";
    }

    /** One line for a message: {@link #escape} of the whole text (a multi-line text becomes one line). */
    public static String line(String message) {
        return escape(message);
    }

    /**
     * The text for a message between quotes (the caller adds the quotes): escaped, and
     * shortened to about {@link #MAX_QUOTE} characters when longer.
     */
    public static String quote(CharSequence s) {
        if (s == null) return "null";
        if (s.length() > MAX_QUOTE) {
            int head = MAX_QUOTE * 2 / 3, tail = MAX_QUOTE - head - 3;
            // never cut a surrogate pair in two
            if (Character.isHighSurrogate(s.charAt(head - 1))) head--;
            int from = s.length() - tail;
            if (Character.isLowSurrogate(s.charAt(from))) from++;
            return escape(s.subSequence(0, head)) + "..." + escape(s.subSequence(from, s.length()));
        }
        return escape(s);
    }

    /**
     * UTF-8 bytes as text, each byte that is not part of a valid UTF-8 sequence mapped to the
     * lone surrogate U+DC00 + byte (PEP 383), so {@link #escape} shows it as {@code \}{@code udcNN}.
     */
    public static String decodeUtf8(byte[] b, int off, int len) {
        StringBuilder sb = new StringBuilder(len);
        int end = off + len;
        int i = off;
        while (i < end) {
            int c = b[i] & 0xff;
            if (c < 0x80) {
                sb.append((char) c);
                i++;
                continue;
            }
            int need = c >= 0xc2 && c <= 0xdf ? 1 : c >= 0xe0 && c <= 0xef ? 2 : c >= 0xf0 && c <= 0xf4 ? 3 : -1;
            int cp = need == 1 ? c & 0x1f : need == 2 ? c & 0x0f : c & 0x07;
            boolean ok = need > 0;
            if (ok) {
                for (int k = 1; k <= need; k++) {
                    if (i + k >= end) { ok = false; break; }
                    int d = b[i + k] & 0xff;
                    if ((d & 0xc0) != 0x80) { ok = false; break; }
                    cp = (cp << 6) | (d & 0x3f);
                }
            }
            // overlong forms, surrogates and values above U+10FFFF are not valid UTF-8
            if (ok && (need == 2 && (cp < 0x800 || (cp >= 0xd800 && cp <= 0xdfff)) || need == 3 && (cp < 0x10000 || cp > 0x10ffff))) ok = false;
            if (ok) {
                sb.appendCodePoint(cp);
                i += need + 1;
            } else {
                sb.append((char) (0xdc00 + c));
                i++;
            }
        }
        return sb.toString();
    }

    /** Whether the character at i is one {@link #escape} replaces. */
    static boolean unsafe(CharSequence s, int i) {
        char c = s.charAt(i);
        if (c < 0x20 || (c >= 0x7f && c <= 0x9f)) return true;
        if (c == 0x2028 || c == 0x2029 || c == 0xfeff || c == 0xfffd) return true;
        if (Character.isHighSurrogate(c)) return i + 1 >= s.length() || !Character.isLowSurrogate(s.charAt(i + 1));
        if (Character.isLowSurrogate(c)) return i == 0 || !Character.isHighSurrogate(s.charAt(i - 1));
        return false;
    }
}
