/**
 * Charts with JFreeChart: the paper's Fig. 7 and Fig. 8 from a run's trace, the
 * speed-versus-accuracy charts, export to PNG and SVG (written atomically). Renders without a display.
 *
 * <p>May use {@code plan}, {@code hold}, {@code trace}, {@code grasp}, {@code files} and {@code text} (and JFreeChart; docs/DESIGN.md, "Modules").
 */
package org.handsim.chart;
