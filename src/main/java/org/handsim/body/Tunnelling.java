package org.handsim.body;

import java.util.Locale;
import org.handsim.mesh.TriangleMesh;

/**
 * Where the step fails by tunnelling: the steps in which some point of the object moved more
 * than the contact margin δ. Contacts come from proximity within δ at the step's start, so a
 * point that travels further than δ in one step can reach a surface, or pass through a thin one,
 * without a contact constraint ever seeing it (DESIGN.md decision 7, "where the method fails").
 *
 * <p>The speed of the fastest point of a rigid body is at most |v| + |ω|·r, v the velocity of the
 * centre of mass, ω the angular velocity, r the body's reach (the largest distance of a vertex
 * from the centre of mass, {@link #reach}); a step of h tunnels when that bound times h exceeds
 * δ. A bound, so it may warn of a step in which no point actually moved δ (the fastest point's
 * speed is |v + ω × r| for the worst r), never miss one that did.
 *
 * <p>Counts them, and keeps the first and the fastest (time at the step's end, speed bound).
 * Not thread-safe; allocation-free.
 */
public final class Tunnelling {
    private final double margin, reach;
    private long steps;
    private double firstTime = Double.NaN, firstSpeed = Double.NaN, fastestTime = Double.NaN, fastestSpeed = Double.NaN;

    /**
     * @param marginM δ, the contact margin (m, &gt; 0)
     * @param reachM  r, the object's reach from its centre of mass (m, ≥ 0)
     */
    public Tunnelling(double marginM, double reachM) {
        if (!(marginM > 0) || !Double.isFinite(marginM)) throw new IllegalArgumentException("contact margin must be a finite number above 0 m, got " + marginM);
        if (!(reachM >= 0) || !Double.isFinite(reachM)) throw new IllegalArgumentException("object reach must be a finite number >= 0 m, got " + reachM);
        this.margin = marginM;
        this.reach = reachM;
    }

    /**
     * r: the largest distance of a vertex of {@code mesh} (its own frame) from the centre of mass
     * {@code props} gives, m.
     */
    public static double reach(TriangleMesh mesh, MassProperties props) {
        double[] v = mesh.vertices(), c = props.comRef();
        double r2 = 0;
        for (int i = 0; i < v.length; i += 3) {
            double dx = v[i] - c[0], dy = v[i + 1] - c[1], dz = v[i + 2] - c[2];
            r2 = Math.max(r2, dx * dx + dy * dy + dz * dz);
        }
        return Math.sqrt(r2);
    }

    /**
     * Looks at one step of h that ended at {@code timeS} with the twist (v, ω) of its drift.
     *
     * @return whether that step tunnelled
     */
    public boolean observe(double timeS, double h, double vx, double vy, double vz, double wx, double wy, double wz) {
        double speed = Math.sqrt(vx * vx + vy * vy + vz * vz) + reach * Math.sqrt(wx * wx + wy * wy + wz * wz);
        if (!(speed * h > margin)) return false;
        if (steps++ == 0) {
            firstTime = timeS;
            firstSpeed = speed;
        }
        if (!(speed <= fastestSpeed)) {
            fastestTime = timeS;
            fastestSpeed = speed;
        }
        return true;
    }

    /** @return whether any step tunnelled */
    public boolean any() { return steps > 0; }

    /** @return the number of steps that tunnelled */
    public long steps() { return steps; }

    /** @return the end time of the first step that tunnelled, s (NaN: none) */
    public double firstTimeS() { return firstTime; }

    /** @return the speed bound in the first step that tunnelled, m/s (NaN: none) */
    public double firstSpeedMS() { return firstSpeed; }

    /** @return the end time of the step with the largest speed bound among those that tunnelled, s (NaN: none) */
    public double fastestTimeS() { return fastestTime; }

    /** @return the largest speed bound among the steps that tunnelled, m/s (NaN: none) */
    public double fastestSpeedMS() { return fastestSpeed; }

    /** @return δ, m */
    public double marginM() { return margin; }

    /** @return r, m */
    public double reachM() { return reach; }

    /** The fastest speed that does not tunnel at step h: δ/h, m/s. */
    public double speedLimitMS(double h) { return margin / h; }

    /** One line for standard error, or null if no step tunnelled. */
    public String warning() {
        if (steps == 0) return null;
        return String.format(Locale.ROOT,
            "warning: the object moved more than the contact margin (%.3g mm) in one step %d time%s (tunnelling: contacts may be"
                + " missed): first at t = %.4f s at %.3g m/s, fastest %.3g m/s at t = %.4f s; a smaller time step helps",
            1e3 * margin, steps, steps == 1 ? "" : "s", firstTime, firstSpeed, fastestSpeed, fastestTime);
    }
}
