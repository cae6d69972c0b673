package org.handsim.hand;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.handsim.files.InputFile;
import org.handsim.math.RigidTransform;
import org.handsim.text.Json;
import org.handsim.text.JsonObject;

/**
 * The whole hand, loaded from a description file (JSON). {@link #barrettHand()} is the
 * BarrettHand BH8-262 from the bundled resource {@code barretthand.json}; {@link #parse} loads
 * any file of the same form, e.g. a hand with modified parameters for a study.
 *
 * <p>Validation: a missing field, a non-finite number, a negative or zero mass or length, or
 * an inertia tensor that no body has (not positive definite about its centre of mass, or
 * breaking the triangle inequality there) is a {@link HandDescriptionException}
 * naming the file and the field path (e.g. {@code mass_properties.links[1].inertia_kgm2}).
 *
 * <p>Units inside: metres, radians, kg. The file holds degrees and encoder counts (the edges,
 * DESIGN.md "Conventions"), converted here, once.
 *
 * <p>Immutable and thread-safe.
 */
public final class HandDescription {
    private static final String RESOURCE = "barretthand.json";
    private static volatile HandDescription barrett;

    private final String name;
    private final FingerDescription[] fingers;
    private final double a1, a2, a3;
    private final double palmAw, palmDw;
    private final double innerCountsPerDeg, outerCountsPerDeg;
    private final int fingerCountsMax, spreadCountsMax;
    private final double[] theta2Limits, theta3Limits, spreadLimits;
    private final double tauBreak, kClutch;
    private final double motorVMax, motorAMax;
    private final double fingerRatingN, fingerRatingKg;

    /** Reads and validates {@code root}; a {@link Json.JsonException} thrown here becomes a {@link HandDescriptionException} in {@link #parse}. */
    private HandDescription(JsonObject root) {
        name = root.string("name");
        JsonObject links = root.object("links");
        a1 = links.positive("A1_m");
        a2 = links.positive("A2_m");
        a3 = links.positive("A3_m");
        double[] alpha = {rad(links.number("alpha1_deg")), rad(links.number("alpha2_deg")), rad(links.number("alpha3_deg"))};
        double[] d = {links.number("d1_m"), links.number("d2_m"), links.number("d3_m")};
        double phi2 = rad(links.number("phi2_deg"));
        double phi3 = rad(links.number("phi3_deg"));
        DhRow[] dh = {
            new DhRow(a1, alpha[0], d[0], 0.0),
            new DhRow(a2, alpha[1], d[1], phi2),
            new DhRow(a3, alpha[2], d[2], phi3)};

        JsonObject palm = root.object("palm");
        palmAw = palm.nonNegative("Aw_m");
        palmDw = palm.number("Dw_m");

        JsonObject tr = root.object("transmission");
        innerCountsPerDeg = tr.positive("inner_counts_per_deg");
        outerCountsPerDeg = tr.positive("outer_counts_per_deg");
        fingerCountsMax = tr.integer("finger_counts_max");
        spreadCountsMax = tr.integer("spread_counts_max");
        if (fingerCountsMax <= 0) throw tr.error("finger_counts_max", "must be > 0");
        if (spreadCountsMax <= 0) throw tr.error("spread_counts_max", "must be > 0");

        JsonObject lim = root.object("joint_limits_deg");
        theta2Limits = range(lim, "theta2");
        theta3Limits = range(lim, "theta3");
        spreadLimits = range(lim, "spread");

        JsonObject mp = root.object("mass_properties");
        if (mp.list("links").size() != 3) throw mp.error("links", "must list exactly 3 links");
        LinkInertia[] inertias = new LinkInertia[3];
        for (int j = 0; j < 3; j++) inertias[j] = linkInertia(mp.objectAt("links", j));

        int nf = root.list("fingers").size();
        if (nf != 3) throw root.error("fingers", "must list exactly 3 fingers, got " + nf);
        fingers = new FingerDescription[3];
        for (int i = 0; i < 3; i++) {
            JsonObject f = root.objectAt("fingers", i);
            int k = f.integer("finger");
            if (k != i + 1) throw f.error("finger", "must be " + (i + 1) + ", got " + k);
            int rTable = f.integer("r_table1");
            if (rTable != 0 && rTable != 1) throw f.error("r_table1", "must be 0 or 1, got " + rTable);
            double rPalm = f.number("r_palm");
            double jPalm = f.number("j_palm");
            // BH8 manual Table 9: spread axis at x = r*Aw, height Dw, base turned by -(pi/2)*j about z.
            RigidTransform base = RigidTransform.translation(rPalm * palmAw, 0, palmDw)
                .compose(RigidTransform.rotZ(-Math.PI / 2 * jPalm));
            double spreadPerCount = rad(f.number("spread_deg_per_count"));
            if (rTable == 0 && spreadPerCount != 0) {
                throw f.error("spread_deg_per_count", "must be 0 for a finger without spread (r_table1 = 0)");
            }
            fingers[i] = new FingerDescription(k, dh, base, rTable == 1, spreadPerCount, inertias);
        }

        JsonObject motors = root.object("motor_limits");
        motorVMax = motors.positive("v_max_counts_s");
        motorAMax = motors.positive("a_max_counts_s2");
        JsonObject clutch = root.object("clutch");
        tauBreak = clutch.positive("tau_break_Nm");
        kClutch = clutch.positive("k_clutch_Nm_per_rad");
        JsonObject hold = root.object("hold");
        fingerRatingKg = hold.positive("finger_rating_kg");
        fingerRatingN = fingerRatingKg * hold.positive("g_m_s2");
    }

