/**
 * Motor set-point trajectories in encoder counts against time in seconds: trapezoidal velocity
 * profile, quintic polynomial, a fingertip straight line through inverse kinematics, a hold,
 * and sequences of these. Each gives position, velocity and acceleration; all are immutable.
 */
package org.handsim.sim.trajectory;
