package org.handsim.text;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParseException;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.StreamReadConstraints;
import com.fasterxml.jackson.core.exc.StreamConstraintsException;
import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A strict JSON (RFC 8259) reader producing {@link Map} (insertion-ordered), {@link List},
 * {@link Double}, {@link String}, {@link Boolean} and {@code null}, on jackson-core's streaming
 * parser: a number with a leading zero ({@code 01}) or a bare trailing dot ({@code 1.}), a
 * duplicate field, a number beyond the range of a double ({@code 1e400}) and anything after the
 * value are refused. Errors are {@link JsonException}s naming the source, line and column.
 * Nesting is limited to {@value #MAX_DEPTH} levels so a hostile file cannot overflow the stack.
 *
 * <p>Numbers are read as {@link Double#valueOf(String)} reads their text, so {@code -0} stays
 * −0.0 and every digit string gives the double it gave before.
 */
public final class Json {
    /** Deepest nesting accepted. */
    public static final int MAX_DEPTH = 512;

    private static final JsonFactory FACTORY = JsonFactory.builder()
        .enable(com.fasterxml.jackson.core.StreamReadFeature.STRICT_DUPLICATE_DETECTION)
        .streamReadConstraints(StreamReadConstraints.builder().maxNestingDepth(MAX_DEPTH).build())
        .build();

    private Json() {}

    /** Parses a whole JSON document; {@code source} names it in error messages. */
    public static Object parse(String source, String text) {
        try (JsonParser p = FACTORY.createParser(text)) {
            JsonToken first = p.nextToken();
            if (first == null) throw error(source, p.currentLocation(), "unexpected end of input, a value was expected");
            Object v = value(source, p, first);
            JsonToken after;
            try {
                after = p.nextToken();
            } catch (JsonParseException e) {
                throw error(source, e.getLocation(), "unexpected text after the JSON value");
            }
            if (after != null) throw error(source, p.currentTokenLocation(), "unexpected text after the JSON value");
            return v;
        } catch (JsonParseException e) {
            String m = e.getOriginalMessage();
            JsonLocation at = e.getLocation();
            // jackson locates an unexpected character or word just after it: name where it starts
            Matcher word = m == null ? null : NON_STANDARD.matcher(m);
            int back = m == null ? 0 : CHARACTER.matcher(m).find() ? 1 : word.find() ? word.group(1).length() : 0;
            throw error(source, at == null ? null : new JsonLocation(null, -1, -1, at.getLineNr(), at.getColumnNr() - back), message(m));
        } catch (StreamConstraintsException e) {
            throw new JsonException(source + ": nesting deeper than " + MAX_DEPTH);
        } catch (IOException e) {
            throw new JsonException(source + ": " + e.getMessage());
        }
    }

    private static Object value(String source, JsonParser p, JsonToken t) throws IOException {
        switch (t) {
            case START_OBJECT: {
                Map<String, Object> m = new LinkedHashMap<>();
                for (JsonToken k = p.nextToken(); k != JsonToken.END_OBJECT; k = p.nextToken()) {
                    String name = p.currentName();
                    m.put(name, value(source, p, p.nextToken()));
                }
                return m;
            }
            case START_ARRAY: {
                List<Object> l = new ArrayList<>();
                for (JsonToken e = p.nextToken(); e != JsonToken.END_ARRAY; e = p.nextToken()) l.add(value(source, p, e));
                return l;
            }
            case VALUE_STRING: return p.getText();
            case VALUE_NUMBER_INT:
            case VALUE_NUMBER_FLOAT: {
                String s = p.getText();
                double d = Double.parseDouble(s);
                if (!Double.isFinite(d)) throw error(source, p.currentTokenLocation(), "number '" + SafeText.quote(s) + "' is beyond the range of a double");
                return d;
            }
            case VALUE_TRUE: return Boolean.TRUE;
            case VALUE_FALSE: return Boolean.FALSE;
            case VALUE_NULL: return null;
            default: throw error(source, p.currentTokenLocation(), "unexpected " + t);
        }
    }

    private static final Pattern CHARACTER = Pattern.compile("^Unexpected character \\((?:'.*' )?\\((?:CTRL-CHAR, )?code (\\d+)[^)]*\\)\\)(?::\\s*(.*))?", Pattern.DOTALL);
    private static final Pattern NON_STANDARD = Pattern.compile("^Non-standard token '([^']*)'");
    private static final Pattern DUPLICATE = Pattern.compile("^Duplicate field '(.*)'", Pattern.DOTALL);

    /** Jackson's message, as short as ours were: the offending character quoted safely, no Java names. */
    static String message(String jackson) {
        String m = jackson == null ? "bad JSON" : jackson;
        Matcher c = CHARACTER.matcher(m);
        if (c.find()) {
            String what = new String(Character.toChars(Integer.parseInt(c.group(1))));
            return "unexpected character '" + SafeText.quote(what) + "'";
        }
        Matcher d = DUPLICATE.matcher(m);
        if (d.find()) return "duplicate field \"" + SafeText.quote(d.group(1)) + "\"";
        Matcher nonStandard = NON_STANDARD.matcher(m);
        if (nonStandard.find()) return "'" + SafeText.quote(nonStandard.group(1)) + "' is not a JSON number (non-finite numbers are refused)";
        if (m.startsWith("Invalid numeric value: Leading zeroes not allowed")) return "bad number: a leading zero is not allowed";
        if (m.startsWith("Unexpected end-of-input")) {
            String rest = m.substring("Unexpected end-of-input".length()).split("\n")[0].trim();
            return "unexpected end of input" + (rest.isEmpty() ? "" : " " + rest);
        }
        String first = m.split("\n")[0].trim();
        return first.isEmpty() ? "bad JSON" : Character.toLowerCase(first.charAt(0)) + first.substring(1);
    }

    private static JsonException error(String source, JsonLocation at, String msg) {
        long line = at == null ? -1 : at.getLineNr(), col = at == null ? -1 : at.getColumnNr();
        return new JsonException(source + ":" + Math.max(1, line) + ":" + Math.max(1, col) + ": " + msg);
    }

    /** A JSON syntax error or a field that fails validation; the message names where. */
    public static final class JsonException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        public JsonException(String message) {
            super(SafeText.line(message));
        }
    }
}
