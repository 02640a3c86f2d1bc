package dev.predmon.forecast;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code forecast.json} with the deadline rules and scorecards, and without them as older files are: each deadline's
 * rule and scorecard in its own entry under {@code properties}.
 */
class ForecastFileDeadlineTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String ID = "navigation-in-time";
    private static final String LEARN_ID = "sha256:0123456789abcdef0123456789abcdef";
    private static final Survival NAVIGATIONS = new Survival(new double[] {2, 3, 3, 4}, new double[] {12});
    private static final DeadlineRule LEARNED = new DeadlineRule(0.62, "0.62 by cross-validation on 5 held-out "
            + "obligations: warned 1 of 1 violations, 0 false alarm(s) in 4", true, new Calibration(1.4, -0.3, 5));
    private static final Scorecard CARD = new Scorecard("a navigation ends in 10 ticks", 5, 5, 1, 1, 0, 6, "ticks",
            0.05, 0.16, Scorecard.OBLIGATIONS);

    private static ForecastModel model(Map<String, DeadlineRule> rules, List<Scorecard> cards) {
        return new ForecastModel(ForecastModel.FORMAT, "s", 20, 5, 1, new Lows(new double[] {30}, new double[] {21}),
                0.5, "default", false, Map.of(), List.of("start"), Calibration.IDENTITY, List.of(),
                Map.of(ID, NAVIGATIONS), rules).withDeadlineScorecards(cards.isEmpty() ? Map.of() : Map.of(ID, cards))
                .named("battery", List.of("battery", ID));
    }

    @Test
    void theLearnedRuleAndItsScorecardRoundTrip() throws Exception {
        ForecastModel m = model(Map.of(ID, LEARNED), List.of(CARD));
        String text = ForecastFile.write(m, LEARN_ID);
        ForecastModel back = ForecastFile.read(text, LEARN_ID);
        assertEquals(m, back);
        assertEquals(LEARNED, back.deadlineRule(ID));
        assertEquals(List.of(CARD), back.property(ID).orElseThrow().scorecards());
        assertEquals(List.of(), back.scorecards(), "the first floor has none");
        assertEquals(List.of(CARD), back.allScorecards());
        JsonNode stored = JSON.readTree(text).get("properties").get(ID);
        assertEquals("deadline", stored.get("kind").asText());
        assertEquals(0.62, stored.get("threshold").asDouble());
        assertTrue(stored.get("validated").asBoolean());
        assertEquals(1.4, stored.get("calibration").get("slope").asDouble());
        assertEquals("obligations", stored.get("scorecards").get(0).get("counted").asText());
        // the learn id still ties the file to its models
        IllegalArgumentException other = assertThrows(IllegalArgumentException.class,
                () -> ForecastFile.read(text, "sha256:fedcba"));
        assertTrue(other.getMessage().startsWith("learned with other models"), other.getMessage());
    }

    /** A file written before deadline rules existed has none: every deadline warns by the default rule. */
    @Test
    void aFileWithoutThemReadsWithTheDefaultRule() throws Exception {
        ObjectNode old = (ObjectNode) JSON.readTree(ForecastFile.write(model(Map.of(ID, LEARNED), List.of(CARD)),
                LEARN_ID));
        ObjectNode navigation = (ObjectNode) old.get("properties").get(ID);
        navigation.remove(List.of("threshold", "note", "validated", "calibration"));
        ObjectNode card = (ObjectNode) navigation.get("scorecards").get(0);
        card.remove("counted");
        ((ObjectNode) old.get("properties").get("battery")).set("scorecards", JSON.createArrayNode().add(card));
        navigation.remove("scorecards");
        ForecastModel back = ForecastFile.read(JSON.writeValueAsString(old), LEARN_ID);
        assertEquals(DeadlineRule.DEFAULT, back.deadlineRule(ID));
        assertEquals(NAVIGATIONS, back.obligations().get(ID));
        assertEquals(Scorecard.RUNS, back.scorecards().get(0).counted());
        String rewritten = ForecastFile.write(model(Map.of(), List.of()), LEARN_ID);
        assertFalse(JSON.readTree(rewritten).get("properties").get(ID).has("threshold"), rewritten);
        assertEquals(model(Map.of(), List.of()), ForecastFile.read(rewritten, LEARN_ID));
    }

    @Test
    void aThresholdThatIsNotAProbabilityIsRefusedWhereItIs() throws Exception {
        ObjectNode f = (ObjectNode) JSON.readTree(ForecastFile.write(model(Map.of(ID, LEARNED), List.of()), LEARN_ID));
        ((ObjectNode) f.get("properties").get(ID)).put("threshold", 1.5);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ForecastFile.read(JSON.writeValueAsString(f), LEARN_ID));
        assertEquals("'properties.navigation-in-time.threshold': a threshold is a probability, from 0 to 1: 1.5",
                e.getMessage());
        ((ObjectNode) f.get("properties").get(ID)).put("threshold", 0.5).put("margin", -0.5);
        IllegalArgumentException margin = assertThrows(IllegalArgumentException.class,
                () -> ForecastFile.read(JSON.writeValueAsString(f), LEARN_ID));
        assertEquals("'properties.navigation-in-time.margin': a margin is a share, from 0 to 1: -0.5",
                margin.getMessage());
    }

    /** An unvalidated rule, whose probability warns at none, is written and read back as such. */
    @Test
    void anUnvalidatedRuleReadsBackAsOneWhoseProbabilityDoesNotWarn() throws Exception {
        DeadlineRule unvalidated = DeadlineRule.unvalidated("no held-out obligation was met or missed");
        ForecastModel back = ForecastFile.read(ForecastFile.write(model(Map.of(ID, unvalidated), List.of()),
                LEARN_ID), LEARN_ID);
        assertEquals(DeadlineRule.NEVER, back.deadlineRule(ID).threshold());
        assertFalse(back.deadlineRule(ID).validated());
    }

    /**
     * A rule whose late clause was chosen keeps its level as {@code "level"} in the property's section, and
     * reads back warning by it; a level that is no prediction level is refused where it is; a file without it reads as
     * the novelty clause.
     */
    @Test
    void theLateClausesLevelRoundTripsAndABadOneIsRefused() throws Exception {
        DeadlineRule late = DeadlineRule.unvalidated("no held-out obligation missed its deadline", false, 0, 0.99);
        String text = ForecastFile.write(model(Map.of(ID, late), List.of()), LEARN_ID);
        assertEquals(0.99, JSON.readTree(text).get("properties").get(ID).get("level").asDouble());
        DeadlineRule back = ForecastFile.read(text, LEARN_ID).deadlineRule(ID);
        assertEquals(late, back);
        assertTrue(back.late());
        assertTrue(back.note().contains("past the 99% prediction bound"), back.note());
        ObjectNode f = (ObjectNode) JSON.readTree(text);
        ((ObjectNode) f.get("properties").get(ID)).put("level", 99);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ForecastFile.read(JSON.writeValueAsString(f), LEARN_ID));
        assertEquals("'properties.navigation-in-time.level': a prediction level is above 0.5 and below 1: 99.0",
                e.getMessage());
        ((ObjectNode) f.get("properties").get(ID)).put("level", 0.99).put("lateCeiling", "all");
        IllegalArgumentException ceiling = assertThrows(IllegalArgumentException.class,
                () -> ForecastFile.read(JSON.writeValueAsString(f), LEARN_ID));
        assertEquals("'properties.navigation-in-time.lateCeiling': expected \"every\"", ceiling.getMessage());
        ((ObjectNode) f.get("properties").get(ID)).put("lateCeiling", "every");
        assertTrue(ForecastFile.read(JSON.writeValueAsString(f), LEARN_ID).deadlineRule(ID).waited());
        ((ObjectNode) f.get("properties").get(ID)).remove(List.of("level", "lateCeiling"));
        assertFalse(ForecastFile.read(JSON.writeValueAsString(f), LEARN_ID).deadlineRule(ID).late());
    }
}
