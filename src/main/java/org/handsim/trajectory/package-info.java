/**
 * Motor set-point trajectories in encoder counts against time in seconds: trapezoidal velocity
 * profile, quintic polynomial, a fingertip straight line through inverse kinematics, a hold, and
 * sequences of these, each immutable and giving position, velocity and acceleration.
 *
 * <p>May use {@code kinematics} (docs/DESIGN.md, "Modules").
 */
package org.handsim.trajectory;
