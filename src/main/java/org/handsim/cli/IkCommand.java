package org.handsim.cli;

import org.handsim.text.Decimal;
import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.Callable;
import org.handsim.kinematics.IkResult;
import org.handsim.kinematics.InverseKinematics;
import org.handsim.hand.InputRanges;
import org.handsim.text.JsonWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code handsim ik}: inverse kinematics of one finger, or of every row of a CSV file. */
@Command(name = "ik", mixinStandardHelpOptions = true,
    description = {"Inverse kinematics (paper eqs 5-7) with joint limits and the closest reachable point.",
        "Prints",
        "  {\"reachable\":true|false,\"joints\":[t1,t2,t3],\"fingertip\":[x,y,z],\"error_m\":e}",
        "(metres, radians; fingertip in the target's frame; unreachable: the closest",
        "reachable point). Bulk: --input IN.csv with the header",
        "  finger,x,y,z",
        "and --output OUT.csv, which adds the columns",
        "  reachable,t1,t2,t3,error_m"})
public final class IkCommand implements Callable<Integer> {
    static final String IN_HEADER = "finger,x,y,z";
    static final String ADDED_HEADER = "reachable,t1,t2,t3,error_m";

    @Spec CommandSpec spec;

    @Mixin FingerOptions shared;

    @Option(names = "--target", paramLabel = "x,y,z", description = "fingertip target in metres")
    String target;

    @Option(names = "--frame", paramLabel = "base|palm", defaultValue = "base", description = "frame of the target: finger base {k0} (default) or palm {P}")
    String frame;

    @Override
    public Integer call() throws IOException {
        boolean palm = Args.palmFrame(frame);
        if (shared.bulk()) return bulk(palm);
        int k = Args.finger(shared.finger);
        double[] t = Args.numbers("--target", target, 3, InputRanges.POSITION);
        InverseKinematics ik = InverseKinematics.of(k);
        IkResult r = palm ? ik.solveInPalm(t) : ik.solve(t);
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("reachable", r.reachable());
        out.put("joints", Decimal.clean(r.joints()));      // README: |x| < 1e-12 is rounding noise, written as 0
        out.put("fingertip", Decimal.clean(r.fingertip()));
        out.put("error_m", Decimal.clean(r.errorM()));
        spec.commandLine().getOut().println(JsonWriter.write(out));
        return 0;
    }

    private int bulk(boolean palm) throws IOException {
        InverseKinematics[] iks = {InverseKinematics.of(1), InverseKinematics.of(2), InverseKinematics.of(3)};
        double[] t = new double[3];
        return BulkCsv.run(spec, "ik", shared.input, shared.output, shared.finger != null || target != null, "--finger or --target",
            IN_HEADER, ADDED_HEADER, (in, sb) -> {
                int k = BulkCsv.finger(in);
                for (int i = 0; i < 3; i++) t[i] = in.number(i + 1);
                String range = InputRanges.POSITION.problem(new String[] {"x", "y", "z"}, t);
                if (range != null) throw in.error(range);
                IkResult r = palm ? iks[k - 1].solveInPalm(t) : iks[k - 1].solve(t);
                double[] j = r.joints();
                sb.append(',').append(r.reachable()).append(',').append(Args.csv(Decimal.clean(j[0]))).append(',').append(Args.csv(Decimal.clean(j[1])))
                    .append(',').append(Args.csv(Decimal.clean(j[2]))).append(',').append(Args.csv(Decimal.clean(r.errorM())));
            });
    }
}
