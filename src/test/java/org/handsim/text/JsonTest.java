package org.handsim.text;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The JSON reader: what RFC 8259 allows comes back as maps, lists, doubles, strings; the rest is refused with file, line and column. */
class JsonTest {
    private static String refused(String text) {
        return assertThrows(Json.JsonException.class, () -> Json.parse("f.json", text)).getMessage();
    }

    @Test
    void valuesComeBackInOrderWithNumbersAsDoubles() {
        Object v = Json.parse("f.json", "{\"b\": [1, -0, 2.5e-3, true, null, \"x\\u00e9\\n\"], \"a\": {}}");
        Map<String, Object> want = new LinkedHashMap<>();
        want.put("b", Arrays.asList(1.0, -0.0, 0.0025, true, null, "xé\n"));
        want.put("a", Map.of());
        assertEquals(want, v);
        assertEquals(List.of("b", "a"), List.copyOf(((Map<?, ?>) v).keySet()));
        // -0 is negative zero, as Double.valueOf reads it
        assertEquals(Double.doubleToRawLongBits(-0.0), Double.doubleToRawLongBits((Double) ((List<?>) ((Map<?, ?>) v).get("b")).get(1)));
    }

    @Test
    void numbersReadAsDoubleValueOfReadsThem() {
        for (String s : List.of("0", "-1", "0.1", "1e-7", "123456789012345678901234567890", "4.9e-324", "1.7976931348623157e308", "2.2250738585072011e-308")) {
            assertEquals(Double.valueOf(s), Json.parse("f.json", "[" + s + "]") instanceof List<?> l ? l.get(0) : null, s);
        }
    }

    @Test
    void leadingZerosAreRefused() {
        assertTrue(refused("[01]").startsWith("f.json:1:"), refused("[01]"));
        assertTrue(refused("{\"a\": -01.5}").contains("leading zero"), refused("{\"a\": -01.5}"));
    }

    @Test
    void bareTrailingDotsAreRefused() {
        assertTrue(refused("[1.]").startsWith("f.json:1:"), refused("[1.]"));
        assertTrue(refused("[-01.e5]").startsWith("f.json:1:"), refused("[-01.e5]"));
        assertTrue(refused("[.5]").startsWith("f.json:1:"), refused("[.5]"));
    }

    @Test
    void duplicateKeysAreRefusedWithTheirName() {
        assertEquals("f.json:2:8: duplicate field \"a\"", refused("{\"a\": 1,\n \"b\": 2, \"a\": 3}").replaceAll(":2:\\d+:", ":2:8:"));
        assertTrue(refused("{\"a\": 1,\n \"b\": 2, \"a\": 3}").startsWith("f.json:2:"));
    }

    @Test
    void nonFiniteNumbersAreRefused() {
        assertEquals("f.json:1:7: number '1e400' is beyond the range of a double", refused("{\"x\": 1e400}"));
        assertTrue(refused("[-1e999]").contains("beyond the range"), refused("[-1e999]"));
        assertEquals("f.json:1:2: 'NaN' is not a JSON number (non-finite numbers are refused)", refused("[NaN]"));
        assertTrue(refused("[Infinity]").startsWith("f.json:1:2:"), refused("[Infinity]"));
    }

    @Test
    void errorsNameTheLineAndColumn() {
        assertEquals("f.json:3:2: unexpected character '}'", refused("{\n \"a\": 1,\n }"));
        assertTrue(refused("").startsWith("f.json:1:1: unexpected end of input"), refused(""));
        assertTrue(refused("{\"a\": 1").startsWith("f.json:1:"), refused("{\"a\": 1"));
        assertTrue(refused("{\"a\": 1} x").startsWith("f.json:1:"), refused("{\"a\": 1} x"));
        assertTrue(refused("{\"a\": 1} {}").contains("after the JSON value"), refused("{\"a\": 1} {}"));
        assertTrue(refused("[\"a\u0001\"]").startsWith("f.json:1:"), refused("[\"a\u0001\"]"));
    }

    @Test
    void nestingIsBounded() {
        String deep = "[".repeat(Json.MAX_DEPTH + 1) + "]".repeat(Json.MAX_DEPTH + 1);
        assertTrue(refused(deep).contains("nesting deeper than " + Json.MAX_DEPTH), refused(deep));
        String ok = "[".repeat(Json.MAX_DEPTH) + "]".repeat(Json.MAX_DEPTH);
        Object v = Json.parse("f.json", ok);
        assertTrue(v instanceof List<?>);
    }
}
