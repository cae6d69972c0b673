package org.handsim.cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.handsim.text.SafeText;

/**
 * Arguments whose bytes are not UTF-8. The JVM decodes its arguments and puts U+FFFD where a
 * byte is not UTF-8, so a file named with such a byte would silently become another name (a
 * folder {@code --out} named with the byte 0xff was made with the three bytes of U+FFFD in its
 * place). Such an argument is refused, naming the byte: on Linux the bytes as given are in
 * {@code /proc/self/cmdline}, where they are read back as lone surrogates
 * ({@link SafeText#decodeUtf8}), which messages show as a backslash, "udc" and the byte.
 */
final class ArgumentBytes {
    private ArgumentBytes() {}

    /** Null when every argument is the text its bytes say, else the message for the first that is not. */
    static String problem(String[] args) {
        int first = -1;
        for (int i = 0; i < args.length && first < 0; i++) if (args[i].indexOf('\ufffd') >= 0) first = i;
        if (first < 0) return null;
        List<byte[]> raw = tail(args.length);
        boolean ours = raw != null;   // this process's own arguments (not a command handed over by another)
        for (int i = 0; ours && i < args.length; i++) ours = new String(raw.get(i), StandardCharsets.UTF_8).equals(args[i]);
        if (ours) {
            for (int i = 0; i < args.length; i++) {
                String exact = SafeText.decodeUtf8(raw.get(i), 0, raw.get(i).length);
                if (!exact.equals(args[i])) return message(exact, byteOf(exact));
            }
            return null;   // each U+FFFD was written as such (its three UTF-8 bytes)
        }
        return message(args[first], -1);
    }

    private static String message(String arg, int b) {
        return "handsim: the argument '" + SafeText.quote(arg) + "' is not UTF-8 text" + (b >= 0 ? String.format(java.util.Locale.ROOT,
            " (byte 0x%02x)", b) : "") + ": Java would read it as another name; rename the file, or give another name";
    }

    /** The first byte kept as a lone surrogate, or -1. */
    private static int byteOf(String s) {
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c >= 0xdc80 && c <= 0xdcff && (i == 0 || !Character.isHighSurrogate(s.charAt(i - 1)))) return c - 0xdc00;
        }
        return -1;
    }

    /** The last {@code n} arguments of this process as given (Linux), or null when they cannot be read or do not match. */
    private static List<byte[]> tail(int n) {
        byte[] all;
        try {
            all = Files.readAllBytes(Path.of("/proc/self/cmdline"));
        } catch (IOException | RuntimeException e) {
            return null;
        }
        List<byte[]> parts = new ArrayList<>();
        int start = 0;
        for (int i = 0; i < all.length; i++) {
            if (all[i] == 0) {
                byte[] p = new byte[i - start];
                System.arraycopy(all, start, p, 0, p.length);
                parts.add(p);
                start = i + 1;
            }
        }
        if (parts.size() < n) return null;
        return parts.subList(parts.size() - n, parts.size());
    }
}
