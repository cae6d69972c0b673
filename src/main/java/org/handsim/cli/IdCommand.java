package org.handsim.cli;

import org.handsim.text.SafeText;
import org.handsim.text.Decimal;
import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.Callable;
import org.handsim.dynamics.ChainDynamics;
import org.handsim.dynamics.HandDynamics;
import org.handsim.dynamics.LinkChain;
import org.handsim.hand.HandDescription;
import org.handsim.hand.InputRanges;
import org.handsim.text.JsonWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code handsim id}: inverse dynamics of one finger, paper eq (8), for one state or for every
 * row of a CSV file. Units: rad, rad/s, rad/s², m/s² (gravity in the finger base frame {k0}),
 * N·m, kg·m².
 */
@Command(name = "id", mixinStandardHelpOptions = true,
    description = {"Inverse dynamics of a finger (paper eq 8): its joint torques and D, H, C.",
        "tau = D(q)*qdd + H(q,qd) + C(q).",
        "Prints {\"finger\":K,\"tau\":[..],\"D\":[[..]],\"H\":[..],\"C\":[..]}",
        "in N*m and kg*m^2. Finger 3 has no spread: give q1 = qd1 = qdd1 = 0;",
        "it prints its two active joints (2-vectors, a 2x2 D).",
        "Bulk: --input IN.csv with the header",
        "  " + IdCommand.IN_HEADER,
        "and --output OUT.csv, which repeats the input columns and adds",
        "tau1,tau2,tau3 (finger 3: tau1 empty). A bad row stops the run",
        "(exit 2, naming its line) and leaves no output file."})
public final class IdCommand implements Callable<Integer> {
    static final String IN_HEADER = "finger,q1,q2,q3,qd1,qd2,qd3,qdd1,qdd2,qdd3,gx,gy,gz";
    static final String ADDED_HEADER = "tau1,tau2,tau3";

    @Spec CommandSpec spec;

    @Mixin FingerOptions shared;

    @Option(names = "--q", paramLabel = "q1,q2,q3", description = "joint angles, rad")
    String q;

    @Option(names = "--qd", paramLabel = "qd1,qd2,qd3", description = "joint velocities, rad/s")
    String qd;

    @Option(names = "--qdd", paramLabel = "qdd1,qdd2,qdd3", description = "joint accelerations, rad/s^2")
    String qdd;

    @Option(names = "--gravity", paramLabel = "gx,gy,gz", description = {"gravity in the finger base frame {k0}, m/s^2,", "e.g. 0,0,-9.81"})
    String gravity;

    @Option(names = "--method", paramLabel = "le|ne", defaultValue = "le",
        description = "le: Lagrange-Euler (default, the paper's algorithm); ne: recursive Newton-Euler")
    String method;

    @Override
    public Integer call() throws IOException {
        HandDynamics.Method m;
        if (method.equals("le")) m = HandDynamics.Method.LAGRANGE_EULER;
        else if (method.equals("ne")) m = HandDynamics.Method.NEWTON_EULER;
        else throw CliError.usage("handsim: --method must be le or ne, got '" + SafeText.quote(method) + "'");
        HandDynamics hand = HandDynamics.of(HandDescription.barrettHand(), m);
        if (shared.bulk()) return bulk(hand);
        Args.finger(shared.finger);
        double[][] v = {
            Args.numbers("--q", q, 3, InputRanges.JOINT_ANGLE), Args.numbers("--qd", qd, 3, InputRanges.JOINT_SPEED),
            Args.numbers("--qdd", qdd, 3, InputRanges.JOINT_ACCELERATION), Args.numbers("--gravity", gravity, 3, InputRanges.GRAVITY)};
        String[] names = {"q%d (value %d of --q)", "qd%d (value %d of --qd)", "qdd%d (value %d of --qdd)"};
        ChainDynamics d = hand.finger(shared.finger);
        String bad = fixedJointViolation(shared.finger, d.chain(), v[0], v[1], v[2], names);
        if (bad != null) throw CliError.usage("handsim: " + bad);
        int n = d.dof();
        double[] qa = active(d.chain(), v[0]), qda = active(d.chain(), v[1]), qdda = active(d.chain(), v[2]);
        double[] dm = new double[n * n], h = new double[n], c = new double[n], tau = new double[n];
        d.terms(qa, qda, v[3], dm, h, c);
        d.inverseDynamics(qa, qda, qdda, v[3], tau);
        double[][] rows = new double[n][n];
        for (int i = 0; i < n; i++) System.arraycopy(dm, i * n, rows[i], 0, n);
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("finger", shared.finger);
        out.put("tau", Decimal.clean(tau));      // README: |x| < 1e-12 is rounding noise, written as 0
        out.put("D", Decimal.clean(rows));
        out.put("H", Decimal.clean(h));
        out.put("C", Decimal.clean(c));
        spec.commandLine().getOut().println(JsonWriter.write(out));
        return 0;
    }

