package org.handsim.text;

import java.util.Iterator;
import java.util.List;
import java.util.Map;

/**
 * Writes JSON for the command outputs (contracts: key order is insertion order). Numbers are
 * written by {@link Decimal} (shortest round trip, integers without a fraction, no -0, the
 * layout of ECMAScript's Number::toString); a non-finite number is an error, never a silent
 * {@code NaN} in the output. Strings escape what {@link SafeText} escapes.
 */
public final class JsonWriter {
    private JsonWriter() {}

    /**
     * A number that is NaN or infinite where a result was to be written, with the path of its
     * field ({@code fingertip[0]}, {@code fingers[2].max_contact_force_N}): the command stops
     * before writing anything (exit 4, a numerical failure) instead of writing a broken file.
     */
    public static final class NonFiniteException extends IllegalArgumentException {
        private static final long serialVersionUID = 1L;
        private final String path;
        private final double value;

        NonFiniteException(String path, double value) {
            super("the result " + (path.isEmpty() ? "" : path + " ") + "is " + value + ", not a finite number");
            this.path = path;
            this.value = value;
        }

        /** The field's path from the root ("" for a bare number). */
        public String path() { return path; }

        public double value() { return value; }

        /** The same, one level further out: {@code key} (an object's field) or {@code [i]} (an element). */
        NonFiniteException within(String step) {
            String p = path.isEmpty() ? step : path.startsWith("[") ? step + path : step + "." + path;
            NonFiniteException e = new NonFiniteException(p, value);
            e.setStackTrace(getStackTrace());
            return e;
        }
    }

    /** Compact JSON text of a value built from Map, List, arrays, numbers, strings, booleans, null. */
    public static String write(Object v) {
        StringBuilder sb = new StringBuilder();
        append(sb, v, -1, 0);
        return sb.toString();
    }

    /** Indented JSON text (2 spaces), for files people read. */
    public static String pretty(Object v) {
        StringBuilder sb = new StringBuilder();
        append(sb, v, 2, 0);
        return sb.append('\n').toString();
    }

    private static void newline(StringBuilder sb, int indent, int level) {
        if (indent < 0) return;
        sb.append('\n');
        for (int i = 0; i < indent * level; i++) sb.append(' ');
    }

    private static void append(StringBuilder sb, Object v, int indent, int level) {
        if (v == null) {
            sb.append("null");
        } else if (v instanceof String) {
            quote(sb, (String) v);
        } else if (v instanceof Boolean) {
            sb.append(v);
        } else if (v instanceof Double || v instanceof Float) {
            number(sb, ((Number) v).doubleValue());
        } else if (v instanceof Number) {
            sb.append(((Number) v).longValue());
        } else if (v instanceof double[]) {
            double[] a = (double[]) v;
            sb.append('[');
            for (int i = 0; i < a.length; i++) {
                if (i > 0) sb.append(',');
                try {
                    number(sb, a[i]);
                } catch (NonFiniteException e) {
                    throw e.within("[" + i + "]");
                }
            }
            sb.append(']');
        } else if (v instanceof int[]) {
            int[] a = (int[]) v;
            sb.append('[');
            for (int i = 0; i < a.length; i++) {
                if (i > 0) sb.append(',');
                sb.append(a[i]);
            }
            sb.append(']');
        } else if (v instanceof double[][]) {
            double[][] a = (double[][]) v;
            sb.append('[');
            for (int i = 0; i < a.length; i++) {
                if (i > 0) sb.append(',');
                try {
                    append(sb, a[i], -1, 0);
                } catch (NonFiniteException e) {
                    throw e.within("[" + i + "]");
                }
            }
            sb.append(']');
        } else if (v instanceof Map) {
            sb.append('{');
            Iterator<? extends Map.Entry<?, ?>> it = ((Map<?, ?>) v).entrySet().iterator();
            boolean any = it.hasNext();
            while (it.hasNext()) {
                Map.Entry<?, ?> e = it.next();
                newline(sb, indent, level + 1);
                quote(sb, String.valueOf(e.getKey()));
                sb.append(indent < 0 ? ":" : ": ");
                try {
                    append(sb, e.getValue(), indent, level + 1);
                } catch (NonFiniteException x) {
                    throw x.within(String.valueOf(e.getKey()));
                }
                if (it.hasNext()) sb.append(',');
            }
            if (any) newline(sb, indent, level);
            sb.append('}');
        } else if (v instanceof List) {
            List<?> l = (List<?>) v;
            sb.append('[');
            boolean scalars = l.stream().noneMatch(x -> x instanceof Map || x instanceof List);
            for (int i = 0; i < l.size(); i++) {
                if (i > 0) sb.append(',');
                if (!scalars) newline(sb, indent, level + 1);
                try {
                    append(sb, l.get(i), indent, level + 1);
                } catch (NonFiniteException e) {
                    throw e.within("[" + i + "]");
                }
            }
            if (!scalars && !l.isEmpty()) newline(sb, indent, level);
            sb.append(']');
        } else {
            throw new IllegalArgumentException("cannot write " + v.getClass().getName() + " as JSON");
        }
    }

    private static void number(StringBuilder sb, double d) {
        if (!Double.isFinite(d)) throw new NonFiniteException("", d);
        Decimal.append(sb, d);
    }

    private static void quote(StringBuilder sb, String s) {
        sb.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"': sb.append("\\\""); break;
                case '\\': sb.append("\\\\"); break;
                case '\n': sb.append("\\n"); break;
                case '\r': sb.append("\\r"); break;
                case '\t': sb.append("\\t"); break;
                default:
                    // C0, C1 (U+0085), U+2028/2029 and lone surrogates as \\uXXXX: one line for line readers
                    if (SafeText.unsafe(s, i)) sb.append(String.format("\\u%04x", (int) c));
                    else sb.append(c);
            }
        }
        sb.append('"');
    }
}
