package org.handsim.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.handsim.TestPaths;
import org.handsim.text.Json;
import org.handsim.text.JsonWriter;

/** scenarios/mug-lift.json read as a map, to be changed by a test and written to its folder. */
final class MugLiftVariant {
    private MugLiftVariant() {}

    /** The lift named {@code name}, lasting {@code durationS}, the mug (by its absolute path) released at {@code releaseS}. */
    @SuppressWarnings("unchecked")
    static Map<String, Object> read(String name, double durationS, double releaseS) throws IOException {
        Path lift = TestPaths.root().resolve("scenarios/mug-lift.json");
        Map<String, Object> s = (Map<String, Object>) Json.parse(lift.toString(), Files.readString(lift));
        s.put("name", name);
        s.put("duration_s", durationS);
        Map<String, Object> o = (Map<String, Object>) s.get("object");
        o.put("file", TestPaths.root().resolve("vrml/objects/mug.wrl").toString());
        o.put("release_s", releaseS);
        return s;
    }

    static Path write(Path dir, String fileName, Map<String, Object> scenario) throws IOException {
        return Files.writeString(dir.resolve(fileName), JsonWriter.pretty(scenario));
    }
}
