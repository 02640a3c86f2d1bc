package dev.predmon.evaluate;

import com.fasterxml.jackson.annotation.JsonValue;

/**
 * What a warning (or its absence) meant for one run. A faulty run is a hit only when the warning came strictly
 * before the safety monitor's violation; a warning at or after it is no prediction and counts as missed.
 */
public enum Verdict {
    /** Faulty run, warning strictly before the violation: a hit; its lead is violation time minus warning time. */
    WARNED_BEFORE_VIOLATION("warned-before-violation"),
    /** Faulty run, warning at or after the violation: counted as missed. */
    WARNED_LATE("warned-late"),
    /** Faulty run, violation and no warning. */
    MISSED("missed"),
    /** Faulty run whose log ends before the property is violated, with a warning (no lead can be measured). */
    WARNED_NO_VIOLATION("warned-no-violation"),
    /** Faulty run whose log ends before the property is violated, without a warning. */
    QUIET_NO_VIOLATION("quiet-no-violation"),
    /** Nominal run with a warning. */
    FALSE_ALARM("false-alarm"),
    /** Nominal run without a warning. */
    QUIET("quiet");

    private final String id;

    Verdict(String id) {
        this.id = id;
    }

    /** The name used in JSON and tables. */
    @JsonValue
    public String id() {
        return id;
    }

    /** Whether a warning was raised. */
    public boolean warned() {
        return this == WARNED_BEFORE_VIOLATION || this == WARNED_LATE || this == WARNED_NO_VIOLATION
                || this == FALSE_ALARM;
    }

    /** The verdict of a run, from its scenario's label and the times of its first warning and violation. */
    public static Verdict of(boolean faulty, Double warning, Double violation) {
        if (!faulty) {
            return warning != null ? FALSE_ALARM : QUIET;
        }
        if (violation == null) {
            return warning != null ? WARNED_NO_VIOLATION : QUIET_NO_VIOLATION;
        }
        if (warning == null) {
            return MISSED;
        }
        return warning < violation ? WARNED_BEFORE_VIOLATION : WARNED_LATE;
    }
}
