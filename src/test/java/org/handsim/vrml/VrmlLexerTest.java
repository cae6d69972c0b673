package org.handsim.vrml;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The hand-written number parser against Double.parseDouble (cross-check, fixed seed). */
class VrmlLexerTest {
    private static VrmlLexer lexer(String s) {
        byte[] b = s.getBytes(StandardCharsets.UTF_8);
        return new VrmlLexer(new VrmlText("t.wrl", b), 0);
    }

    @Test
    void doublesAreCorrectlyRounded() {
        Random r = new Random(345);
        StringBuilder sb = new StringBuilder();
        String[] forms = new String[20000];
        for (int i = 0; i < forms.length; i++) {
            String f;
            switch (i % 5) {
                case 0: f = Double.toString(r.nextGaussian() * Math.pow(10, r.nextInt(40) - 20)); break;
                case 1: f = String.format(Locale.ROOT, "%.6f", r.nextDouble() * 1000 - 500); break;
                case 2: f = String.format(Locale.ROOT, "%.17e", r.nextDouble()); break;
                case 3: f = (r.nextBoolean() ? "+" : "-") + r.nextInt(100000) + "." + r.nextInt(1000) + "e" + (r.nextInt(60) - 30); break;
                default: f = "." + r.nextInt(1_000_000_000) + r.nextInt(1_000_000_000); break;
            }
            forms[i] = f;
            sb.append(f).append(i % 3 == 0 ? ", " : " \n");
        }
        VrmlLexer lx = lexer(sb.toString());
        for (String f : forms) assertEquals(Double.parseDouble(f), lx.readDouble("test"), f);
    }

    @Test
    void integersIncludingHexAndLimits() {
        VrmlLexer lx = lexer("0 -1 2147483647 -2147483648 0xFF 0XfFfFfFfF +7 # comment\n 12");
        int[] expected = {0, -1, Integer.MAX_VALUE, Integer.MIN_VALUE, 255, -1, 7, 12};
        for (int e : expected) assertEquals(e, lx.readInt("test"));
        assertThrows(VrmlParseException.class, () -> lexer("2147483648").readInt("test"));
        assertThrows(VrmlParseException.class, () -> lexer("12abc").readInt("test"));
        assertThrows(VrmlParseException.class, () -> lexer("1.5").readInt("test"));
    }

    @Test
    void numberFormsOfTheStandard() {
        VrmlLexer lx = lexer("1. .5 -0 1e3 1E-3 +2.5e+2 0.000000000000000000000000001");
        double[] expected = {1, 0.5, -0.0, 1000, 0.001, 250, 1e-27};
        for (double e : expected) assertEquals(e, lx.readDouble("test"));
        assertThrows(VrmlParseException.class, () -> lexer("1e").readDouble("test"));
        assertThrows(VrmlParseException.class, () -> lexer("- 1").readDouble("test"));
        assertThrows(VrmlParseException.class, () -> lexer("1.2.3").readDouble("test"));
    }

    @Test
    void stringsWithEscapesAndIdentifiersWithPlus() {
        VrmlLexer lx = lexer("\"say \\\"hi\\\" \\\\ there\" _+0 caf\u00e9");
        assertEquals("say \"hi\" \\ there", lx.string("s"));
        assertEquals("_+0", lx.identifier("id"));
        assertEquals("caf\u00e9", lx.identifier("id"));
    }
}
