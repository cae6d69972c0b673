package org.handsim.gui;

import java.awt.Color;
import java.awt.Font;
import java.awt.GridBagConstraints;
import java.awt.Insets;
import java.awt.event.FocusAdapter;
import java.awt.event.FocusEvent;
import java.util.Locale;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JPanel;
import javax.swing.JTextField;

/** Small helpers shared by the panels: named fields and buttons, number parsing, layout. */
final class Widgets {
    private Widgets() {}

    static final Color ERROR = new Color(0xB00020);
    static final Color OK = new Color(0x1B5E20);

    /**
     * A text field with a name (the script's {@code set <name> <value>} finds it) that runs
     * {@code onCommit} on Enter and when it loses the focus.
     */
    static JTextField field(String name, String text, int columns, Runnable onCommit) {
        JTextField f = new JTextField(text, columns);
        f.setName(name);
        f.setHorizontalAlignment(JTextField.RIGHT);
        if (onCommit != null) {
            f.addActionListener(e -> onCommit.run());
            f.addFocusListener(new FocusAdapter() {
                @Override
                public void focusLost(FocusEvent e) {
                    if (!e.isTemporary()) onCommit.run();
                }
            });
        }
        return f;
    }

    /** A button with a label and a script name. */
    static JButton button(String name, String label, Runnable action) {
        JButton b = new JButton(label);
        b.setName(name);
        b.addActionListener(e -> action.run());
        return b;
    }

    /**
     * Parses a field as a finite number.
     *
     * @throws IllegalArgumentException naming the field and the text
     */
    static double number(JTextField f, String what) {
        String t = f.getText().trim();
        try {
            double v = org.handsim.text.Decimal.parse(t);   // decimals only: '0d', 'NaN' are not numbers
            if (!Double.isFinite(v)) throw new NumberFormatException();
            return v;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(what + ": '" + org.handsim.text.SafeText.quote(t) + "' is not a number");
        }
    }

    /** Formats a number for a field (fixed decimals, '.' as the decimal point). */
    static String fmt(double v, int decimals) {
        String s = String.format(Locale.ROOT, "%." + decimals + "f", v);
        return s.matches("-0(\\.0*)?") ? s.substring(1) : s;   // no "-0.00"
    }

    /**
     * Formats a number with {@code digits} significant digits, rounded half-up and written out in
     * full (0.1984, 0.08472, 58.84, 0.0001235, 2.500; never an exponent); 0 as "0"; NaN and ±∞ as Java writes them.
     */
    static String significant(double v, int digits) {
        if (v == 0) return "0";
        if (!Double.isFinite(v)) return String.valueOf(v);
        java.math.BigDecimal r = new java.math.BigDecimal(v).round(new java.math.MathContext(digits, java.math.RoundingMode.HALF_UP));
        if (r.precision() < digits) r = r.setScale(r.scale() + digits - r.precision());   // 2.5 -> 2.500: always that many digits
        return r.toPlainString();
    }

    static <T extends JComponent> T titled(T c, String title) {
        c.setBorder(BorderFactory.createCompoundBorder(BorderFactory.createTitledBorder(title),
            BorderFactory.createEmptyBorder(2, 4, 4, 4)));
        return c;
    }

    static GridBagConstraints at(int x, int y) {
        GridBagConstraints g = new GridBagConstraints();
        g.gridx = x;
        g.gridy = y;
        g.insets = new Insets(2, 2, 2, 2);
        g.anchor = GridBagConstraints.WEST;
        g.fill = GridBagConstraints.HORIZONTAL;
        g.weightx = 1;
        return g;
    }

    static GridBagConstraints at(int x, int y, int width) {
        GridBagConstraints g = at(x, y);
        g.gridwidth = width;
        return g;
    }

    /** A vertical column of sections for a tool panel (see {@link #top}). */
    static JPanel column() {
        JPanel p = new StackPanel();
        p.setLayout(new javax.swing.BoxLayout(p, javax.swing.BoxLayout.Y_AXIS));
        return p;
    }

    /**
     * The column at the top of a panel that follows the scroll pane's viewport width, every
     * section left-aligned (so wrapped text wraps and grids stay in view).
     */
    static JComponent top(JPanel column) {
        for (java.awt.Component c : column.getComponents()) {
            if (c instanceof JComponent) ((JComponent) c).setAlignmentX(0f);
        }
        JPanel wrap = new StackPanel();
        wrap.setLayout(new java.awt.BorderLayout());
        wrap.add(column, java.awt.BorderLayout.NORTH);
        return wrap;
    }

    /** A small HTML note that wraps at the tool panel's width. */
    static javax.swing.JLabel note(String html) {
        javax.swing.JLabel l = new javax.swing.JLabel("<html><body style='width: 240px'><small>" + html + "</small></body></html>");
        return l;
    }

    /** A panel that follows the viewport's width inside a scroll pane. */
    private static final class StackPanel extends JPanel implements javax.swing.Scrollable {
        private static final long serialVersionUID = 1L;
        @Override public java.awt.Dimension getPreferredScrollableViewportSize() { return getPreferredSize(); }
        @Override public int getScrollableUnitIncrement(java.awt.Rectangle r, int o, int d) { return 16; }
        @Override public int getScrollableBlockIncrement(java.awt.Rectangle r, int o, int d) { return 160; }
        @Override public boolean getScrollableTracksViewportWidth() { return true; }
        @Override public boolean getScrollableTracksViewportHeight() { return false; }
    }

    static Font small() {
        return new Font("SansSerif", Font.PLAIN, 11);
    }
}
