package dev.predmon.evaluate;

import com.fasterxml.jackson.annotation.JsonIgnore;
import com.fasterxml.jackson.annotation.JsonProperty;
import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import dev.predmon.model.ModelSet;

import java.util.List;

/**
 * The outcome of {@code evaluate}.
 *
 * @param mode        {@code cross-validation} or {@code test-set}
 * @param folds       K, or 0 with a test set
 * @param tolerance   the discrepancy tolerance: discrepancies tolerated per model
 * @param abstraction the abstraction's name
 * @param scenarios   per-scenario counts, sorted by scenario
 * @param confusion   actual against predicted over all runs
 * @param runs        every judged run, in scenario then log order
 * @param notes       what a reader should know (scenarios missing from a fold's training data, skipped logs)
 * @param models      the models to show: learned on all of {@code --logs} (not serialised)
 * @param rule        the warning rule the runs were judged by
 * @param forecast    how good the forecast was, or null when the models carry none
 */
@JsonPropertyOrder({"mode", "folds", "tolerance", "abstraction", "rule", "scenarios", "confusion", "forecast", "properties", "notes",
        "runs"})
public record Evaluation(String mode, int folds, int tolerance, String abstraction, List<ScenarioSummary> scenarios,
                         Confusion confusion, List<RunResult> runs, List<String> notes,
                         @JsonIgnore ModelSet models, String rule, ForecastScore forecast) {

    /** An evaluation by the match rule, without a forecast. */
    public Evaluation(String mode, int folds, int tolerance, String abstraction, List<ScenarioSummary> scenarios,
                      Confusion confusion, List<RunResult> runs, List<String> notes, ModelSet models) {
        this(mode, folds, tolerance, abstraction, scenarios, confusion, runs, notes, models, "match", null);
    }

    /**
     * How each of the abstraction's other properties fared ({@link PropertyScore}): its violations, warnings, lead,
     * the elapsed-time baseline, and how good its forecast was.
     */
    @JsonProperty("properties")
    public List<PropertyScore> properties() {
        return PropertyScore.of(runs);
    }
}