    private int bulk(HandDynamics hand) throws IOException {
        double[] qf = new double[3], qdf = new double[3], qddf = new double[3], g = new double[3], tau = new double[3];
        String[] names = {"column q%d", "column qd%d", "column qdd%d"};
        return BulkCsv.run(spec, "id", shared.input, shared.output, shared.finger != null || q != null || qd != null || qdd != null || gravity != null,
            "--finger, --q, --qd, --qdd or --gravity", IN_HEADER, ADDED_HEADER, (in, sb) -> {
                int k = BulkCsv.finger(in);
                for (int j = 0; j < 3; j++) {
                    qf[j] = in.number(1 + j);
                    qdf[j] = in.number(4 + j);
                    qddf[j] = in.number(7 + j);
                    g[j] = in.number(10 + j);
                }
                String range = firstProblem(InputRanges.JOINT_ANGLE.problem(new String[] {"q1", "q2", "q3"}, qf),
                    InputRanges.JOINT_SPEED.problem(new String[] {"qd1", "qd2", "qd3"}, qdf),
                    InputRanges.JOINT_ACCELERATION.problem(new String[] {"qdd1", "qdd2", "qdd3"}, qddf),
                    InputRanges.GRAVITY.problem(new String[] {"gx", "gy", "gz"}, g));
                if (range != null) throw in.error(range);
                LinkChain chain = hand.finger(k).chain();
                String bad = fixedJointViolation(k, chain, qf, qdf, qddf, names);
                if (bad != null) throw in.error(bad);
                hand.inverseDynamics(k, qf, qdf, qddf, g, tau);
                for (int j = 0; j < 3; j++) {
                    sb.append(',');
                    if (!chain.isActive(j)) continue;
                    if (!Double.isFinite(tau[j])) throw in.error("torque tau" + (j + 1) + " is not finite (" + tau[j] + ")");
                    sb.append(Args.csv(Decimal.clean(tau[j])));
                }
            });
    }

    /**
     * Null, or what is wrong with a fixed joint given another angle or a motion; {@code names}
     * are format strings for q, qd, qdd taking the joint number (twice).
     */
    private static String fixedJointViolation(int k, LinkChain chain, double[] q, double[] qd, double[] qdd, String[] names) {
        for (int j = 0; j < 3; j++) {
            if (chain.isActive(j)) continue;
            double[][] v = {q, qd, qdd};
            double[] want = {chain.fixedValue(j), 0, 0};
            for (int i = 0; i < 3; i++) {
                if (v[i][j] != want[i]) {
                    String name = String.format(names[i], j + 1, j + 1);
                    return "finger " + k + "'s joint " + (j + 1) + " is fixed at " + fmt(chain.fixedValue(j)) + " rad (no spread): "
                        + name + " must be " + fmt(want[i]) + ", got " + fmt(v[i][j]);
                }
            }
        }
        return null;
    }

    /** The first non-null of the problems, or null. */
    static String firstProblem(String... problems) {
        for (String p : problems) if (p != null) return p;
        return null;
    }

    private static String fmt(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }

    private static double[] active(LinkChain chain, double[] all) {
        double[] a = new double[chain.dof()];
        for (int j = 0; j < 3; j++) {
            int p = chain.dofOfLink(j);
            if (p >= 0) a[p] = all[j];
        }
        return a;
    }
}
