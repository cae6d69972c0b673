package org.handsim.dynamics;

/** Argument checks shared by the dynamics classes: misuse is an exception naming the argument. */
final class Check {
    private Check() {}

    /** Requires {@code v} to hold at least {@code n} values. */
    static void vec(String name, double[] v, int n) {
        if (v == null) throw new IllegalArgumentException(name + " must not be null");
        if (v.length < n) throw new IllegalArgumentException(name + " needs " + n + " values, got " + v.length);
    }

    /**
     * An output argument (docs/STYLE.md, item 3): null gives a new array of {@code n} values; a
     * given array must be long enough and must not be one of the inputs.
     */
    static double[] out(String name, double[] out, int n, double[] in1, double[] in2, double[] in3, double[] in4) {
        if (out == null) return new double[n];
        if (out.length < n) throw new IllegalArgumentException(name + " needs " + n + " values, got " + out.length);
        if (out == in1 || out == in2 || out == in3 || out == in4) {
            throw new IllegalArgumentException(name + " must not be the same array as an input");
        }
        return out;
    }

    /** An output that must be given (no allocation on null). */
    static void outNonNull(String name, double[] out, int n, double[] in1, double[] in2, double[] in3) {
        if (out == null) throw new IllegalArgumentException(name + " must not be null");
        out(name, out, n, in1, in2, in3, null);
    }
}