    /** A copy with other values (the fields of {@link #with}). */
    private HandDescription(HandDescription h, int fingerCountsMax, int spreadCountsMax, double[] theta2Limits, double[] theta3Limits,
                            double[] spreadLimits, double tauBreak, double kClutch, double motorVMax, double motorAMax) {
        name = h.name;
        fingers = h.fingers;
        a1 = h.a1; a2 = h.a2; a3 = h.a3;
        palmAw = h.palmAw; palmDw = h.palmDw;
        innerCountsPerDeg = h.innerCountsPerDeg; outerCountsPerDeg = h.outerCountsPerDeg;
        this.fingerCountsMax = fingerCountsMax;
        this.spreadCountsMax = spreadCountsMax;
        this.theta2Limits = theta2Limits;
        this.theta3Limits = theta3Limits;
        this.spreadLimits = spreadLimits;
        this.tauBreak = tauBreak;
        this.kClutch = kClutch;
        this.motorVMax = motorVMax;
        this.motorAMax = motorAMax;
        fingerRatingN = h.fingerRatingN;
        fingerRatingKg = h.fingerRatingKg;
    }

    /**
     * This hand with a scenario's overrides ({@link HandParameters}, valid: {@link HandParameters#problem}
     * null), the derived values following (DESIGN.md decision 1, "Hand parameters"): k_clutch =
     * τ_break / wind-up, the wind-up being the given one, else τ_break / the given stiffness, else
     * this hand's (τ_break / k_clutch: 10°); the finger count range 0 to 125·θk2,max (eq 3), the
     * spread's 0 to 3150/180·spread_max (eqs 1–2). This object when nothing is overridden.
     */
    public HandDescription with(HandParameters p) {
        if (p == null || p.isEmpty()) return this;
        String why = p.problem();
        if (why != null) throw new IllegalArgumentException(why);
        double tau = p.tauBreakNm() != null ? p.tauBreakNm() : tauBreak;
        double windupRad = p.windupDeg() != null ? Math.toRadians(p.windupDeg())
            : p.kClutchNmPerRad() != null ? tau / p.kClutchNmPerRad() : tauBreak / kClutch;
        double k = p.kClutchNmPerRad() != null ? p.kClutchNmPerRad() : p.windupDeg() == null && p.tauBreakNm() == null ? kClutch : tau / windupRad;
        double[] t2 = p.theta2LimitsDeg() != null ? new double[] {rad(p.theta2LimitsDeg()[0]), rad(p.theta2LimitsDeg()[1])} : theta2Limits;
        double[] t3 = p.theta3LimitsDeg() != null ? new double[] {rad(p.theta3LimitsDeg()[0]), rad(p.theta3LimitsDeg()[1])} : theta3Limits;
        double[] sp = p.spreadLimitsDeg() != null ? new double[] {rad(p.spreadLimitsDeg()[0]), rad(p.spreadLimitsDeg()[1])} : spreadLimits;
        int fingerMax = p.theta2LimitsDeg() != null ? (int) Math.round(p.theta2LimitsDeg()[1] * innerCountsPerDeg) : fingerCountsMax;
        int spreadMax = p.spreadLimitsDeg() != null ? (int) Math.round(p.spreadLimitsDeg()[1] / 180.0 * 3150) : spreadCountsMax;
        return new HandDescription(this, fingerMax, spreadMax, t2, t3, sp, tau, k,
            p.motorVMaxCountsS() != null ? p.motorVMaxCountsS() : motorVMax, p.motorAMaxCountsS2() != null ? p.motorAMaxCountsS2() : motorAMax);
    }

