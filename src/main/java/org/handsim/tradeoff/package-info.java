/**
 * Speed against accuracy: studies that run the model at several settings, measure
 * wall time and error against a reference, and return the rows ({@code chart.StudyTable}) that {@code chart.TradeoffChart} draws.
 * {@code cli.TradeoffCommand} runs the studies.
 *
 * <p>May use every room below it but {@code gui} (docs/DESIGN.md, "Modules").
 */
package org.handsim.tradeoff;
