package dev.predmon.live;

import com.fasterxml.jackson.databind.node.ArrayNode;

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

    /**
     * The robot's state: a violated property makes it a violation, a warned one a warning unless the forecast
     * property's own state says more (no verdict, a violation, a run that ended); else the forecast property's state.
     *
     * @param own   the forecast property's state ({@link Tile#state})
     * @param props every property's light, worst first ({@link PropertyLights#json})
     */
    static TileState worst(TileState own, ArrayNode props) {
        String w = props.isEmpty() ? "" : props.get(0).path("state").asText();
        if (own == NO_VERDICT || own == VIOLATION) {
            return own;
        }
        if (w.equals(PropertyLights.Light.VIOLATED.id)) {
            return VIOLATION;
        }
        return w.equals(PropertyLights.Light.WARNING.id) && own != ENDED ? WARNING : own;
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
