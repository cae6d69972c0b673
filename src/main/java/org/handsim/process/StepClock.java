package org.handsim.process;

import java.math.BigDecimal;
import org.handsim.text.Decimal;

/**
 * The time of step n of a fixed time step, as people write it: n × dt computed once from the
 * step count (never accumulated, so no drift) <em>and</em> in decimal, so that step 8947 at
 * dt = 0.001 s is 8.947 s and not the double {@code 8947 * 0.001 = 8.947000000000001}.
 *
 * <p>dt is read as its shortest decimal m × 10^-s ({@link Decimal}); then t = (n·m) / 10^s.
 * While n·m &lt; 2^53 and s ≤ 22 both operands are exact doubles and IEEE division rounds once,
 * so t is the double nearest the exact decimal product (Goldberg 1991, §1.2: a correctly
 * rounded operation on exact operands); beyond that range the product is formed in
 * {@link BigDecimal} and rounded once. The result differs from {@code n * dt} by at most one
 * rounding unit.
 */
public final class StepClock {
    /** 10^0 .. 10^22: every one an exact double (10^22 = 2^22 · 5^22 and 5^22 < 2^53). */
    private static final double[] POWERS = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
        1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    private final double dt;
    private final long mantissa;      // dt = mantissa × 10^-scale
    private final int scale;
    private final double divisor;     // 10^scale, exact when scale ≤ 22
    private final BigDecimal exact;

    /** @param dt the time step, seconds (finite, &gt; 0) */
    public StepClock(double dt) {
        if (!(dt > 0) || !Double.isFinite(dt)) throw new IllegalArgumentException("dt must be a positive finite number, got " + dt);
        this.dt = dt;
        this.exact = new BigDecimal(Decimal.format(dt));
        BigDecimal m = exact.unscaledValue().bitLength() < 53 ? exact : null;
        if (m != null && exact.scale() >= 0 && exact.scale() <= 22) {
            mantissa = exact.unscaledValue().longValue();
            scale = exact.scale();
            divisor = POWERS[scale];
        } else {
            mantissa = 0;
            scale = -1;
            divisor = Double.NaN;
        }
    }

    /** The time step, seconds. */
    public double dt() { return dt; }

    /** The time of step {@code n} (n ≥ 0), seconds: the double nearest n × dt in decimal. */
    public double at(long n) {
        if (scale >= 0 && n >= 0 && n < (1L << 53) / Math.max(1, mantissa)) {
            return (double) (n * mantissa) / divisor;
        }
        return exact.multiply(BigDecimal.valueOf(n)).doubleValue();
    }
}
