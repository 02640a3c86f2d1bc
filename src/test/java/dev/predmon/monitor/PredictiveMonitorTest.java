package dev.predmon.monitor;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.LearnedModels;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.learn.ScenarioLearner;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.mealy.MealyAlphabet;
import dev.predmon.mealy.MealyMapping;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.ModelSet;
import dev.predmon.parse.LogRecord;
import dev.predmon.pipeline.Traces;
import dev.predmon.support.HandRuns;
import dev.predmon.support.Records;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The predictive monitor on hand-written runs of the case study: a recharge run (nominal) and a depleted run
 * (faulty) share their beginning and part when the depleted run's battery keeps falling on the way to the
 * charging station (thesis Figure 5.6, with the refined bands of Section 5.2).
 */
class PredictiveMonitorTest {

    private static final Abstraction A = AbstractionFiles.defaults();

    static Records recharge() {
        return HandRuns.recharge();
    }

    static Records depleted() {
        return HandRuns.depleted();
    }

    private static MealyTrace trace(Records r, String name) {
        return MealyMapping.toTrace(Traces.compact(r.list(), A), name);
    }

    static ModelSet models() {
        List<LearnedScenario> l = new ArrayList<>();
        l.add(ScenarioLearner.learnSamples(new ScenarioSpec("recharge", false, "", List.of(Path.of("r.log"))),
                List.of(trace(recharge(), "r.log")), MealyAlphabet.inputs(A)));
        l.add(ScenarioLearner.learnSamples(new ScenarioSpec("depleted", true, "", List.of(Path.of("d.log"))),
                List.of(trace(depleted(), "d.log")), MealyAlphabet.inputs(A)));
        return LearnedModels.modelSet(l, A);
    }

    private static List<MonitorEvent> watch(ModelSet models, List<LogRecord> records) {
        List<MonitorEvent> events = new ArrayList<>();
        PredictiveMonitor m = new PredictiveMonitor(models, A, 0, events::add);
        records.forEach(m::accept);
        m.endOfInput();
        return events;
    }

    @Test
    void depletedRunWarnsBeforeItsViolationWithTheBatteryAtTheWarning() {
        List<MonitorEvent> events = watch(models(), depleted().list());
        MonitorEvent.Warning w = events.stream().filter(e -> e instanceof MonitorEvent.Warning)
                .map(e -> (MonitorEvent.Warning) e).findFirst().orElseThrow();
        MonitorEvent.Violation v = events.stream().filter(e -> e instanceof MonitorEvent.Violation)
                .map(e -> (MonitorEvent.Violation) e).findFirst().orElseThrow();
        assertEquals(List.of("depleted"), w.scenarios());
        // Recharge reached the station at medium_four; the depleted run's next level (33, medium_three) is new.
        assertEquals(33.0, w.value(), 1e-9);
        assertEquals(50.0, w.time(), 0.01);
        assertEquals(18.0, v.value(), 1e-9);
        assertTrue(w.time() < v.time());
        assertTrue(events.indexOf(w) < events.indexOf(v));
    }

    @Test
    void confirmWaitsForTheFaultyModelToMatchThatManyMorePairs() {
        ModelSet models = models();
        List<MonitorEvent> strict = watch(models, depleted().list());
        List<MonitorEvent> confirmed = new ArrayList<>();
        PredictiveMonitor m = new PredictiveMonitor(models, A, 0, 1, confirmed::add);
        depleted().list().forEach(m::accept);
        m.endOfInput();
        MonitorEvent.Warning first = strict.stream().filter(e -> e instanceof MonitorEvent.Warning)
                .map(e -> (MonitorEvent.Warning) e).findFirst().orElseThrow();
        MonitorEvent.Warning later = confirmed.stream().filter(e -> e instanceof MonitorEvent.Warning)
                .map(e -> (MonitorEvent.Warning) e).findFirst().orElseThrow();
        assertEquals(0, A.confirm(), "the thesis abstraction keeps Algorithm 8");
        assertEquals(first.pairs() + 1, later.pairs(), "one more pair matched by the faulty model");
        assertTrue(later.time() > first.time());
        MonitorEvent.Violation v = confirmed.stream().filter(e -> e instanceof MonitorEvent.Violation)
                .map(e -> (MonitorEvent.Violation) e).findFirst().orElseThrow();
        assertTrue(later.time() < v.time(), "still before the violation");
    }

