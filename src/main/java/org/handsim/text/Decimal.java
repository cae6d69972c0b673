package org.handsim.text;

import com.fasterxml.jackson.core.io.NumberOutput;

/**
 * The one number format of every command output — JSON, CSV and console: numbers as people
 * read them. A double is written as ECMAScript's {@code Number.prototype.toString}
 * writes it (ECMA-262, 7.1.12.1 Number::toString; what {@code JSON.stringify} and Python's
 * {@code json} read back exactly):
 * <ul>
 *   <li>the <em>shortest</em> decimal that reads back as the same double (Schubfach, R. Giulietti
 *       2020, through jackson-core's {@code NumberOutput}: Java 17's {@code Double.toString} is
 *       not always shortest, e.g. {@code 9.999999999999999E22} for 1e23, fixed only in Java 19);</li>
 *   <li>integers without a fraction: {@code 44732}, never {@code 44732.0};</li>
 *   <li>plain decimals for 1e-6 ≤ |x| &lt; 1e21 ({@code 0.0005}, {@code 8.947}); exponent form
 *       outside that range with a lower-case {@code e} and a sign: {@code 4.9e-19},
 *       {@code 1.5e+21};</li>
 *   <li>{@code -0.0} as {@code 0};</li>
 *   <li>NaN and infinities are refused ({@link IllegalArgumentException}): a command never
 *       writes them silently.</li>
 * </ul>
 * Worked example: {@code 8947 * 0.001} is the double {@code 8.947000000000001} (its shortest
 * form has 16 digits because it is not the double nearest 8.947); that is why times are not
 * formatted away but computed cleanly by {@link StepClock}. {@code 5.0E-4} becomes
 * {@code 0.0005}, {@code 1.0E7} becomes {@code 10000000}.
 *
 * <p><b>Zero up to rounding.</b> {@link #clean(double)} maps magnitudes below
 * {@link #ZERO_BELOW} to 0. It is applied where the README says so — quantities of the hand in
 * SI units (coordinates in metres, angles in radians, torques in N·m, forces in N, their rates)
 * whose exact value is 0 but whose computation through sines and cosines leaves about 1e-17
 * (e.g. {@code 5.6E-18} m off the plane of a finger). Never to ratios or errors (a relative
 * error of 1e-16 is a result).
 */
public final class Decimal {
    /** Physical values below this magnitude (SI units) are rounding noise: {@link #clean} makes them 0. */
    public static final double ZERO_BELOW = 1e-12;

    private Decimal() {}

    /** The text of a finite double (see the class comment). */
    public static String format(double d) {
        StringBuilder sb = new StringBuilder(24);
        append(sb, d);
        return sb.toString();
    }

    /** What {@link #parse} reads: an optional sign, digits with an optional point, an optional exponent. */
    private static final java.util.regex.Pattern NUMBER = java.util.regex.Pattern.compile("[-+]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?");

    /**
     * The one reader of numbers typed by people (options, CSV cells, script arguments): a
     * decimal such as {@code 12}, {@code -0.5}, {@code .5}, {@code 1e-3}, {@code 2.5E+2}, spaces
     * around it ignored. Unlike {@link Double#parseDouble} it refuses Java's other spellings —
     * {@code 0d}, {@code 1f}, {@code 0x1p3}, {@code NaN}, {@code Infinity} — which are not
     * numbers to anyone but a Java compiler. A decimal beyond the double range reads as an
     * infinity (callers refuse it as not finite, naming the value).
     *
     * @throws NumberFormatException for anything else, its message quoting the text
     */
    public static double parse(String text) {
        String t = text == null ? "" : text.trim();
        if (!NUMBER.matcher(t).matches()) throw new NumberFormatException("'" + SafeText.quote(t) + "' is not a number");
        return Double.parseDouble(t);
    }

    /**
     * A large count as a person reads it in a message: below a million its digits ({@code 8947}),
     * then two significant decimals and a word ({@code 8.9 million}, {@code 8.95 billion},
     * {@code 12 trillion}), and beyond 10^15 the exponent form ({@code 1e+303}). Never
     * {@code 9223372036854775807}: a count too large for a long is given as the double it is.
     */
    public static String count(double n) {
        if (!Double.isFinite(n)) return Double.isNaN(n) ? "an undefined number of" : "infinitely many";
        if (!(Math.abs(n) < 1e6)) {
            String[] words = {"million", "billion", "trillion"};
            for (int i = 0; i < words.length; i++) {
                double unit = Math.pow(1000, i + 2);
                if (Math.abs(n) < unit * 1000) {
                    double v = new java.math.BigDecimal(n / unit).round(new java.math.MathContext(3)).doubleValue();
                    if (v >= 1000 && i + 1 < words.length) continue;
                    return format(v) + " " + words[i];
                }
            }
            java.math.BigDecimal b = new java.math.BigDecimal(n).round(new java.math.MathContext(3));
            int exp = b.precision() - b.scale() - 1;
            return b.movePointLeft(exp).stripTrailingZeros().toPlainString() + "e+" + exp;
        }
        return format(Math.rint(n));
    }

    /** The text of a long (plain digits). */
    public static String format(long n) {
        return Long.toString(n);
    }

    /** The text of a double, or the empty string for NaN (an empty CSV cell: "none"). */
    public static String orEmpty(double d) {
        return Double.isNaN(d) ? "" : format(d);
    }

    /** 0 for a magnitude below {@link #ZERO_BELOW}, else {@code d} (physical values only). */
    public static double clean(double d) {
        return Math.abs(d) < ZERO_BELOW ? 0.0 : d;
    }

