package org.handsim.tradeoff;

import java.util.List;
import java.util.function.Supplier;

/** Every study of {@code handsim tradeoff}, in chart order (charts 1–6). */
public final class Studies {
    private Studies() {}

    /** Studies register here, one line each, in the order of their charts. */
    public static final List<Supplier<Study>> ALL = List.of(
        DtStudy::new,
        TessellationStudy::new,
        KdopStudy::new,
        IntegratorStudy::new,
        BodyRestStudy::new,
        BodyTumbleStudy::new
    );
}
