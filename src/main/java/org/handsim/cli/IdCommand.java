package org.handsim.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.Callable;
import org.handsim.dynamics.ChainDynamics;
import org.handsim.dynamics.HandDynamics;
import org.handsim.dynamics.LinkChain;
import org.handsim.hand.HandDescription;
import org.handsim.util.AtomicFile;
import org.handsim.util.JsonWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code handsim id}: inverse dynamics of one finger, paper eq (8), for one state or for every
 * row of a CSV file. Units: rad, rad/s, rad/s², m/s² (gravity in the finger base frame {k0}),
 * N·m, kg·m².
 */
@Command(name = "id", mixinStandardHelpOptions = true,
    description = {"Inverse dynamics of a finger, paper eq (8): tau = D(q)*qdd + H(q,qd) + C(q).",
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
    static final String OUT_HEADER = IN_HEADER + ",tau1,tau2,tau3";
    private static final String[] COLUMNS = IN_HEADER.split(",");

    @Spec CommandSpec spec;

    @Option(names = "--finger", paramLabel = "K", description = "finger 1, 2 or 3")
    Integer finger;

    @Option(names = "--q", paramLabel = "q1,q2,q3", description = "joint angles, rad")
    String q;

    @Option(names = "--qd", paramLabel = "qd1,qd2,qd3", description = "joint velocities, rad/s")
    String qd;

    @Option(names = "--qdd", paramLabel = "qdd1,qdd2,qdd3", description = "joint accelerations, rad/s^2")
    String qdd;

    @Option(names = "--gravity", paramLabel = "gx,gy,gz", description = "gravity in the finger base frame {k0}, m/s^2, e.g. 0,0,-9.81")
    String gravity;

    @Option(names = "--method", paramLabel = "le|ne", defaultValue = "le",
        description = "le: Lagrange-Euler (default, the paper's algorithm); ne: recursive Newton-Euler")
    String method;

    @Option(names = "--input", paramLabel = "IN.csv", description = "bulk input with header " + IN_HEADER)
    Path input;

    @Option(names = "--output", paramLabel = "OUT.csv", description = "bulk output (written only if every row succeeds)")
    Path output;

    @Override
    public Integer call() throws IOException {
        HandDynamics.Method m;
        if (method.equals("le")) m = HandDynamics.Method.LAGRANGE_EULER;
        else if (method.equals("ne")) m = HandDynamics.Method.NEWTON_EULER;
        else throw CliError.usage("handsim: --method must be le or ne, got '" + method + "'");
        HandDynamics hand = HandDynamics.of(HandDescription.barrettHand(), m);
        if (input != null || output != null) return bulk(hand);
        if (finger == null) throw CliError.usage("handsim: --finger is required (or --input/--output for bulk)");
        if (finger < 1 || finger > 3) throw CliError.usage("handsim: --finger must be 1, 2 or 3, got " + finger);
        double[][] v = {
            numbers("--q", q), numbers("--qd", qd), numbers("--qdd", qdd), numbers("--gravity", gravity)};
        String[] names = {"q%d (value %d of --q)", "qd%d (value %d of --qd)", "qdd%d (value %d of --qdd)"};
        ChainDynamics d = hand.finger(finger);
        String bad = fixedJointViolation(finger, d.chain(), v[0], v[1], v[2], names);
        if (bad != null) throw CliError.usage("handsim: " + bad);
        int n = d.dof();
        double[] qa = active(d.chain(), v[0]), qda = active(d.chain(), v[1]), qdda = active(d.chain(), v[2]);
        double[] dm = new double[n * n], h = new double[n], c = new double[n], tau = new double[n];
        d.terms(qa, qda, v[3], dm, h, c);
        d.inverseDynamics(qa, qda, qdda, v[3], tau);
        double[][] rows = new double[n][n];
        for (int i = 0; i < n; i++) System.arraycopy(dm, i * n, rows[i], 0, n);
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("finger", finger);
        out.put("tau", tau);
        out.put("D", rows);
        out.put("H", h);
        out.put("C", c);
        spec.commandLine().getOut().println(JsonWriter.write(out));
        return 0;
    }

    private int bulk(HandDynamics hand) throws IOException {
        if (input == null || output == null) throw CliError.usage("handsim: bulk mode needs both --input and --output");
        if (finger != null || q != null || qd != null || qdd != null || gravity != null) {
            throw CliError.usage("handsim: --input/--output cannot be combined with --finger, --q, --qd, --qdd or --gravity");
        }
        double[] qf = new double[3], qdf = new double[3], qddf = new double[3], g = new double[3], tau = new double[3];
        String[] names = {"column q%d", "column qd%d", "column qdd%d"};
        int rows = 0;
        BufferedReader in;
        try {
            in = Files.newBufferedReader(input, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new CliError(CliError.LOAD, "handsim: " + input + ": no such file");
        }
        try (BufferedReader r = in; AtomicFile af = new AtomicFile(output)) {
            Writer w = af.writer();
            String header = r.readLine();
            if (header == null) throw rowError(1, "empty file, expected the header " + IN_HEADER);
            if (header.startsWith("\uFEFF")) header = header.substring(1);
            if (!normalise(header).equals(IN_HEADER)) {
                throw rowError(1, "header must be exactly '" + IN_HEADER + "', got '" + header.trim() + "'");
            }
            w.write(OUT_HEADER);
            w.write('\n');
            int line = 1;
            String s;
            while ((s = r.readLine()) != null) {
                line++;
                if (s.isBlank()) continue;
                String[] p = s.split(",", -1);
                if (p.length != COLUMNS.length) throw rowError(line, "expected " + COLUMNS.length + " columns, got " + p.length);
                for (int i = 0; i < p.length; i++) p[i] = p[i].trim();
                int k;
                try {
                    k = Integer.parseInt(p[0]);
                } catch (NumberFormatException e) {
                    throw rowError(line, "column finger = '" + p[0] + "' is not an integer");
                }
                if (k < 1 || k > 3) throw rowError(line, "finger must be 1, 2 or 3, got " + p[0]);
                for (int j = 0; j < 3; j++) {
                    qf[j] = cell(p, 1 + j, line);
                    qdf[j] = cell(p, 4 + j, line);
                    qddf[j] = cell(p, 7 + j, line);
                    g[j] = cell(p, 10 + j, line);
                }
                LinkChain chain = hand.finger(k).chain();
                String bad = fixedJointViolation(k, chain, qf, qdf, qddf, names);
                if (bad != null) throw rowError(line, bad);
                hand.inverseDynamics(k, qf, qdf, qddf, g, tau);
                StringBuilder sb = new StringBuilder(s.length() + 64);
                for (int i = 0; i < p.length; i++) sb.append(i == 0 ? "" : ",").append(p[i]);
                for (int j = 0; j < 3; j++) {
                    sb.append(',');
                    if (chain.isActive(j)) sb.append(number(tau[j], line));
                }
                w.write(sb.append('\n').toString());
                rows++;
            }
            af.commit();
        }
        spec.commandLine().getErr().println("handsim id: " + rows + " rows written to " + output);
        return 0;
    }

    private CliError rowError(int line, String message) {
        return CliError.usage("handsim: " + input + ":" + line + ": " + message);
    }

    private double cell(String[] p, int i, int line) {
        try {
            double d = Double.parseDouble(p[i]);
            if (!Double.isFinite(d)) throw rowError(line, "column " + COLUMNS[i] + " = " + p[i] + " is not finite");
            return d;
        } catch (NumberFormatException e) {
            throw rowError(line, "column " + COLUMNS[i] + " = '" + p[i] + "' is not a number");
        }
    }

    private String number(double v, int line) {
        if (!Double.isFinite(v)) throw rowError(line, "torque is not finite (" + v + ")");
        return Double.toString(v);
    }

    private static String normalise(String header) {
        String[] p = header.split(",", -1);
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < p.length; i++) sb.append(i == 0 ? "" : ",").append(p[i].trim());
        return sb.toString();
    }

    /** Three finite numbers from "a,b,c"; the message names the option. */
    private static double[] numbers(String option, String text) {
        if (text == null) throw CliError.usage("handsim: " + option + " is required");
        String[] p = text.split(",", -1);
        if (p.length != 3) throw CliError.usage("handsim: " + option + " needs 3 comma-separated numbers, got '" + text + "'");
        double[] v = new double[3];
        for (int i = 0; i < 3; i++) {
            try {
                v[i] = Double.parseDouble(p[i].trim());
            } catch (NumberFormatException e) {
                throw CliError.usage("handsim: " + option + ": '" + p[i].trim() + "' is not a number");
            }
            if (!Double.isFinite(v[i])) throw CliError.usage("handsim: " + option + ": " + p[i].trim() + " is not finite");
        }
        return v;
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
