package org.handsim.dynamics;

/**
 * Dormand–Prince 5(4), the adaptive embedded Runge–Kutta pair behind MATLAB's {@code ode45}
 * (Dormand and Prince 1980; Hairer–Nørsett–Wanner, <i>Solving ODEs I</i>, §II.4 step-size
 * control, §II.5 the coefficients):
 * seven stages, the last reused as the first of the next step (FSAL), the fifth-order solution
 * propagated and the embedded fourth-order one used only to estimate the local error.
 *
 * <p><b>Error control</b> (HNW §II.4): with {@code sc_i = atol + rtol·max(|y_i|, |y_new,i|)} the
 * error norm is {@code err = sqrt(mean((ŷ_i − y_new,i)/sc_i)²)}; a step is accepted when
 * err ≤ 1, and the next step is {@code h·min(5, max(0.2, 0.9·err^(−1/5)))} (no growth right
 * after a rejection). {@link #step} covers the requested interval exactly with as many accepted
 * steps as that takes (the last one clipped), and remembers the step size for the next call.
 * It fails (false, y unchanged) if f is undefined at a stage or the step size falls below
 * {@code 1e-12·max(1, |t|)} s or more than {@link #MAX_STEPS} steps would be needed.
 *
 * <p>{@link #fixedStep} takes one step of a given size without error control: with it the
 * fifth order is checked by decreasing steps (docs/STYLE.md, item 11).
 */
public final class DormandPrince54 extends AbstractIntegrator {
    /** Most internal steps per call of {@link #step}. */
    public static final int MAX_STEPS = 1_000_000;

    private static final double C2 = 1.0 / 5, C3 = 3.0 / 10, C4 = 4.0 / 5, C5 = 8.0 / 9;
    private static final double A21 = 1.0 / 5;
    private static final double A31 = 3.0 / 40, A32 = 9.0 / 40;
    private static final double A41 = 44.0 / 45, A42 = -56.0 / 15, A43 = 32.0 / 9;
    private static final double A51 = 19372.0 / 6561, A52 = -25360.0 / 2187, A53 = 64448.0 / 6561, A54 = -212.0 / 729;
    private static final double A61 = 9017.0 / 3168, A62 = -355.0 / 33, A63 = 46732.0 / 5247, A64 = 49.0 / 176,
        A65 = -5103.0 / 18656;
    private static final double B1 = 35.0 / 384, B3 = 500.0 / 1113, B4 = 125.0 / 192, B5 = -2187.0 / 6784, B6 = 11.0 / 84;
    // b − b̂ (fifth- minus fourth-order weights)
    private static final double E1 = 71.0 / 57600, E3 = -71.0 / 16695, E4 = 71.0 / 1920, E5 = -17253.0 / 339200,
        E6 = 22.0 / 525, E7 = -1.0 / 40;

    private final double absTol, relTol;
    private final double[] k1, k2, k3, k4, k5, k6, k7, tmp, yNew, y0;
    private double hNext = Double.NaN;
    private double lastError;
    private long accepted, rejected;
    // FSAL bookkeeping: k1 holds f(fsalT, fsalY) of fsalOde when fsalValid
    private boolean fsalValid;
    private Ode fsalOde;
    private double fsalT;
    private final double[] fsalY;

    /**
     * @param dimension state length
     * @param absTol    absolute tolerance (state units, > 0)
     * @param relTol    relative tolerance (≥ 0)
     */
    public DormandPrince54(int dimension, double absTol, double relTol) {
        super(dimension);
        if (!(absTol > 0) || !Double.isFinite(absTol)) throw new IllegalArgumentException("absTol must be finite and > 0, got " + absTol);
        if (!(relTol >= 0) || !Double.isFinite(relTol)) throw new IllegalArgumentException("relTol must be finite and >= 0, got " + relTol);
        this.absTol = absTol;
        this.relTol = relTol;
        k1 = new double[dimension];
        k2 = new double[dimension];
        k3 = new double[dimension];
        k4 = new double[dimension];
        k5 = new double[dimension];
        k6 = new double[dimension];
        k7 = new double[dimension];
        tmp = new double[dimension];
        yNew = new double[dimension];
        y0 = new double[dimension];
        fsalY = new double[dimension];
    }

    @Override
    public String name() {
        return "dopri5";
    }

    @Override
    public int order() {
        return 5;
    }

    /** @return the absolute tolerance */
    public double absTol() {
        return absTol;
    }

    /** @return the relative tolerance */
    public double relTol() {
        return relTol;
    }

    /** @return accepted internal steps since construction */
    public long acceptedSteps() {
        return accepted;
    }

    /** @return rejected internal steps since construction */
    public long rejectedSteps() {
        return rejected;
    }

    /** @return the scaled error norm of the last attempted step (≤ 1 means accepted) */
    public double lastError() {
        return lastError;
    }

    /** Forgets the remembered step size and the FSAL stage (e.g. after the state jumped). */
    public void reset() {
        hNext = Double.NaN;
        fsalValid = false;
    }

