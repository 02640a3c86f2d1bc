package dev.predmon.monitor;

import java.util.Optional;

/**
 * What every run of a log since the start adds up to, also the runs whose outcome is no longer kept in full.
 *
 * @param runs           runs since the start, the current one included
 * @param dropped        the oldest of them, whose outcome is no longer listed ({@link PredictiveMonitor#runs})
 * @param pairs          compacted pairs over all of them
 * @param noMatch        whether in one of them a point came where no model matched
 * @param safetyObserved whether one of them had a value of the safety property
 * @param warnedMatching whether one of them was warned (of any property) while some model still matched it
 * @param firstWarned    the first run warned of the forecast's property, if one was
 * @param unwarnedViolation whether one of them violated a property with no warning before it
 *                          ({@link RunOutcome#unwarnedViolation})
 * @param warned         whether one of them was warned of any property ({@link RunOutcome#warned})
 */
public record RunsSummary(int runs, int dropped, long pairs, boolean noMatch, boolean safetyObserved,
                          boolean warnedMatching, Optional<RunOutcome> firstWarned,
                          boolean unwarnedViolation, boolean warned) {
}
