/**
 * Charts with JFreeChart: the paper's Fig. 7 and Fig. 8 from a run's trace, the
 * speed-versus-accuracy charts, export to PNG and SVG (written atomically). Uses the
 * simulation's results only; renders without a display.
 */
package org.handsim.chart;
