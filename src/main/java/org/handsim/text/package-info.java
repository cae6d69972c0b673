/**
 * Edge-of-the-program helpers: a small JSON reader that reports line and column, a JSON writer
 * for the command outputs, CSV reading with line numbers, atomic file output (write to a
 * temporary name, then rename) so that a failed run never leaves a half-written file that looks
 * complete, and the command line's conventions (issue 15): the one number format of every output
 * ({@link org.handsim.util.Decimal}), step times in decimal ({@link org.handsim.util.StepClock}),
 * input quoted safely in one-line messages ({@link org.handsim.util.SafeText}) and the one timing
 * helper for commands that print a time ({@link org.handsim.util.SteadyTiming}).
 */
package org.handsim.util;
