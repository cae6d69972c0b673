/**
 * The {@code handsim} command and its sub-commands (picocli). Exit codes, one place:
 * 0 success; 2 bad arguments (one line naming the argument); 3 an input file that cannot be
 * loaded ({@code FILE:LINE:COL: message}); 4 a run that failed numerically (message names the
 * step and time); 1 anything unexpected.
 *
 * <p>May use every room below it (docs/DESIGN.md, "Modules").
 */
package org.handsim.cli;