    /**
     * The values this hand runs with, as {@code summary.json}'s {@code hand_parameters} records
     * them: τ_break, k_clutch, the wind-up angle, the motor limits, the joint ranges (degrees).
     */
    public java.util.Map<String, Object> parametersJson() {
        java.util.Map<String, Object> m = new java.util.LinkedHashMap<>();
        m.put("tau_break_Nm", tauBreak);
        m.put("k_clutch_Nm_per_rad", kClutch);
        m.put("windup_deg", Math.toDegrees(tauBreak / kClutch));
        m.put("motor_v_max_counts_s", motorVMax);
        m.put("motor_a_max_counts_s2", motorAMax);
        m.put("theta2_limits_deg", new double[] {Math.toDegrees(theta2Limits[0]), Math.toDegrees(theta2Limits[1])});
        m.put("theta3_limits_deg", new double[] {Math.toDegrees(theta3Limits[0]), Math.toDegrees(theta3Limits[1])});
        m.put("spread_limits_deg", new double[] {Math.toDegrees(spreadLimits[0]), Math.toDegrees(spreadLimits[1])});
        return m;
    }

    /** The fastest a motor's set-point may move, counts/s (the hand file's {@code motor_limits}). */
    public double motorVMax() { return motorVMax; }
    /** The largest acceleration of a motor's set-point, counts/s². */
    public double motorAMax() { return motorAMax; }

    /** The BarrettHand BH8-262 from the bundled resource (loaded once, shared). */
    public static HandDescription barrettHand() {
        HandDescription h = barrett;
        if (h == null) {
            try (InputStream in = HandDescription.class.getResourceAsStream(RESOURCE)) {
                if (in == null) throw new IllegalStateException("resource " + RESOURCE + " is missing from the classpath");
                h = parse(RESOURCE, new String(in.readAllBytes(), StandardCharsets.UTF_8));
            } catch (IOException e) {
                throw new IllegalStateException("cannot read resource " + RESOURCE, e);
            }
            barrett = h;
        }
        return h;
    }

    /** Largest hand description file accepted: the bundled one is 7 KB. */
    public static final long MAX_FILE_BYTES = 1 << 20;

    /**
     * Loads a description file through the input gate ({@link InputFile}: a regular file of at
     * most {@link #MAX_FILE_BYTES}, UTF-8).
     *
     * @throws InputFile.InputFileException naming the file: not a regular file, too large, not UTF-8
     */
    public static HandDescription load(Path file) throws IOException {
        return parse(file.toString(), InputFile.readText(file, MAX_FILE_BYTES, "the limit of hand files"));
    }

    /**
     * Parses description text; {@code source} names it in error messages.
     *
     * @throws HandDescriptionException naming the file, line/column or field path
     */
    public static HandDescription parse(String source, String text) {
        try {
            return new HandDescription(JsonObject.parse(source, text));
        } catch (Json.JsonException e) {
            throw new HandDescriptionException(e.getMessage());
        }
    }

    private static double rad(double deg) {
        return Math.toRadians(deg);
    }

    private static double[] range(JsonObject o, String field) {
        double[] r = o.numbers(field, 2);
        if (!(r[0] < r[1])) throw o.error(field, "lower limit must be below the upper, got " + r[0] + ", " + r[1]);
        return new double[] {rad(r[0]), rad(r[1])};
    }

