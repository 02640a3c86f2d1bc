package dev.predmon.evaluate;

import com.fasterxml.jackson.annotation.JsonProperty;

import java.util.List;
import java.util.Objects;
import java.util.TreeSet;

/**
 * The counts of one scenario's test runs.
 *
 * @param scenario           the scenario
 * @param faulty             whether it is faulty
 * @param runs               test runs
 * @param warned             runs with a warning (whatever its timing)
 * @param hits               faulty runs warned strictly before the violation
 * @param falseAlarms        nominal runs with a warning
 * @param missed             faulty runs with a violation and no warning before it (late warnings included)
 * @param late               of {@code missed}, those warned at or after the violation
 * @param noViolation        faulty runs whose log ends before any violation (neither hit nor missed)
 * @param noMatch            runs where at some point no model matched (unknown behaviour)
 * @param lead               lead of the hits, in {@code leadUnit}
 * @param valueAtWarning     the watched value at the warning, over the hits
 * @param sudden             runs whose violation was sudden ({@link RunResult#sudden()}): few readings near the bound
 * @param suddenHits         of {@code hits}, those with a sudden violation
 * @param leadUnit           what the lead counts ({@code s} or {@code ticks}; {@code s, ticks} when runs differ)
 */
public record ScenarioSummary(String scenario, boolean faulty, int runs, int warned, int hits, int falseAlarms,
                              int missed, int late, int noViolation, int noMatch, Stats lead, Stats valueAtWarning,
                              int sudden, int suddenHits, String leadUnit) {

    /** Summarises the runs of one scenario. */
    public static ScenarioSummary of(String scenario, boolean faulty, List<RunResult> runs) {
        int warned = 0;
        int hits = 0;
        int falseAlarms = 0;
        int missed = 0;
        int late = 0;
        int noViolation = 0;
        int noMatch = 0;
        int sudden = 0;
        int suddenHits = 0;
        for (RunResult r : runs) {
            sudden += r.sudden() ? 1 : 0;
            suddenHits += r.sudden() && r.verdict() == Verdict.WARNED_BEFORE_VIOLATION ? 1 : 0;
            Verdict v = r.verdict();
            warned += v.warned() ? 1 : 0;
            hits += v == Verdict.WARNED_BEFORE_VIOLATION ? 1 : 0;
            falseAlarms += v == Verdict.FALSE_ALARM ? 1 : 0;
            missed += v == Verdict.MISSED || v == Verdict.WARNED_LATE ? 1 : 0;
            late += v == Verdict.WARNED_LATE ? 1 : 0;
            noViolation += v == Verdict.WARNED_NO_VIOLATION || v == Verdict.QUIET_NO_VIOLATION ? 1 : 0;
            noMatch += r.noMatch() ? 1 : 0;
        }
        List<RunResult> hit = runs.stream().filter(r -> r.verdict() == Verdict.WARNED_BEFORE_VIOLATION).toList();
        return new ScenarioSummary(scenario, faulty, runs.size(), warned, hits, falseAlarms, missed, late, noViolation,
                noMatch, Stats.of(hit.stream().map(RunResult::lead).toList()),
                Stats.of(hit.stream().map(RunResult::valueAtWarning).filter(Objects::nonNull).toList()),
                sudden, suddenHits, String.join(", ", new TreeSet<>(runs.stream().map(RunResult::unit).toList())));
    }

    /** {@link #valueAtWarning} under its older name in the evaluation's JSON, kept for existing scripts. */
    @JsonProperty("batteryAtWarning")
    public Stats batteryAtWarning() {
        return valueAtWarning;
    }
}
