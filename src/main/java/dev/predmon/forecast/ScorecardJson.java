package dev.predmon.forecast;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.util.ArrayList;
import java.util.List;

import static dev.predmon.forecast.ForecastFileSections.integer;
import static dev.predmon.forecast.ForecastFileSections.number;
import static dev.predmon.forecast.ForecastFileSections.required;

/**
 * The {@code scorecards} of {@code forecast.json} ({@link ForecastFile}): one per property, each with its baseline's
 * beside it when the cross-validation scored one. Optional, so that an older file still reads.
 */
final class ScorecardJson {

    private ScorecardJson() {
    }

    /** The optional {@code scorecards} list: one object per property, written only when there is one. */
    static void writeScorecards(ObjectNode root, List<Scorecard> cards) {
        if (cards.isEmpty()) {
            return;
        }
        ArrayNode a = root.putArray("scorecards");
        cards.forEach(c -> a.add(scorecard(c)));
    }

    /** One scorecard as {@code forecast.json} holds it (and {@code /status} shows it). */
    static ObjectNode scorecard(Scorecard c) {
        ObjectNode n = JsonNodeFactory.instance.objectNode();
        n.put("property", c.property());
        n.put("folds", c.folds());
        n.put("runs", c.runs());
        n.put("violating", c.violating());
        n.put("warned", c.warned());
        n.put("falseAlarms", c.falseAlarms());
        number(n, "medianLead", c.medianLead());
        n.put("unit", c.unit());
        number(n, "brier", c.brier());
        number(n, "baseBrier", c.baseBrier());
        if (!Scorecard.RUNS.equals(c.counted())) {
            n.put("counted", c.counted());
        }
        if (!Scorecard.FORECAST.equals(c.rule())) {
            n.put("rule", c.rule());
        }
        if (c.baseline() != null) {
            n.set("baseline", scorecard(c.baseline()));
            n.put("baselineChosen", c.baselineChosen());
        }
        return n;
    }

    static List<Scorecard> readScorecards(JsonNode root) {
        JsonNode a = root.get("scorecards");
        if (a == null) {
            return List.of();
        }
        if (!a.isArray()) {
            throw new IllegalArgumentException("'scorecards': expected an array");
        }
        List<Scorecard> cards = new ArrayList<>();
        for (JsonNode n : a) {
            if (!n.isObject()) {
                throw new IllegalArgumentException("'scorecards': expected an array of objects");
            }
            cards.add(scorecardOf(n));
        }
        return cards;
    }

    /** One scorecard of {@link #scorecard}, its baseline's read the same way. */
    private static Scorecard scorecardOf(JsonNode n) {
        JsonNode b = n.get("baseline");
        if (b != null && !b.isObject()) {
            throw new IllegalArgumentException("'scorecards' of '" + n.path("property").asText()
                    + "': 'baseline' expected an object");
        }
        Scorecard baseline = b == null ? null : scorecardOf(b);
        JsonNode chosen = n.get("baselineChosen");
        if (chosen != null && (!chosen.isBoolean() || baseline == null)) {
            throw new IllegalArgumentException("'scorecards' of '" + n.path("property").asText()
                    + "': 'baselineChosen' expected true or false, beside a 'baseline'");
        }
        Scorecard c = new Scorecard(required(n, "property").asText(), integer(n, "folds"), integer(n, "runs"),
                integer(n, "violating"), integer(n, "warned"), integer(n, "falseAlarms"), number(n, "medianLead"),
                required(n, "unit").asText(), number(n, "brier"), number(n, "baseBrier"),
                n.has("counted") ? n.get("counted").asText() : Scorecard.RUNS,
                n.has("rule") ? n.get("rule").asText() : Scorecard.FORECAST, baseline,
                chosen != null && chosen.booleanValue());
        if (c.runs() < 0 || c.violating() < 0 || c.violating() > c.runs() || c.warned() < 0
                || c.warned() > c.violating() || c.falseAlarms() < 0 || c.falseAlarms() > c.held()) {
            throw new IllegalArgumentException("'scorecards' of '" + c.property() + "': expected 0 <= warned <= "
                    + "violating <= runs and 0 <= falseAlarms <= runs - violating");
        }
        if (!(Double.isNaN(c.brier()) || (c.brier() >= 0 && c.brier() <= 1))
                || !(Double.isNaN(c.baseBrier()) || (c.baseBrier() >= 0 && c.baseBrier() <= 1))) {
            throw new IllegalArgumentException("'scorecards' of '" + c.property() + "': expected Brier scores "
                    + "between 0 and 1");
        }
        return c;
    }
}
