package dev.predmon.forecast;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.util.ArrayList;
import java.util.List;

import static dev.predmon.forecast.JsonAt.number;

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

    /** The optional {@code scorecards} list at {@code n}: none when it is not there. */
    static List<Scorecard> readScorecards(JsonAt n) {
        JsonAt a = n.optional("scorecards");
        if (a == null) {
            return List.of();
        }
        if (!a.node().isArray()) {
            throw a.wrong("expected an array");
        }
        List<Scorecard> cards = new ArrayList<>();
        for (int i = 0; i < a.node().size(); i++) {
            cards.add(scorecardOf(new JsonAt(a.node().get(i), a.at(Integer.toString(i)))));
        }
        return cards;
    }

    /** One scorecard of {@link #scorecard}, its baseline's read the same way. */
    private static Scorecard scorecardOf(JsonAt n) {
        n.object();
        JsonAt b = n.optional("baseline");
        Scorecard baseline = b == null ? null : scorecardOf(b);
        JsonAt chosen = n.optional("baselineChosen");
        if (chosen != null && (!chosen.node().isBoolean() || baseline == null)) {
            throw chosen.wrong("expected true or false, beside a 'baseline'");
        }
        String property = n.text("property");
        int folds = n.integer("folds");
        int runs = n.integer("runs");
        int violating = n.integer("violating");
        int warned = n.integer("warned");
        int alarms = n.integer("falseAlarms");
        double lead = n.number("medianLead");
        String unit = n.text("unit");
        double brier = n.number("brier");
        double baseBrier = n.number("baseBrier");
        String counted = n.has("counted") ? n.text("counted") : Scorecard.RUNS;
        String rule = n.has("rule") ? n.text("rule") : Scorecard.FORECAST;
        boolean baselineChosen = chosen != null && chosen.node().booleanValue();
        Scorecard c = n.built(() -> new Scorecard(property, folds, runs, violating, warned, alarms, lead, unit, brier,
                baseBrier, counted, rule, baseline, baselineChosen));
        if (c.runs() < 0 || c.violating() < 0 || c.violating() > c.runs() || c.warned() < 0
                || c.warned() > c.violating() || c.falseAlarms() < 0 || c.falseAlarms() > c.held()) {
            throw n.wrong("the scorecard of '" + c.property() + "': expected 0 <= warned <= violating <= runs and "
                    + "0 <= falseAlarms <= runs - violating");
        }
        if (!(Double.isNaN(c.brier()) || (c.brier() >= 0 && c.brier() <= 1))
                || !(Double.isNaN(c.baseBrier()) || (c.baseBrier() >= 0 && c.baseBrier() <= 1))) {
            throw n.wrong("the scorecard of '" + c.property() + "': expected Brier scores between 0 and 1");
        }
        return c;
    }
}