    /**
     * One link of Table III: the tensor about the origin of {kj} with the products as printed,
     * +∫xy dm (the CAD sign), negated here into matrix entries ({@link LinkInertia}). A link must
     * be a physical body: its second moments about the centre of mass
     * ({@link LinkInertia#secondMomentsAboutCentreOfMass()}) positive definite, which is the
     * tensor about the centre of mass positive definite and within the triangle inequality.
     */
    private static LinkInertia linkInertia(JsonObject l) {
        double m = l.number("mass_kg");
        if (!(m > 0)) throw l.error("mass_kg", "must be > 0, got " + m);
        double[] com = l.numbers("com_m", 3);
        JsonObject in = l.object("inertia_kgm2");
        double[] t = {in.number("xx"), -in.number("xy"), -in.number("xz"), in.number("yy"), -in.number("yz"), in.number("zz")};
        LinkInertia link = new LinkInertia(m, com, t);
        // Positive definite by Sylvester's criterion (leading principal minors > 0).
        double[] s = link.secondMomentsAboutCentreOfMass();
        double m1 = s[0];
        double m2 = s[0] * s[3] - s[1] * s[1];
        double m3 = s[0] * (s[3] * s[5] - s[4] * s[4]) - s[1] * (s[1] * s[5] - s[4] * s[2]) + s[2] * (s[1] * s[4] - s[3] * s[2]);
        if (!(m1 > 0 && m2 > 0 && m3 > 0)) {
            throw l.error("inertia_kgm2", "is not a physical body: about the centre of mass it is not positive definite"
                + " or breaks the triangle inequality (leading minors of the second moments " + m1 + ", " + m2 + ", " + m3 + ")");
        }
        return link;
    }

    public String name() { return name; }

    /** @param k finger number 1, 2 or 3 */
    public FingerDescription finger(int k) {
        if (k < 1 || k > 3) throw new IllegalArgumentException("finger must be 1, 2 or 3, got " + k);
        return fingers[k - 1];
    }

    /** Link lengths A1, A2, A3 (metres, Table II). */
    public double a1() { return a1; }
    public double a2() { return a2; }
    public double a3() { return a3; }
    /** Palm placement (metres, BH8 manual Table 9). */
    public double palmAw() { return palmAw; }
    public double palmDw() { return palmDw; }
    /** Encoder counts per degree of the inner joint (125, eq 3) and outer joint (375, eq 4). */
    public double innerCountsPerDeg() { return innerCountsPerDeg; }
    public double outerCountsPerDeg() { return outerCountsPerDeg; }
    /** Count ranges: q_Mk ∈ [0, fingerCountsMax], q_M4 ∈ [0, spreadCountsMax]. */
    public int fingerCountsMax() { return fingerCountsMax; }
    public int spreadCountsMax() { return spreadCountsMax; }
    /** Joint limits of θk2, θk3 and of the spread magnitude |θk1|, radians {lo, hi} (new arrays). */
    public double[] theta2Limits() { return theta2Limits.clone(); }
    public double[] theta3Limits() { return theta3Limits.clone(); }
    public double[] spreadLimits() { return spreadLimits.clone(); }
    /** Breakaway threshold τ_break in N·m (Section V). */
    public double tauBreak() { return tauBreak; }
    /** Clutch (Belleville spring) stiffness k_clutch in N·m/rad (DESIGN.md decision 1). */
    public double kClutch() { return kClutch; }
    /** Barrett's rated load of one finger at its tip, newtons (2 kg × g; the hand file's {@code hold}). */
    public double fingerRatingN() { return fingerRatingN; }
    /** Barrett's rated load of one finger as a mass, kg (the hand file's {@code hold.finger_rating_kg}). */
    public double fingerRatingKg() { return fingerRatingKg; }
    /** The hand's rated load, the three fingers' ratings, newtons: the largest hold HandSim reports. */
    public double handRatingN() { return 3 * fingerRatingN; }
    /**
     * The lever of joint j (1 spread, 2 inner, 3 outer) to the fingertip of the stretched
     * finger, metres: A1 + A2 + A3, A2 + A3, A3 (Table II). A joint torque over it is the
     * fingertip-equivalent force, which Barrett's rating ({@link #fingerRatingN}) bounds.
     */
    public double leverToTip(int joint) {
        switch (joint) {
            case 1: return a1 + a2 + a3;
            case 2: return a2 + a3;
            case 3: return a3;
            default: throw new IllegalArgumentException("joint must be 1, 2 or 3, got " + joint);
        }
    }

    @Override
    public String toString() {
        return "HandDescription[" + name + "]";
    }
}
