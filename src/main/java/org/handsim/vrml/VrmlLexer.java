package org.handsim.vrml;

import org.handsim.text.SafeText;
import java.nio.charset.StandardCharsets;

/**
 * Tokens of the VRML97 grammar (ISO/IEC 14772-1, 5.1 and Annex A), read straight from the
 * file's bytes.
 *
 * <p>The lexer is pull-based: the parser knows from the field type what comes next (a float, an
 * integer, a string, an identifier) and asks for exactly that, so there is no token object and
 * nothing is allocated per number. Hot paths are written for speed:
 * <ul>
 *   <li>{@link #skip()} passes over white space, commas (which VRML treats as white space) and
 *       {@code #} comments with one table lookup per byte;</li>
 *   <li>numbers are parsed by hand: up to 18 significant digits are accumulated in a
 *       {@code long} and scaled by an exact power of ten, which gives the correctly rounded
 *       double whenever the power is at most 10<sup>22</sup> (Clinger's fast path, "How to read
 *       floating point numbers accurately", PLDI 1990); anything else falls back to
 *       {@link Double#parseDouble}. A number must be followed by a separator, so {@code 1.2.3}
 *       or {@code 12abc} is an error rather than two tokens.</li>
 * </ul>
 *
 * <p>Identifiers follow the standard: the first character may not be a control character,
 * space, {@code " # ' + , - . [ \ ] { }}, a digit or DEL; the following ones may not be
 * {@code " # ' , . [ \ ] { }}, control, space or DEL ({@code +} and {@code -} are allowed, so
 * {@code _+0} is a name). A control byte other than tab, CR and LF is "binary data" and an error.
 *
 * <p>Not thread-safe; one lexer per file being parsed.
 */
final class VrmlLexer {
    private static final byte WS = 1, ID_FIRST = 2, ID_REST = 4, BAD = 8;
    private static final byte[] CLASS = new byte[256];
    private static final double[] POW10 = new double[23];

    static {
        for (int b = 0; b < 256; b++) {
            byte k;
            if (b == ' ' || b == '\t' || b == '\n' || b == '\r' || b == ',') k = WS;
            else if (b < 0x20 || b == 0x7f) k = BAD;
            else if (b == '"' || b == '#' || b == '\'' || b == '.' || b == '[' || b == '\\' || b == ']' || b == '{' || b == '}') k = 0;
            else if (b == '+' || b == '-' || (b >= '0' && b <= '9')) k = ID_REST;
            else k = ID_FIRST | ID_REST;
            CLASS[b] = k;
        }
        double p = 1;
        for (int i = 0; i < POW10.length; i++) { POW10[i] = p; p *= 10; }
    }

    final VrmlText text;
    private final byte[] buf;
    private final int end;
    /** Offset of the next unread byte. */
    int pos;
    /** Offset of the number {@link #readDouble} read last (where a float range error points). */
    private int numberStart;

    VrmlLexer(VrmlText text, int start) {
        this.text = text;
        this.buf = text.buf;
        this.end = text.length;
        this.pos = start;
    }

    /**
     * Skips white space, commas and comments.
     *
     * @return the next byte (0..255) without consuming it, or -1 at the end of the input
     */
    int skip() {
        final byte[] b = buf;
        int p = pos;
        while (p < end) {
            int c = b[p] & 0xff;
            if (CLASS[c] == WS) {
                p++;
            } else if (c == '#') {
                while (p < end && b[p] != '\n' && b[p] != '\r') p++;
            } else {
                pos = p;
                return c;
            }
        }
        pos = p;
        return -1;
    }

    /** True if only white space and comments remain. */
    boolean atEnd() {
        return skip() < 0;
    }

    /** True if the next token starts an identifier. */
    boolean atIdentifier() {
        int c = skip();
        return c >= 0 && (CLASS[c] & ID_FIRST) != 0;
    }

    /** True if the next token looks like a number (digit, sign or point). */
    boolean atNumber() {
        int c = skip();
        return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
    }

    /** Consumes {@code c} if it is the next token. */
    boolean accept(char c) {
        if (skip() == c) {
            pos++;
            return true;
        }
        return false;
    }

    /** Consumes {@code c} or fails with "expected c {context}, found ...". */
    void expect(char c, String context) {
        if (skip() != c) throw error("expected '" + c + "' " + context + ", found " + describe());
        pos++;
    }

