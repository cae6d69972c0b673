package org.handsim.hand;

/**
 * One row of a standard Denavit–Hartenberg table (paper Table I):
 * {@code T(i−1 → i) = Rz(θ + thetaOffset)·Tz(d)·Tx(a)·Rx(alpha)}, lengths in metres, angles in
 * radians. The joint variable θ is the transmission's joint angle; the DH angle is θ plus the
 * constant offset (Φ2, Φ3 of Table II; 0 for the spread joint).
 */
public record DhRow(double a, double alpha, double d, double thetaOffset) {
}
