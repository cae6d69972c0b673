/**
 * Speed against accuracy: studies that run the model at several settings, measure
 * wall time and error against a reference, and return the rows ({@code chart.StudyTable}) that {@code chart.TradeoffChart} draws.
 * Uses {@code model} and everything below it; {@code cli.TradeoffCommand} runs the studies.
 */
package org.handsim.tradeoff;
