package dev.predmon.pipeline;

/** Which runs of a log a scenario takes: all of them, or, in a folder labelled by the safety monitor, one kind. */
public enum RunLabel {
    /** Every run (a scenario directory: its logs hold runs of that scenario). */
    ALL,
    /** Runs the safety monitor saw violate the property. */
    VIOLATING,
    /** Runs in which the property held to the end. */
    SAFE;

    /** Whether a run with that outcome is selected. */
    public boolean selects(boolean violated) {
        return this == ALL || (this == VIOLATING) == violated;
    }
}
