package dev.predmon.watch;

import dev.predmon.event.EventJson;

import java.time.Duration;
import java.time.Instant;
import java.util.Locale;

/** What begins each text line a watch session prints about a log, given when it is printed. */
@FunctionalInterface
public interface Stamp {

    /** Nothing. */
    Stamp NONE = at -> "";

    /** The wall-clock time ({@code watch --timestamps}), as events carry it, and a space. */
    Stamp WALL_CLOCK = at -> EventJson.wallTime(at) + " ";

    /** The stamp of a line printed at {@code at}. */
    String of(Instant at);

    /** The seconds since {@code start}, indented, as the demo shows them: {@code "  [  5.1 s] "}. */
    static Stamp since(Instant start) {
        return at -> String.format(Locale.ROOT, "  [%5.1f s] ", Duration.between(start, at).toNanos() / 1e9);
    }
}