    @Override
    public boolean step(Ode ode, double t, double[] y, double h) {
        check(ode, y, h);
        System.arraycopy(y, 0, y0, 0, n);
        double tEnd = t + h;
        double hTry = Double.isNaN(hNext) ? h : Math.min(hNext, h);
        boolean lastRejected = false;
        for (int steps = 0; steps < MAX_STEPS; steps++) {
            double remaining = tEnd - t;
            if (remaining <= 0) return true;
            boolean last = hTry >= remaining * (1 - 1e-12);
            double hs = last ? remaining : hTry;
            if (hs < 1e-12 * Math.max(1.0, Math.abs(t))) return fail(y);
            if (!stages(ode, t, y, hs)) return fail(y);
            double err = lastError;
            if (err <= 1.0) {
                accepted++;
                t = last ? tEnd : t + hs;
                System.arraycopy(yNew, 0, y, 0, n);
                System.arraycopy(k7, 0, k1, 0, n);
                remember(ode, t, y);
                double grow = err == 0 ? 5.0 : Math.min(5.0, Math.max(0.2, 0.9 * Math.pow(err, -0.2)));
                if (lastRejected) grow = Math.min(1.0, grow);
                double proposed = hs * grow;
                // a clipped final step says little about the natural step size: keep the larger
                hNext = last ? Math.max(proposed, Math.min(hTry, hs * 5.0)) : proposed;
                hTry = hNext;
                lastRejected = false;
                if (last) return true;
            } else {
                rejected++;
                lastRejected = true;
                hTry = hs * Math.max(0.2, 0.9 * Math.pow(err, -0.2));
            }
        }
        return fail(y);
    }

    /**
     * One Dormand–Prince step of exactly {@code h} without error control: y becomes the
     * fifth-order solution; {@link #lastError()} holds the error estimate.
     *
     * @return false if f was undefined at a stage (y unchanged)
     */
    public boolean fixedStep(Ode ode, double t, double[] y, double h) {
        check(ode, y, h);
        if (!stages(ode, t, y, h)) return false;
        System.arraycopy(yNew, 0, y, 0, n);
        System.arraycopy(k7, 0, k1, 0, n);
        remember(ode, t + h, y);
        return true;
    }

    private boolean fail(double[] y) {
        System.arraycopy(y0, 0, y, 0, n);
        fsalValid = false;
        return false;
    }

    private void remember(Ode ode, double t, double[] y) {
        fsalValid = true;
        fsalOde = ode;
        fsalT = t;
        System.arraycopy(y, 0, fsalY, 0, n);
    }

    private boolean fsalHolds(Ode ode, double t, double[] y) {
        // t may differ from the remembered end time by rounding (t0 + h vs the caller's i·h)
        if (!fsalValid || ode != fsalOde || Math.abs(t - fsalT) > 4 * Math.ulp(Math.max(Math.abs(t), Math.abs(fsalT)))) return false;
        for (int i = 0; i < n; i++) {
            if (y[i] != fsalY[i]) return false;
        }
        return true;
    }

    /** The seven stages from (t, y) with step h: yNew and lastError set; k7 = f(t + h, yNew). */
    private boolean stages(Ode ode, double t, double[] y, double h) {
        if (!fsalHolds(ode, t, y)) {
            if (!eval(ode, t, y, k1)) return false;
            remember(ode, t, y);
        }
        for (int i = 0; i < n; i++) tmp[i] = y[i] + h * A21 * k1[i];
        if (!eval(ode, t + C2 * h, tmp, k2)) return false;
        for (int i = 0; i < n; i++) tmp[i] = y[i] + h * (A31 * k1[i] + A32 * k2[i]);
        if (!eval(ode, t + C3 * h, tmp, k3)) return false;
        for (int i = 0; i < n; i++) tmp[i] = y[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i]);
        if (!eval(ode, t + C4 * h, tmp, k4)) return false;
        for (int i = 0; i < n; i++) tmp[i] = y[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i]);
        if (!eval(ode, t + C5 * h, tmp, k5)) return false;
        for (int i = 0; i < n; i++) tmp[i] = y[i] + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i]);
        if (!eval(ode, t + h, tmp, k6)) return false;
        for (int i = 0; i < n; i++) yNew[i] = y[i] + h * (B1 * k1[i] + B3 * k3[i] + B4 * k4[i] + B5 * k5[i] + B6 * k6[i]);
        if (!eval(ode, t + h, yNew, k7)) return false;
        double sum = 0;
        for (int i = 0; i < n; i++) {
            double e = h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
            double sc = absTol + relTol * Math.max(Math.abs(y[i]), Math.abs(yNew[i]));
            double r = e / sc;
            sum += r * r;
        }
        lastError = Math.sqrt(sum / n);
        if (Double.isNaN(lastError)) lastError = Double.POSITIVE_INFINITY;
        return true;
    }
}