    /** Reads an identifier or fails with "expected {what}, found ...". */
    String identifier(String what) {
        int c = skip();
        if (c < 0 || (CLASS[c] & ID_FIRST) == 0) {
            checkBinary(c);
            throw error("expected " + what + ", found " + describe());
        }
        int start = pos;
        int p = pos + 1;
        boolean ascii = c < 0x80;
        while (p < end) {
            int d = buf[p] & 0xff;
            if ((CLASS[d] & ID_REST) == 0) break;
            if (d >= 0x80) ascii = false;
            p++;
        }
        pos = p;
        // not ASCII: invalid UTF-8 bytes become lone surrogates (text.SafeText), escaped in messages
        return ascii ? new String(buf, start, p - start, StandardCharsets.ISO_8859_1) : SafeText.decodeUtf8(buf, start, p - start);
    }

    /** True if the next token is the keyword/identifier {@code word} (not consumed). */
    boolean atWord(String word) {
        int c = skip();
        if (c < 0) return false;
        int n = word.length();
        if (pos + n > end) return false;
        for (int i = 0; i < n; i++) {
            if (buf[pos + i] != word.charAt(i)) return false;
        }
        return pos + n == end || (CLASS[buf[pos + n] & 0xff] & ID_REST) == 0;
    }

    private void checkBinary(int c) {
        if (c >= 0 && CLASS[c] == BAD) {
            throw error(String.format("unexpected control byte 0x%02x (binary data in a text file?)", c));
        }
    }

    /** Reads a double-quoted string with {@code \"} and {@code \\} escapes. */
    String string(String what) {
        int c = skip();
        if (c != '"') throw error("expected " + what + " (a string in double quotes), found " + describe());
        int start = pos;
        int p = pos + 1;
        StringBuilder sb = null;
        int runStart = p;
        while (true) {
            if (p >= end) throw text.error(start, "unterminated string (no closing '\"' before the end of the file)");
            byte b = buf[p];
            if (b == '"') break;
            if (b == '\\') {
                if (sb == null) sb = new StringBuilder();
                sb.append(new String(buf, runStart, p - runStart, StandardCharsets.UTF_8));
                p++;
                if (p >= end) throw text.error(start, "unterminated string (no closing '\"' before the end of the file)");
                runStart = p; // the escaped character is kept as is
                p++;
                continue;
            }
            p++;
        }
        String tail = new String(buf, runStart, p - runStart, StandardCharsets.UTF_8);
        pos = p + 1;
        return sb == null ? tail : sb.append(tail).toString();
    }

    /** Reads a float (SFFloat component); fails if it is not a number or out of float range. */
    float readFloat(String what) {
        double d = readDouble(what);
        float f = (float) d;
        if (Float.isInfinite(f)) throw text.error(numberStart, "number " + d + " is out of the single-precision range (" + what + ")");
        return f;
    }

    /** Reads a double (SFTime, or a float read at double precision). */
    double readDouble(String what) {
        int c = skip();
        final byte[] b = buf;
        int start = pos;
        int p = start;
        if (c == '+' || c == '-') p++;
        long m = 0;
        int digits = 0;
        int exp10 = 0;
        boolean any = false, truncated = false;
        int d;
        while (p < end && (d = b[p] - '0') >= 0 && d <= 9) {
            any = true;
            if (digits < 18) {
                m = m * 10 + d;
                if (m != 0) digits++;
            } else {
                exp10++;
                if (d != 0) truncated = true;
            }
            p++;
        }
        if (p < end && b[p] == '.') {
            p++;
            while (p < end && (d = b[p] - '0') >= 0 && d <= 9) {
                any = true;
                if (digits < 18) {
                    m = m * 10 + d;
                    if (m != 0) digits++;
                    exp10--;
                } else if (d != 0) {
                    truncated = true;
                }
                p++;
            }
        }
        if (!any) {
            checkBinary(c);
            throw error("expected a number for " + what + ", found " + describe());
        }
        if (p < end && (b[p] == 'e' || b[p] == 'E')) {
            int q = p + 1;
            boolean eneg = false;
            if (q < end && (b[q] == '+' || b[q] == '-')) { eneg = b[q] == '-'; q++; }
            int e = 0;
            boolean edig = false;
            while (q < end && (d = b[q] - '0') >= 0 && d <= 9) {
                edig = true;
                if (e < 100000) e = e * 10 + d;
                q++;
            }
            if (!edig) {
                pos = start;
                throw error("malformed number " + describe() + " for " + what + " (exponent without digits)");
            }
            exp10 += eneg ? -e : e;
            p = q;
        }
        if (p < end) {
            int k = b[p] & 0xff;
            if (k == '.' || (CLASS[k] & ID_REST) != 0) {
                pos = start;
                throw error("malformed number " + describe() + " for " + what);
            }
        }
        double v;
        if (!truncated && m < (1L << 53) && exp10 >= -22 && exp10 <= 22) {
            v = exp10 >= 0 ? m * POW10[exp10] : m / POW10[-exp10];
            if (c == '-') v = -v;
        } else {
            v = Double.parseDouble(new String(b, start, p - start, StandardCharsets.ISO_8859_1));
        }
        pos = p;
        numberStart = start;
        return v;
    }

