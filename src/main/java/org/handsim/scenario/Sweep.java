package org.handsim.scenario;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.handsim.files.InputFile;
import org.handsim.files.FileName;
import org.handsim.text.Json;
import org.handsim.text.JsonObject;
import org.handsim.text.JsonWriter;

/**
 * A sweep file: many runs of one base scenario with fields overridden, and/or other scenario
 * files, run in parallel by {@code handsim sweep}.
 *
 * <pre>{@code
 * {
 *   "name": "cube-positions",
 *   "base": "paper-breakaway.json",                       // relative to the sweep file
 *   "runs": [ {"label": "y-5mm", "set": {"object.position_m": [0, 0.005, 0.12]}},
 *             {"label": "slow",  "set": {"motors.M3[0].v_max": 3000}} ],
 *   "scenarios": ["../scenarios/mug-grasp.json"],         // optional
 *   "threads": 0                                          // optional, 0 = all cores
 * }
 * }</pre>
 * A {@code set} key is a path into the base scenario's JSON: field names separated by dots,
 * array elements by {@code [i]}; the value replaces what is there (or adds the field).
 */
public final class Sweep {
    /** One run: a label and the scenario it runs (built lazily so that a bad run fails alone). */
    public record Run(String label, java.util.function.Supplier<Scenario> scenario) {}

    /** Most worker threads a sweep may ask for (as {@code --threads}): far beyond any machine's cores. */
    public static final int MAX_THREADS = 1024;

    private final String name;
    private final List<Run> runs = new ArrayList<>();
    private final int threads;

    private Sweep(Path file, JsonObject r) {
        r.allowOnly("name", "base", "runs", "scenarios", "threads");
        name = r.string("name");
        String bad = FileName.problem(name);
        if (bad != null) throw r.error("name", bad + ", got \"" + name + "\"");
        threads = r.has("threads") ? r.integer("threads") : 0;
        if (threads < 0 || threads > MAX_THREADS) {
            throw r.error("threads", "must be in [0, " + MAX_THREADS + "] (0: all cores), got " + threads);
        }
        Path dir = file.toAbsolutePath().getParent();
        if (r.has("runs")) {
            if (!r.has("base")) throw r.error("base", "missing (the runs override fields of a base scenario)");
            Path base = dir.resolve(r.string("base")).normalize();
            String why = InputFile.problem(base);
            if (why != null) throw r.error("base", why + ": " + base);
            String baseText;
            try {
                baseText = Scenario.readText(base);
            } catch (ScenarioException e) {
                throw r.error("base", e.getMessage());
            }
            int n = r.list("runs").size();
            for (int i = 0; i < n; i++) {
                JsonObject run = r.objectAt("runs", i);
                run.allowOnly("label", "set");
                String label = run.string("label");
                JsonObject set = run.has("set") ? run.object("set") : null;
                Map<String, Object> overrides = new LinkedHashMap<>();
                if (set != null) for (String k : set.keys()) overrides.put(k, set.raw(k));
                String text = baseText;
                runs.add(new Run(label, () -> Scenario.parse(base, applyOverrides(base, text, overrides))));
            }
        }
        if (r.has("scenarios")) {
            int n = r.list("scenarios").size();
            for (int i = 0; i < n; i++) {
                Object v = r.list("scenarios").get(i);
                if (!(v instanceof String)) throw r.error("scenarios[" + i + "]", "must be a file name");
                Path f = dir.resolve((String) v).normalize();
                String why = InputFile.problem(f);
                if (why != null && !why.equals("no such file")) throw r.error("scenarios[" + i + "]", why + ": " + f);   // a missing one fails its row alone
                runs.add(new Run(f.getFileName().toString().replaceFirst("\\.json$", ""), () -> Scenario.load(f)));
            }
        }
        if (runs.isEmpty()) throw r.error("runs", "the sweep has no runs and no scenarios");
    }

    /** Applies dotted-path overrides to scenario JSON text and returns the new text. */
    @SuppressWarnings("unchecked")
    static String applyOverrides(Path file, String text, Map<String, Object> overrides) {
        Object root;
        try {
            root = Json.parse(file.toString(), text);
        } catch (Json.JsonException e) {
            throw new ScenarioException(e.getMessage(), e);
        }
        for (Map.Entry<String, Object> e : overrides.entrySet()) {
            String[] parts = e.getKey().split("\\.");
            Object node = root;
            for (int p = 0; p < parts.length; p++) {
                String part = parts[p];
                int idx = -1;
                int b = part.indexOf('[');
                if (b >= 0) {
                    if (!part.endsWith("]")) throw new ScenarioException(file + ": override \"" + e.getKey() + "\": bad index in '" + part + "'");
                    try {
                        idx = Integer.parseInt(part.substring(b + 1, part.length() - 1));
                    } catch (NumberFormatException x) {
                        throw new ScenarioException(file + ": override \"" + e.getKey() + "\": bad index in '" + part + "'");
                    }
                    part = part.substring(0, b);
                }
                if (!(node instanceof Map)) throw new ScenarioException(file + ": override \"" + e.getKey() + "\": '" + part + "' is not inside an object");
                Map<String, Object> m = (Map<String, Object>) node;
                boolean last = p == parts.length - 1;
                if (idx < 0) {
                    if (last) m.put(part, e.getValue());
                    else node = m.computeIfAbsent(part, x -> new LinkedHashMap<String, Object>());
                } else {
                    Object l = m.get(part);
                    if (!(l instanceof List) || idx >= ((List<Object>) l).size()) {
                        throw new ScenarioException(file + ": override \"" + e.getKey() + "\": no element " + idx + " in '" + part + "'");
                    }
                    if (last) ((List<Object>) l).set(idx, e.getValue());
                    else node = ((List<Object>) l).get(idx);
                }
            }
        }
        return JsonWriter.write(root);
    }

    /** Loads a sweep file. */
    public static Sweep load(Path file) {
        try {
            return new Sweep(file, JsonObject.parse(file.toString(), Scenario.readText(file)));
        } catch (Json.JsonException e) {
            throw new ScenarioException(e.getMessage(), e);
        }
    }

    public String name() { return name; }
    public List<Run> runs() { return runs; }
    /** Worker threads: the file's value, or all cores when 0. */
    public int threads() { return threads > 0 ? threads : Runtime.getRuntime().availableProcessors(); }
}
