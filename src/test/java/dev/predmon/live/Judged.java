package dev.predmon.live;

import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.PropertyChecker;
import dev.predmon.property.PropertyView;

/** Hands a tile a record as watch does: with the built-in properties as a checker judged it. */
final class Judged {

    private static final PropertyChecker CHECKER = new PropertyChecker(AbstractionFiles.defaults().properties(),
            (i, p, v) -> { });

    private Judged() {
    }

    /** The built-in properties judged on {@code r} alone. */
    static synchronized PropertyView of(LogRecord r) {
        CHECKER.reset();
        CHECKER.accept(r);
        return CHECKER;
    }

    /** Gives {@code tile} record {@code r}, judged. */
    static void record(Tile tile, LogRecord r) {
        tile.record(r, of(r));
    }
}
