package org.handsim.chart;

import org.handsim.text.Decimal;
import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.handsim.files.AtomicFile;

/**
 * The result of one study: rows of numbers (the CSV behind a chart) and what the chart plots.
 * Each row belongs to a series (one coloured set of points with its own Pareto front), names
 * its setting, and has an x (cost, e.g. wall time) and a y (error, or triangle tests), both
 * plotted on log axes; one row per series may be the default setting, marked on the chart.
 *
 * <p>CSV: the header is {@code series,setting,default,} followed by {@link #columns()}; the
 * x and y of a row are two of those columns ({@link #xColumn()}, {@link #yColumn()}).
 */
public final class StudyTable {
    /** One point: the series it belongs to, its setting, whether it is the default, its values (in column order). */
    public record Row(String series, String setting, boolean isDefault, double[] values) {}

    private final String id, title, xLabel, yLabel;
    private final List<String> columns;
    private final int xColumn, yColumn;
    private final List<Row> rows = new ArrayList<>();
    private final Map<String, String> notes = new LinkedHashMap<>();
    private boolean labelEveryPoint = true;
    private boolean front = true;

    /**
     * @param id      file base name, e.g. {@code 1-dt}
     * @param title   chart title
     * @param columns numeric column names (CSV header after series, setting, default)
     * @param xColumn column plotted on x (log axis)
     * @param yColumn column plotted on y (log axis)
     */
    public StudyTable(String id, String title, List<String> columns, String xColumn, String yColumn, String xLabel, String yLabel) {
        this.id = id;
        this.title = title;
        this.columns = List.copyOf(columns);
        this.xColumn = index(xColumn);
        this.yColumn = index(yColumn);
        this.xLabel = xLabel;
        this.yLabel = yLabel;
    }

    private int index(String column) {
        int i = columns.indexOf(column);
        if (i < 0) throw new IllegalArgumentException("no column " + column + " in " + columns);
        return i;
    }

    /** Adds a row; {@code values} in column order. */
    public StudyTable add(String series, String setting, boolean isDefault, double... values) {
        if (values.length != columns.size()) {
            throw new IllegalArgumentException(id + ": row " + setting + " has " + values.length + " values for " + columns.size() + " columns");
        }
        rows.add(new Row(series, setting, isDefault, values.clone()));
        return this;
    }

    /** A line under the chart and in the CSV's companion notes (e.g. the reference used). */
    public StudyTable note(String key, String text) {
        notes.put(key, text);
        return this;
    }

    /**
     * Whether the chart labels every point with its setting (default) or, for crowded charts,
     * only the points on a Pareto front and the defaults.
     */
    public StudyTable labelEveryPoint(boolean on) {
        labelEveryPoint = on;
        return this;
    }

    public boolean labelsEveryPoint() { return labelEveryPoint; }

    /**
     * Whether the chart draws each series' Pareto front (default: x is a cost, y an error) or,
     * when x is a setting rather than a cost (the time step against an error), a thin line
     * through each series' points in the order of x instead.
     */
    public StudyTable paretoFront(boolean on) {
        front = on;
        return this;
    }

    public boolean drawsParetoFront() { return front; }
    public String id() { return id; }
    public String title() { return title; }
    public String xLabel() { return xLabel; }
    public String yLabel() { return yLabel; }
    public List<String> columns() { return columns; }
    public int xColumn() { return xColumn; }
    public int yColumn() { return yColumn; }
    public List<Row> rows() { return Collections.unmodifiableList(rows); }
    public Map<String, String> notes() { return Collections.unmodifiableMap(notes); }

    /** The value of column {@code name} in a row. */
    public double value(Row r, String name) { return r.values()[index(name)]; }

    /** Series names in the order they first appear. */
    public List<String> series() {
        List<String> s = new ArrayList<>();
        for (Row r : rows) if (!s.contains(r.series())) s.add(r.series());
        return s;
    }

    /** Rows of one series, in insertion order. */
    public List<Row> rows(String series) {
        List<Row> out = new ArrayList<>();
        for (Row r : rows) if (r.series().equals(series)) out.add(r);
        return out;
    }

    /** The header line of the CSV (without newline). */
    public String csvHeader() {
        return "series,setting,default," + String.join(",", columns);
    }

    /** Writes the CSV atomically. Numbers are written by {@link Decimal} (shortest round trip, integers plain); NaN (not defined) as an empty cell. */
    public void writeCsv(Path file) throws IOException {
        try (AtomicFile f = new AtomicFile(file)) {
            Writer w = f.writer();
            w.write(csvHeader());
            w.write('\n');
            StringBuilder sb = new StringBuilder();
            for (Row r : rows) {
                sb.setLength(0);
                sb.append(r.series()).append(',').append(r.setting()).append(',').append(r.isDefault());
                for (double v : r.values()) sb.append(',').append(Decimal.orEmpty(v));
                sb.append('\n');
                w.append(sb);
            }
            f.commit();
        }
    }
}
