package org.handsim.cli;

import org.handsim.text.SafeText;
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
import org.handsim.chart.ChartSet;
import org.handsim.chart.StudyTable;
import org.handsim.chart.TradeoffChart;
import org.handsim.tradeoff.Studies;
import org.handsim.tradeoff.Study;
import org.handsim.files.AtomicFile;
import org.handsim.text.JsonWriter;
import org.handsim.files.OutputSet;
import org.handsim.process.Phase;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code handsim tradeoff}: the speed-against-accuracy charts. */
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
        "drift of a free finger), 5-body-rest (the free object's time step against",
        "the drift and penetration of a box resting on / dropped onto a table; x is",
        "dt), 6-body-tumble (its time step against the errors of a torque-free",
        "tumble). The full run takes about a minute (48 s on 2",
        "cores); --quick runs fewer settings (a smoke test). DIR holds one run's",
        "files: --only removes those of the studies it did not run."})
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
        Args.outputPath("--out", out);
        List<Study> chosen = choose();
        Map<String, Object> summary = new LinkedHashMap<>();
        summary.put("quick", quick);
        Map<String, Object> perStudy = new LinkedHashMap<>();
        summary.put("studies", perStudy);
        long start = System.nanoTime();
        String missing = null;   // once the charts cannot be drawn, the other studies write their tables only
        // every file goes to the set's private folder; the folder gets them all, or none, at the end
        try (OutputSet set = Args.outputSet(err, "--out", out, layout())) {
            Phase.reach("opened");
            for (Study s : chosen) {
                long t0 = System.nanoTime();
                StudyTable table = s.run(quick, Phase.atHalf("half-" + s.id(), new ProgressBar(err, "handsim tradeoff " + s.id())));
                table.writeCsv(set.dir().resolve(s.id() + ".csv"));
                if (missing == null) {
                    ChartSet charts = ChartSet.start(null);   // drawn before the next study starts: its timings see an idle machine
                    charts.add(set.dir().resolve(s.id()), TradeoffChart.WIDTH, TradeoffChart.HEIGHT, () -> TradeoffChart.create(table));
                    missing = Charts.finish(charts, err);
                }
                double secs = (System.nanoTime() - t0) / 1e9;
                Map<String, Object> m = new LinkedHashMap<>();
                m.put("rows", table.rows().size());
                m.put("wall_time_s", secs);
                m.put("files", missing == null ? List.of(s.id() + ".png", s.id() + ".svg", s.id() + ".csv") : List.of(s.id() + ".csv"));
                m.put("notes", new ArrayList<>(table.notes().values()));   // the chart's caption: for the docs, not under the plot
                perStudy.put(s.id(), m);
                stdout.println(String.format(Locale.ROOT, "%s: %d settings in %.1f s -> %s/%s.%s",
                    s.id(), table.rows().size(), secs, out, s.id(), missing == null ? "{png,svg,csv}" : "csv"));
                stdout.flush();
                Phase.reach("study-" + s.id());
            }
            summary.put("wall_time_s", (System.nanoTime() - start) / 1e9);
            if (missing != null) summary.put(Charts.MISSING_KEY, missing);
            AtomicFile.writeString(set.dir().resolve("tradeoff.json"), JsonWriter.pretty(summary));
            set.publish();
        }
        return 0;
    }

    /** The files of the tradeoff folder, every study's (a run of some studies removes the others'): tradeoff.json is published last. */
    static OutputSet.Layout layout() {
        List<String> ids = new ArrayList<>();
        for (Supplier<Study> s : Studies.ALL) ids.add(java.util.regex.Pattern.quote(s.get().id()));
        return new OutputSet.Layout("tradeoff.json", "tradeoff\\.json|(" + String.join("|", ids) + ")\\.(png|svg|csv)");
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
