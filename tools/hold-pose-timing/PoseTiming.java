// The cost of the hold test on each of a set of grasps, as `plan --hold-test` runs it on a
// trial: close the scenario, lock the hand, release and settle the object, then the six pushes,
// verdicts only (a failed push stops at the step that crosses a threshold). One warm JVM, one
// thread: a warm-up round, then ROUNDS rounds over every grasp; per grasp, the median of its
// thread's CPU time. Prints one JSON object (tools/hold-vs-mujoco's step posetiming reads it).
//   ./handsim --help >/dev/null   # builds build/install
//   java -cp "build/install/handsim/lib/*" -Dj3d.rend=noop -Djava.awt.headless=true -Xss16m \
//       tools/hold-pose-timing/PoseTiming.java ROUNDS MASS_KG FORCE_N MU SCENARIO.json ...
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import org.handsim.hold.DirectionResult;
import org.handsim.hold.HoldReport;
import org.handsim.hold.HoldSettings;
import org.handsim.hold.HoldTest;
import org.handsim.hold.LockedGrasp;
import org.handsim.hold.ObjectMass;
import org.handsim.model.HandModel;
import org.handsim.model.SceneGeometry;
import org.handsim.model.Simulation;
import org.handsim.scenario.Scenario;

/** Per grasp: CPU of closing and of the hold test (settling and six verdict-only pushes), medians of warm rounds. */
public class PoseTiming {
  public static void main(String[] a) throws Exception {
    int rounds = Integer.parseInt(a[0]);
    double mass = Double.parseDouble(a[1]), force = Double.parseDouble(a[2]), mu = Double.parseDouble(a[3]);
    int n = a.length - 4;
    ThreadMXBean threads = ManagementFactory.getThreadMXBean();
    double[][] closeS = new double[n][rounds], testS = new double[n][rounds], simS = new double[n][rounds];
    String[] passed = new String[n];
    for (int r = -1; r < rounds; r++) {
      for (int i = 0; i < n; i++) {
        long c0 = threads.getCurrentThreadCpuTime();
        Scenario s = Scenario.load(Path.of(a[4 + i])).withFriction(mu);
        SceneGeometry g = new SceneGeometry(s.object(), SceneGeometry.DEFAULT_K);
        HandModel m = Simulation.model(s, g);
        HoldReport.close(m);
        long c1 = threads.getCurrentThreadCpuTime();
        HoldSettings hs = HoldSettings.defaults(m.graspInput().hand().handRatingN()).withForce(force);
        HoldTest t = new HoldTest(LockedGrasp.of(m, g, ObjectMass.of(g.objectMesh(), mass, Double.NaN)), hs);
        StringBuilder v = new StringBuilder();
        double simulated = t.settling()[2];
        for (int d = 0; d < 6; d++) {
          DirectionResult x = t.push(d, true);
          if (x.passed()) v.append(v.length() > 0 ? " " : "").append(x.direction());
          simulated += x.simulatedS();
        }
        long c2 = threads.getCurrentThreadCpuTime();
        if (r >= 0) {
          closeS[i][r] = (c1 - c0) / 1e9;
          testS[i][r] = (c2 - c1) / 1e9;
          simS[i][r] = simulated;
        }
        passed[i] = v.toString();
      }
      System.err.println("PoseTiming: round " + (r + 1) + " of " + rounds + (r < 0 ? " (warm-up)" : ""));
    }
    StringBuilder json = new StringBuilder("{\"rounds\": " + rounds + ", \"poses\": [");
    for (int i = 0; i < n; i++) {
      json.append(i > 0 ? ", " : "").append(String.format(Locale.ROOT,
          "{\"scenario\": \"%s\", \"close_cpu_s\": %.5f, \"hold_test_cpu_s\": %.5f, \"simulated_s\": %.3f, \"passed\": \"%s\"}",
          a[4 + i], median(closeS[i]), median(testS[i]), median(simS[i]), passed[i]));
    }
    System.out.println(json.append("]}"));
  }

  private static double median(double[] x) {
    double[] s = x.clone();
    Arrays.sort(s);
    return s.length % 2 == 1 ? s[s.length / 2] : 0.5 * (s[s.length / 2 - 1] + s[s.length / 2]);
  }
}
