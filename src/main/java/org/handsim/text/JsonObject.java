package org.handsim.text;

import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Typed, validating access to a parsed JSON object. Every failure names the field by its
 * path from the document root (e.g. {@code fingers[2].links[0].mass}) and the source file,
 * and every number is checked to be finite.
 */
public final class JsonObject {
    private final String source;
    private final String path;
    private final Map<String, Object> map;

    public JsonObject(String source, String path, Map<String, Object> map) {
        this.source = source;
        this.path = path;
        this.map = map;
    }

    /** Parses {@code text} and requires an object at the top. */
    @SuppressWarnings("unchecked")
    public static JsonObject parse(String source, String text) {
        Object v = Json.parse(source, text);
        if (!(v instanceof Map)) throw new Json.JsonException(source + ": the top level must be a JSON object");
        return new JsonObject(source, "", (Map<String, Object>) v);
    }

    public String source() { return source; }

    /** @return the field's path, e.g. {@code fingers[1].dh} */
    public String pathOf(String field) {
        return path.isEmpty() ? field : path + "." + field;
    }

    /** The parsed value of a field as is (Map, List, Double, String, Boolean or null). */
    public Object raw(String field) { return map.get(field); }

    public boolean has(String field) { return map.containsKey(field) && map.get(field) != null; }

    public Set<String> keys() { return map.keySet(); }

    /** An error about {@code field}: "{source}: field {path}: {message}". */
    public Json.JsonException error(String field, String message) {
        return new Json.JsonException(source + ": field " + pathOf(field) + ": " + message);
    }

    private Object require(String field) {
        if (!map.containsKey(field)) throw error(field, "missing");
        Object v = map.get(field);
        if (v == null) throw error(field, "is null");
        return v;
    }

    public double number(String field) {
        Object v = require(field);
        if (!(v instanceof Double)) throw error(field, "must be a number, got " + describe(v));
        double d = (Double) v;
        if (!Double.isFinite(d)) throw error(field, "must be finite, got " + d);
        return d;
    }

    public double number(String field, double dflt) { return has(field) ? number(field) : dflt; }

    public double positive(String field) {
        double d = number(field);
        if (!(d > 0)) throw error(field, "must be > 0, got " + Decimal.format(d));
        return d;
    }

    public double nonNegative(String field) {
        double d = number(field);
        if (d < 0) throw error(field, "must be >= 0, got " + Decimal.format(d));
        return d;
    }

    public int integer(String field) {
        double d = number(field);
        if (d != Math.rint(d) || Math.abs(d) > Integer.MAX_VALUE) throw error(field, "must be an integer, got " + Decimal.format(d));
        return (int) d;
    }

    public String string(String field) {
        Object v = require(field);
        if (!(v instanceof String)) throw error(field, "must be a string, got " + describe(v));
        return (String) v;
    }

    public String string(String field, String dflt) { return has(field) ? string(field) : dflt; }

    public boolean bool(String field, boolean dflt) {
        if (!has(field)) return dflt;
        Object v = map.get(field);
        if (!(v instanceof Boolean)) throw error(field, "must be true or false, got " + describe(v));
        return (Boolean) v;
    }

    /** A numeric array of exactly {@code n} finite entries ({@code n < 0}: any length). */
    public double[] numbers(String field, int n) {
        List<Object> l = list(field);
        if (n >= 0 && l.size() != n) throw error(field, "must have " + n + " numbers, got " + l.size());
        double[] out = new double[l.size()];
        for (int i = 0; i < out.length; i++) {
            Object v = l.get(i);
            if (!(v instanceof Double) || !Double.isFinite((Double) v)) {
                throw error(field + "[" + i + "]", "must be a finite number, got " + describe(v));
            }
            out[i] = (Double) v;
        }
        return out;
    }

    @SuppressWarnings("unchecked")
    public List<Object> list(String field) {
        Object v = require(field);
        if (!(v instanceof List)) throw error(field, "must be an array, got " + describe(v));
        return (List<Object>) v;
    }

    @SuppressWarnings("unchecked")
    public JsonObject object(String field) {
        Object v = require(field);
        if (!(v instanceof Map)) throw error(field, "must be an object, got " + describe(v));
        return new JsonObject(source, pathOf(field), (Map<String, Object>) v);
    }

    /** The i-th element of array {@code field}, required to be an object. */
    @SuppressWarnings("unchecked")
    public JsonObject objectAt(String field, int i) {
        Object v = list(field).get(i);
        if (!(v instanceof Map)) throw error(field + "[" + i + "]", "must be an object, got " + describe(v));
        return new JsonObject(source, pathOf(field) + "[" + i + "]", (Map<String, Object>) v);
    }

    /** Rejects any field not in {@code allowed} (catches typos in hand-written files). */
    public void allowOnly(String... allowed) {
        Set<String> ok = Set.of(allowed);
        for (String k : map.keySet()) {
            if (!ok.contains(k)) throw error(k, "is not a known field (known: " + String.join(", ", allowed) + ")");
        }
    }

    private static String describe(Object v) {
        if (v == null) return "null";
        if (v instanceof String) return "\"" + v + "\"";
        if (v instanceof Map) return "an object";
        if (v instanceof List) return "an array";
        return String.valueOf(v);
    }
}
