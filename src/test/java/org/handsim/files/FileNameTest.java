package org.handsim.files;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import org.junit.jupiter.api.Test;

/** Names that become folder names: never '.', '..', a separator, a control character or empty. */
class FileNameTest {
    @Test
    void safeAndUnsafeNames() {
        for (String ok : new String[] {"paper-breakaway", "a.b", "v1.2_x", ".hidden", "a..b"}) assertEquals(null, FileName.problem(ok), ok);
        for (String bad : new String[] {"", ".", "..", "...", "a/b", "../x", "a\\b", "a\u0000b", "a\nb", "tab\there", "é"}) {
            assertNotNull(FileName.problem(bad), bad);
        }
    }
}
