package dev.predmon.monitor;

import java.util.Locale;

/** When the monitor warns. */
public enum WarningRule {
    /**
     * When the forecast's probability of a violation reaches the threshold learned with the models (chosen by
     * cross-validation over the training runs): it also warns through behaviour no model has seen.
     */
    FORECAST,
    /**
     * The thesis's Algorithm 8: when every nominal model is eliminated while a faulty one still matches. Silent once
     * no model matches.
     */
    MATCH;

    /** As written on the command line: {@code forecast}, {@code match}. */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }
}