    /**
     * Reads an SFInt32: decimal, or hexadecimal {@code 0x...} (up to 0xFFFFFFFF, as SFImage pixels
     * are written), with an optional sign.
     */
    int readInt(String what) {
        int c = skip();
        final byte[] b = buf;
        int start = pos;
        int p = start;
        boolean neg = false;
        if (c == '+' || c == '-') { neg = c == '-'; p++; }
        long v = 0;
        int d;
        boolean any = false;
        if (p + 1 < end && b[p] == '0' && (b[p + 1] == 'x' || b[p + 1] == 'X')) {
            p += 2;
            while (p < end) {
                int k = b[p];
                if (k >= '0' && k <= '9') d = k - '0';
                else if (k >= 'a' && k <= 'f') d = k - 'a' + 10;
                else if (k >= 'A' && k <= 'F') d = k - 'A' + 10;
                else break;
                any = true;
                v = v * 16 + d;
                if (v > 0xffffffffL) { pos = start; throw error("integer " + describe() + " out of the 32-bit range for " + what); }
                p++;
            }
            if (!any) { pos = start; throw error("malformed hexadecimal integer " + describe() + " for " + what); }
            v = (int) v;
        } else {
            while (p < end && (d = b[p] - '0') >= 0 && d <= 9) {
                any = true;
                v = v * 10 + d;
                if (v > 0x80000000L) { pos = start; throw error("integer " + describe() + " out of the 32-bit range for " + what); }
                p++;
            }
            if (!any) {
                checkBinary(c);
                throw error("expected an integer for " + what + ", found " + describe());
            }
            if (!neg && v > Integer.MAX_VALUE) { pos = start; throw error("integer " + describe() + " out of the 32-bit range for " + what); }
        }
        if (p < end) {
            int k = b[p] & 0xff;
            if (k == '.' || k == 'e' || k == 'E') {
                pos = start;
                throw error("expected an integer for " + what + ", found " + describe());
            }
            if ((CLASS[k] & ID_REST) != 0) {
                pos = start;
                throw error("malformed integer " + describe() + " for " + what);
            }
        }
        pos = p;
        return neg ? (int) -v : (int) v;
    }

    /** A short quoted description of the token at the current position, for messages. */
    String describe() {
        int c = skip();
        if (c < 0) return "the end of the file";
        if (CLASS[c] == BAD) return String.format("control byte 0x%02x", c);
        int p = pos;
        if (c == '"') return "a string";
        if (c == '{' || c == '}' || c == '[' || c == ']' || c == '.' && (p + 1 >= end || (buf[p + 1] < '0' || buf[p + 1] > '9'))) {
            return "'" + (char) c + "'";
        }
        int q = p;
        while (q < end && q - p < 40) {
            int k = buf[q] & 0xff;
            if (CLASS[k] == WS || CLASS[k] == BAD || k == '#' || k == '"' || k == '[' || k == ']' || k == '{' || k == '}') break;
            q++;
        }
        if (q == p) q = p + 1;
        return "'" + SafeText.quote(SafeText.decodeUtf8(buf, p, q - p)) + "'";
    }

    /** An error at the current position. */
    VrmlParseException error(String message) {
        return text.error(pos, message);
    }

    int end() { return end; }
}
