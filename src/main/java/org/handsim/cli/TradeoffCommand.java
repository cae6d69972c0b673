package org.handsim.cli;

import org.handsim.util.SafeText;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.function.Supplier;
import org.handsim.chart.StudyTable;
import org.handsim.chart.TradeoffChart;
import org.handsim.tradeoff.Studies;
import org.handsim.tradeoff.Study;
import org.handsim.util.AtomicFile;
import org.handsim.util.JsonWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code handsim tradeoff}: the speed-against-accuracy charts of issue 8. */
@Command(name = "tradeoff", mixinStandardHelpOptions = true,
    description = {
        "Runs the speed-against-accuracy studies and charts them.",
        "Per study it writes <id>.png, <id>.svg and <id>.csv",
        "(header: series,setting,default,<study columns>)",
        "into --out DIR (default out/tradeoff), and tradeoff.json (per study:",
        "rows, wall_time_s, files). Each chart plots cost against error on log",
        "axes, one point per setting, the Pareto front dashed, the default marked.",
        "Studies: 1-dt (time step, paper experiment), 2-tessellation (object",
        "resolution against analytic contacts), 3-kdop (k of the k-DOPs and brute",
        "force, the hand grasping each vrml/objects model), 4-integrators (energy",
        "drift of a free finger). The full run takes about a minute (48 s on 2",
        "cores); --quick runs fewer settings (a smoke test)."})
public final class TradeoffCommand implements Callable<Integer> {
    @Spec CommandSpec spec;

    @Option(names = "--out", paramLabel = "DIR", description = "output folder (default out/tradeoff)")
    Path out = Path.of("out", "tradeoff");

    @Option(names = "--only", paramLabel = "ID", split = ",",
        description = "run only these studies (ids or their numbers, e.g. 1,3 or 2-tessellation)")
    List<String> only;

    @Option(names = "--quick", description = "fewer settings and timing runs (seconds instead of a minute)")
    boolean quick;

    @Override
    public Integer call() throws IOException {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        List<Study> chosen = choose();
        Map<String, Object> summary = new LinkedHashMap<>();
        summary.put("quick", quick);
        Map<String, Object> perStudy = new LinkedHashMap<>();
        summary.put("studies", perStudy);
        long start = System.nanoTime();
        for (Study s : chosen) {
            long t0 = System.nanoTime();
            StudyTable table = s.run(quick, new ProgressBar(err, "handsim tradeoff " + s.id()));
            TradeoffChart.write(table, out);
            double secs = (System.nanoTime() - t0) / 1e9;
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("rows", table.rows().size());
            m.put("wall_time_s", secs);
            m.put("files", List.of(s.id() + ".png", s.id() + ".svg", s.id() + ".csv"));
            m.put("notes", new ArrayList<>(table.notes().values()));   // the chart's caption: for the docs, not under the plot
            perStudy.put(s.id(), m);
            stdout.println(String.format(Locale.ROOT, "%s: %d settings in %.1f s -> %s/%s.{png,svg,csv}",
                s.id(), table.rows().size(), secs, out, s.id()));
            stdout.flush();
        }
        summary.put("wall_time_s", (System.nanoTime() - start) / 1e9);
        AtomicFile.writeString(out.resolve("tradeoff.json"), JsonWriter.pretty(summary));
        return 0;
    }

    private List<Study> choose() {
        List<Study> all = new ArrayList<>();
        for (Supplier<Study> s : Studies.ALL) all.add(s.get());
        if (only == null || only.isEmpty()) return all;
        List<Study> chosen = new ArrayList<>();
        for (String want : only) {
            Study hit = null;
            for (Study s : all) {
                if (s.id().equals(want) || s.id().startsWith(want.trim() + "-")) hit = s;
            }
            if (hit == null) {
                List<String> ids = new ArrayList<>();
                for (Study s : all) ids.add(s.id());
                throw CliError.usage("handsim: --only: no study '" + SafeText.quote(want) + "' (known: " + String.join(", ", ids) + ")");
            }
            if (!chosen.contains(hit)) chosen.add(hit);
        }
        return chosen;
    }
}
