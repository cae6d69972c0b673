package org.handsim.cli;

import org.handsim.text.SafeText;
import org.handsim.text.Decimal;
import java.io.IOException;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.Callable;
import org.handsim.kinematics.FingerKinematics;
import org.handsim.kinematics.Transmission;
import org.handsim.hand.InputRanges;
import org.handsim.text.JsonWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code handsim fk}: forward kinematics of one finger, or of every row of a CSV file. */
@Command(name = "fk", mixinStandardHelpOptions = true,
    description = {"Forward kinematics (paper Section II.A): the origins of frames {k0}..{k3} and the fingertip.",
        "Prints",
        "  {\"finger\":K,\"frame\":\"base\",\"joints\":[t1,t2,t3],",
        "   \"origins\":[[x,y,z],[x,y,z],[x,y,z],[x,y,z]],\"fingertip\":[x,y,z]}",
        "(metres; joints in radians). Bulk: --input IN.csv with the header",
        "  finger,t1,t2,t3",
        "and --output OUT.csv, which adds the columns (base frame)",
        "  o0x,o0y,o0z,o1x,o1y,o1z,o2x,o2y,o2z,o3x,o3y,o3z"})
public final class FkCommand implements Callable<Integer> {
    static final String IN_HEADER = "finger,t1,t2,t3";
    static final String ADDED_HEADER = "o0x,o0y,o0z,o1x,o1y,o1z,o2x,o2y,o2z,o3x,o3y,o3z";

    @Spec CommandSpec spec;

    @Mixin FingerOptions shared;

    @Option(names = "--joints", paramLabel = "t1,t2,t3", description = "joint angles in radians (finger 3: t1 = 0)")
    String joints;

    @Option(names = "--counts", paramLabel = "q[,qSpread]", description = "motor encoder counts: q_Mk in [0, 17500], optional spread q_M4 in [0, 3150]")
    String counts;

    @Option(names = "--frame", paramLabel = "base|palm", defaultValue = "base", description = "frame of the output: finger base {k0} (default) or palm {P}")
    String frame;

    @Override
    public Integer call() throws IOException {
        boolean palm = Args.palmFrame(frame);
        if (shared.bulk()) return bulk(palm);
        int k = Args.finger(shared.finger);
        double[] j;
        if ((joints == null) == (counts == null)) throw CliError.usage("handsim: give exactly one of --joints or --counts");
        if (joints != null) {
            j = Args.numbers("--joints", joints, 3, InputRanges.JOINT_ANGLE);
        } else {
            String[] p = counts.split(",", -1);
            if (p.length < 1 || p.length > 2) throw CliError.usage("handsim: --counts needs q or q,qSpread, got '" + SafeText.quote(counts) + "'");
            double[] q = Args.numbers("--counts", counts, p.length);
            try {
                j = Transmission.barrettHand().joints(k, q[0], p.length == 2 ? q[1] : 0, null);
            } catch (IllegalArgumentException e) {
                throw CliError.usage("handsim: --counts: " + e.getMessage());
            }
        }
        double[] frames = new double[FingerKinematics.FRAMES_LENGTH];
        try {
            FingerKinematics fk = FingerKinematics.of(k);
            if (palm) fk.framesInPalm(j, frames); else fk.frames(j, frames);
        } catch (IllegalArgumentException e) {
            throw CliError.usage("handsim: --joints: " + e.getMessage());
        }
        double[][] origins = new double[4][];
        for (int i = 0; i < 4; i++) origins[i] = new double[] {frames[12 * i + 3], frames[12 * i + 7], frames[12 * i + 11]};
        Map<String, Object> out = new LinkedHashMap<>();
        out.put("finger", k);
        out.put("frame", frame);
        out.put("joints", Decimal.clean(j));          // README: |x| < 1e-12 is rounding noise, written as 0
        out.put("origins", Decimal.clean(origins));
        out.put("fingertip", Decimal.clean(origins[3]));
        spec.commandLine().getOut().println(JsonWriter.write(out));
        return 0;
    }

    private int bulk(boolean palm) throws IOException {
        FingerKinematics[] fks = {FingerKinematics.of(1), FingerKinematics.of(2), FingerKinematics.of(3)};
        double[] frames = new double[FingerKinematics.FRAMES_LENGTH];
        double[] j = new double[3];
        return BulkCsv.run(spec, "fk", shared.input, shared.output, shared.finger != null || joints != null || counts != null,
            "--finger, --joints or --counts", IN_HEADER, ADDED_HEADER, (in, sb) -> {
                int k = BulkCsv.finger(in);
                for (int i = 0; i < 3; i++) j[i] = in.number(i + 1);
                String range = InputRanges.JOINT_ANGLE.problem(new String[] {"t1", "t2", "t3"}, j);
                if (range != null) throw in.error(range);
                try {
                    if (palm) fks[k - 1].framesInPalm(j, frames); else fks[k - 1].frames(j, frames);
                } catch (IllegalArgumentException e) {
                    throw in.error(e.getMessage());
                }
                for (int f = 0; f < 4; f++) {
                    for (int c = 0; c < 3; c++) sb.append(',').append(Args.csv(Decimal.clean(frames[12 * f + 4 * c + 3])));
                }
            });
    }
}
