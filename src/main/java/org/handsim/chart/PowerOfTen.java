package org.handsim.chart;

import java.text.FieldPosition;
import java.text.NumberFormat;
import java.text.ParsePosition;

/**
 * Tick labels of a log axis as powers of ten written as a paper writes them — 10⁻¹², 10⁰, 10³ —
 * with Unicode superscripts (every font the charts use has them), not Java's 1E-12.
 * A value that is not a whole power of ten keeps its mantissa: 2×10⁻³.
 */
final class PowerOfTen extends NumberFormat {
    private static final long serialVersionUID = 1L;
    private static final String SUPERSCRIPT = "⁰¹²³⁴⁵⁶⁷⁸⁹";

    /** {@code 10} followed by the exponent in superscript digits, e.g. {@code 10⁻¹²}. */
    static String power(int exponent) {
        StringBuilder sb = new StringBuilder("10");
        if (exponent < 0) sb.append('⁻');
        for (char c : Integer.toString(Math.abs(exponent)).toCharArray()) sb.append(SUPERSCRIPT.charAt(c - '0'));
        return sb.toString();
    }

    @Override
    public StringBuffer format(double v, StringBuffer to, FieldPosition pos) {
        if (!(v > 0) || !Double.isFinite(v)) return to.append(v == 0 ? "0" : Double.toString(v));
        int e = (int) Math.floor(Math.log10(v) + 1e-9);
        double m = v / Math.pow(10, e);
        if (Math.abs(m - Math.rint(m)) < 1e-6 && Math.rint(m) == 1) return to.append(power(e));
        return to.append(String.format(java.util.Locale.ROOT, "%.3g", m).replaceAll("\\.?0+$", "")).append('×').append(power(e));
    }

    @Override
    public StringBuffer format(long v, StringBuffer to, FieldPosition pos) {
        return format((double) v, to, pos);
    }

    @Override
    public Number parse(String source, ParsePosition pos) {
        throw new UnsupportedOperationException("tick labels are only written");
    }
}
