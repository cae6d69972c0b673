// The hold LP against the free hold test (DESIGN.md decision 8, "Statics against dynamics"): for
// each scenario, close it, take the hold LP's load L along each world direction
// (GraspAssessment.holdN, 8-edge cones) and run HoldTest's ramp along it, and, where L is below
// the cap, constant pushes of 0.9 L and 1.1 L (verdicts only); AGREE when 0.9 L held and 1.1 L
// failed. The object's mass: its closed mesh at 1000 kg/m3.
//   ./handsim --help >/dev/null   # builds build/install
//   java -cp "build/install/handsim/lib/*" -Dj3d.rend=noop -Djava.awt.headless=true \
//       tools/hold-lp-consistency/Consistency.java PLAN_DIR/best/01.json ...
// (the planner's best grasps: handsim plan vrml/objects/mug.wrl --trials 400 --seed 101).
import java.nio.file.*;
import java.util.*;
import org.handsim.hold.*;
import org.handsim.model.*;
import org.handsim.grasp.*;
import org.handsim.scenario.*;
/** The hold LP's load L along each world direction against the free test at 0.9 L and 1.1 L, and the ramp. */
public class Consistency {
  public static void main(String[] a) throws Exception {
    String[] dn = {"+x","-x","+y","-y","+z","-z"};
    double[][] du = {{1,0,0},{-1,0,0},{0,1,0},{0,-1,0},{0,0,1},{0,0,-1}};
    for (String f : a) {
      long t0 = System.nanoTime();
      Scenario s = Scenario.load(Path.of(f));
      double mu = s.friction();
      SceneGeometry g = new SceneGeometry(s.object(), SceneGeometry.DEFAULT_K);
      HandModel m = Simulation.model(s, g);
      HoldReport.close(m);
      GraspAssessment.Input in = m.graspInput();
      GraspAssessment ga = GraspAssessment.of(in, mu, 8);
      double cap = in.hand().handRatingN();
      HoldTest t = new HoldTest(LockedGrasp.of(m, g, ObjectMass.of(g.objectMesh(), Double.NaN, Double.NaN)), HoldSettings.defaults(cap));
      System.out.println(String.format("%s mu %s engaged %b %b %b drop %b settle %.2g m", f.replaceAll(".*/(s[0-9]+)/best/", "$1_"), mu,
        m.clutchEngaged(1), m.clutchEngaged(2), m.clutchEngaged(3), t.droppedOnRelease(), t.settling()[0]));
      for (int d = 0; d < 6; d++) {
        double L = ga.holdN()[d];
        RampResult r = t.ramp(dn[d], du[d]);
        String line = String.format("   %s L %.3f ramp %s%.3f", dn[d], L, r.heldAtMax() ? ">=" : "", r.forceN());
        if (L > 0 && L < cap * (1 - 1e-9)) {
          DirectionResult lo = t.push(dn[d], du[d], 0.9 * L, true), hi = t.push(dn[d], du[d], 1.1 * L, true);
          line += String.format(" | 0.9L %s (%.2g m %.2g deg) 1.1L %s (%.2g m %.2g deg) %s", lo.passed() ? "held" : "FAILED", lo.displacementM(), lo.rotationDeg(),
            hi.passed() ? "HELD" : "failed", hi.displacementM(), hi.rotationDeg(), lo.passed() && !hi.passed() ? "AGREE" : "DISAGREE");
        } else {
          DirectionResult one = t.push(dn[d], du[d], 0.9 * cap, true);
          line += String.format(" | L at cap: 0.9cap %s (%.2g m)", one.passed() ? "held" : "FAILED", one.displacementM());
        }
        System.out.println(line); System.out.flush();
      }
      System.out.println(String.format("   (%.1f s)", (System.nanoTime() - t0) / 1e9));
    }
  }
}