    /** A copy of {@code a} with {@link #clean(double)} applied to every element. */
    public static double[] clean(double[] a) {
        double[] c = new double[a.length];
        for (int i = 0; i < a.length; i++) c[i] = clean(a[i]);
        return c;
    }

    /** A copy of {@code a} with {@link #clean(double)} applied to every element. */
    public static double[][] clean(double[][] a) {
        double[][] c = new double[a.length][];
        for (int i = 0; i < a.length; i++) c[i] = clean(a[i]);
        return c;
    }

    /**
     * Appends the text of a finite double.
     *
     * <p>Each thread keeps the texts of the last {@value #MEMO_SLOTS} values it wrote (a
     * direct-mapped table keyed by the bits), so a value written again — most cells of a trace
     * repeat the row above: 92 % of the paper's, 79 % of the mug's — is copied, not formatted;
     * the text is the same either way.
     *
     * @throws IllegalArgumentException for NaN or an infinity
     */
    public static StringBuilder append(StringBuilder sb, double d) {
        if (!Double.isFinite(d)) throw new IllegalArgumentException("refusing to write a non-finite number (" + d + ")");
        if (d == 0) return sb.append('0');
        if (Math.abs(d) < 0x1p53 && d == (long) d) return sb.append((long) d);   // exact integers: their digits
        return MEMO.get().append(sb, d);
    }

    /** Slots of each thread's table of recent texts. */
    static final int MEMO_SLOTS = 256;
    private static final ThreadLocal<Memo> MEMO = ThreadLocal.withInitial(Memo::new);

    /** A thread's recent texts: slot {@code hash(bits)} holds one value's bits and characters. */
    private static final class Memo {
        final long[] bits = new long[MEMO_SLOTS];
        final char[][] text = new char[MEMO_SLOTS][32];   // the longest text is 24 characters (-1.2345678901234567e-308)
        final int[] length = new int[MEMO_SLOTS];         // 0: empty (no finite non-zero text is empty)

        StringBuilder append(StringBuilder sb, double d) {
            long b = Double.doubleToRawLongBits(d);
            int slot = slot(b);
            if (length[slot] > 0 && bits[slot] == b) return sb.append(text[slot], 0, length[slot]);
            int start = sb.length();
            appendUncached(sb, d);
            int n = sb.length() - start;
            if (n <= text[slot].length) {
                sb.getChars(start, start + n, text[slot], 0);
                bits[slot] = b;
                length[slot] = n;
            }
            return sb;
        }
    }

    /** The memo slot of a double's bits (high and low bits mixed: neighbouring values differ in the low ones). */
    static int slot(long bits) {
        long h = bits * 0x9E3779B97F4A7C15L;
        return (int) (h >>> 56) & (MEMO_SLOTS - 1);
    }

    /** {@link #append} without the memo: the format itself. */
    static StringBuilder appendUncached(StringBuilder sb, double d) {
        // Schubfach gives "d.dddE±n" or "ddd.ddd": take its digits and decimal exponent
        String s = NumberOutput.toString(d, true);
        int start = sb.length();
        int i = 0;
        boolean negative = s.charAt(0) == '-';
        if (negative) i = 1;
        int e = s.indexOf('E');
        int end = e < 0 ? s.length() : e;
        // digits without the point, and the position of the point
        char[] digits = new char[end - i];
        int nd = 0, point = -1;
        for (int p = i; p < end; p++) {
            char c = s.charAt(p);
            if (c == '.') point = nd; else digits[nd++] = c;
        }
        if (point < 0) point = nd;
        int exp10 = e < 0 ? 0 : Integer.parseInt(s.substring(e + 1));
        // strip leading and trailing zeros: value = 0.d1d2..dk × 10^n  (ECMA-262's n, k, s)
        int first = 0;
        while (first < nd - 1 && digits[first] == '0') {
            first++;
            point--;
        }
        int last = nd;
        while (last > first + 1 && digits[last - 1] == '0') last--;
        int k = last - first;
        int n = point + exp10;
        if (k == 2) {
            // Schubfach, as Java's Double.toString, writes at least two digits (4.9E-324); one may
            // read back too (5e-324, ECMAScript's choice): try the one-digit neighbours, the
            // closer to d first (ECMA-262: of several shortest, the closest)
            int d1 = digits[first] - '0', d2 = digits[first + 1] - '0';
            boolean upFirst = d2 > 5 || d2 == 5 && new java.math.BigDecimal(Math.abs(d))
                .compareTo(new java.math.BigDecimal((d1 * 10 + 5) + "e" + (n - 2))) >= 0;
            for (int attempt = 0; attempt < 2; attempt++) {
                int c = upFirst == (attempt == 0) ? d1 + 1 : d1;
                int cn = c == 10 ? n + 1 : n;
                char cd = c == 10 ? '1' : (char) ('0' + c);
                if (c > 0 && Double.parseDouble((negative ? "-" : "") + cd + "e" + (cn - 1)) == d) {
                    digits[first] = cd;
                    k = 1;
                    n = cn;
                    break;
                }
            }
        }
        if (negative) sb.append('-');
        if (k <= n && n <= 21) {
            sb.append(digits, first, k);
            for (int z = 0; z < n - k; z++) sb.append('0');
        } else if (0 < n && n <= 21) {
            sb.append(digits, first, n).append('.').append(digits, first + n, k - n);
        } else if (-6 < n && n <= 0) {
            sb.append("0.");
            for (int z = 0; z < -n; z++) sb.append('0');
            sb.append(digits, first, k);
        } else {
            sb.append(digits[first]);
            if (k > 1) sb.append('.').append(digits, first + 1, k - 1);
            sb.append('e').append(n - 1 >= 0 ? "+" : "-").append(Math.abs(n - 1));
        }
        assert sb.length() > start;
        return sb;
    }
}