    @Test
    void nominalRunNeverWarnsAndNeverViolates() {
        List<MonitorEvent> events = watch(models(), recharge().list());
        assertTrue(events.stream().noneMatch(e -> e instanceof MonitorEvent.Warning || e instanceof MonitorEvent.Violation),
                events.toString());
    }

    @Test
    void eliminationNamesTheModelAndWhatItExpected() {
        List<MonitorEvent> events = watch(models(), depleted().list());
        MonitorEvent.Eliminated x = events.stream().filter(e -> e instanceof MonitorEvent.Eliminated)
                .map(e -> (MonitorEvent.Eliminated) e).findFirst().orElseThrow();
        assertEquals("recharge", x.model());
        assertTrue(x.reason().contains("o_level_medium_three") || x.reason().contains("cannot take"), x.reason());
    }

    /** Thesis Section 5.2: with the coarse bands of Section 4.2 the two runs part only at o_level_low: no lead. */
    @Test
    void coarseBandsOfSection42GiveNoLeadFigure56() throws Exception {
        String json = new String(Abstraction.class.getResourceAsStream("default-abstraction.json").readAllBytes(),
                StandardCharsets.UTF_8);
        Abstraction coarse = AbstractionFiles.fromJson("coarse.json", coarsen(json));
        List<LearnedScenario> l = new ArrayList<>();
        l.add(ScenarioLearner.learnSamples(new ScenarioSpec("recharge", false, "", List.of()),
                List.of(MealyMapping.toTrace(Traces.compact(recharge().list(), coarse), "r")), MealyAlphabet.inputs(coarse)));
        l.add(ScenarioLearner.learnSamples(new ScenarioSpec("depleted", true, "", List.of()),
                List.of(MealyMapping.toTrace(Traces.compact(depleted().list(), coarse), "d")), MealyAlphabet.inputs(coarse)));
        List<MonitorEvent> events = new ArrayList<>();
        PredictiveMonitor m = new PredictiveMonitor(LearnedModels.modelSet(l, coarse), coarse, 0, events::add);
        depleted().list().forEach(m::accept);
        MonitorEvent.Warning w = m.warning().orElseThrow();
        MonitorEvent.Violation v = m.violation().orElseThrow();
        assertEquals(v.time(), w.time(), 0.01, "the warning comes with the violation, not before");
    }

    /** Replaces the six medium bands by the thesis's single o_level_medium (20 to 50). */
    private static String coarsen(String json) {
        ObjectMapper om = new ObjectMapper();
        try {
            ObjectNode root = (ObjectNode) om.readTree(json);
            root.put("name", "thesis-4.2-coarse");
            for (JsonNode rule : root.get("rules")) {
                if (!"level".equals(rule.path("command").asText())) {
                    continue;
                }
                ArrayNode replies = (ArrayNode) rule.get("replies");
                ArrayNode kept = om.createArrayNode();
                for (JsonNode r : replies) {
                    String s = r.get("symbol").asText();
                    if (!s.startsWith("o_level_medium")) {
                        kept.add(r);
                    } else if (s.equals("o_level_medium_one")) {
                        ObjectNode medium = om.createObjectNode();
                        medium.put("symbol", "o_level_medium");
                        medium.putObject("range").put("atLeast", 20).put("atMost", 50);
                        kept.add(medium);
                    }
                }
                ((ObjectNode) rule).set("replies", kept);
            }
            return om.writeValueAsString(root);
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }
}
