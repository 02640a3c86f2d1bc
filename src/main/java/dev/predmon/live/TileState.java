package dev.predmon.live;

/**
 * What a tile says about its robot now, worst first: the order the page sorts tiles in. Each state has a light in the
 * conventions of robot monitors (green, yellow, red), plus blue for a run the models cannot judge and slate for a run
 * that is over.
 */
enum TileState {
    /** The property is violated now. */
    VIOLATION("violation", "red"),
    /** The run is predicted to violate the property. */
    WARNING("warning", "yellow"),
    /** No learned model matches the run, or it does something no model does: neither safe nor faulty is known. */
    UNKNOWN("unknown", "blue"),
    /** The models cannot judge the log: not a monitor log, or an abstraction that does not fit it. */
    NO_VERDICT("no-verdict", "purple"),
    /** The property holds and the models predict no violation (or it holds again after one). */
    OK("ok", "green"),
    /** No data yet. */
    WAITING("waiting", "grey"),
    /** The run completed: the log went quiet with the tree at rest. */
    ENDED("ended", "slate");

    private final String id;
    private final String light;

    TileState(String id, String light) {
        this.id = id;
        this.light = light;
    }

    /** As in {@code /status}. */
    String id() {
        return id;
    }

    /** The light's colour. */
    String light() {
        return light;
    }
}
