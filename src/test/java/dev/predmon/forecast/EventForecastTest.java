package dev.predmon.forecast;

import dev.predmon.compact.IoPair;
import dev.predmon.mealy.MealyMapping;
import dev.predmon.parse.RecordKind;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunTiming;
import dev.predmon.property.Absence;
import dev.predmon.property.Event;
import dev.predmon.property.Precedence;
import dev.predmon.property.RecordMatch;
import dev.predmon.property.Scope;
import net.automatalib.automaton.transducer.CompactMealy;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * An absence's forecast, hand-computed on a hand-made machine and seven hand-made training runs: after {@code a/x}
 * the run goes either the risky way ({@code b/y}: three of the four runs that went there aborted) or the safe way
 * ({@code c/z}: one of three).
 */
class EventForecastTest {

    static final Absence NO_ABORT = new Absence("no-abort", "navigation never aborts", "send it again", Scope.GLOBAL,
            Event.of(new RecordMatch(RecordKind.REPLY, "GoTo", "getStatus", null, null, null, List.of("3"))));

    /** Pair states: 2 after a/x, 4 after b/y (risky), 6 after c/z (safe); d/w loops on 4 and 6. */
    static CompactMealy<String, String> fork() {
        CompactMealy<String, String> m = new CompactMealy<>(net.automatalib.alphabet.Alphabets.fromList(
                List.of("a", "b", "c", "d", MealyMapping.DELTA)));
        int[] s = new int[9];
        for (int i = 0; i < s.length; i++) {
            s[i] = i == 0 ? m.addInitialState() : m.addState();
        }
        m.addTransition(s[0], "a", s[1], MealyMapping.OK);
        m.addTransition(s[1], MealyMapping.DELTA, s[2], "x");
        m.addTransition(s[2], "b", s[3], MealyMapping.OK);
        m.addTransition(s[3], MealyMapping.DELTA, s[4], "y");
        m.addTransition(s[2], "c", s[5], MealyMapping.OK);
        m.addTransition(s[5], MealyMapping.DELTA, s[6], "z");
        m.addTransition(s[4], "d", s[7], MealyMapping.OK);
        m.addTransition(s[7], MealyMapping.DELTA, s[4], "w");
        m.addTransition(s[6], "d", s[8], MealyMapping.OK);
        m.addTransition(s[8], MealyMapping.DELTA, s[6], "w");
        return m;
    }

    static final Map<String, CompactMealy<String, String>> MACHINES = Map.of("fork", fork());

    /**
     * A run of {@code pairs}, one a second from t=0, whose absence was violated at {@code violation} (NaN: held), or
     * that gave no evidence for it when {@code unobserved}.
     */
    static LogTrace.Run run(List<String> pairs, double violation, boolean unobserved) {
        List<IoPair> io = new ArrayList<>();
        double[] times = new double[pairs.size()];
        double[] none = new double[pairs.size()];
        for (int i = 0; i < pairs.size(); i++) {
            String[] p = pairs.get(i).split("/", -1);
            io.add(new IoPair(p[0], p[1], null, null));
            times[i] = i;
            none[i] = Double.NaN;
        }
        RunTiming t = new RunTiming(times, none, Double.NaN, pairs.size(), Double.NaN, "s", List.of(), List.of(),
                List.of(), Double.isNaN(violation) ? Map.of() : Map.of("no-abort", violation), Map.of(),
                unobserved ? Set.of("no-abort") : Set.of());
        return new LogTrace.Run(0, 1, io, false, Map.of(), t);
    }

    static final List<String> RISKY = List.of("a/x", "b/y", "d/w");
    static final List<String> SAFE = List.of("a/x", "c/z", "d/w");

    /** 3 of 4 risky runs abort (1.5 s after they went the risky way), 1 of 3 safe ones does. */
    static List<LogTrace.Run> training() {
        return List.of(run(RISKY, 2.5, false), run(RISKY, 2.5, false), run(RISKY, 2.5, false),
                run(RISKY, Double.NaN, false), run(SAFE, Double.NaN, false), run(SAFE, Double.NaN, false),
                run(SAFE, 2.5, false));
    }

    @Test
    void eachStateSaysHowManyOfTheRunsThroughItWentOnToViolateWithAPriorOfTwoRunsAtTheBaseRate() {
        EventModel e = EventModel.learn(MACHINES, NO_ABORT, training(), "s");
        assertTrue(e.forecasts());
        assertEquals(7, e.runs());
        assertEquals(4, e.violating());
        ForecastModel m = e.model();
        assertEquals(EventModel.HOLDS, m.limit());
        StateStats risky = m.states().get("fork").get(4);
        StateStats safe = m.states().get("fork").get(6);
        assertEquals(4, risky.runs());
        assertEquals(3, risky.violated());
        assertEquals(3, safe.runs());
        assertEquals(1, safe.violated());
        assertEquals(1.5, risky.toViolationMedian(), 1e-12, "went the risky way at t=1, aborted at t=2.5");

        // the prior's mean: the base rate b = (4 + 1) / (7 + 2), smoothed once more over the 7 runs:
        // p0 = (4 + 2 b) / (7 + 2) = 46/81
        double p0 = 46.0 / 81;
        Forecaster f = new Forecaster(m, MACHINES);
        Forecast afterA = EventModel.shown(f.pair("a", "x", 0, EventModel.HOLDS, 1));
        assertEquals((4 + 2 * p0) / (7 + 2), afterA.probability(), 1e-9, "every run went through a/x: 416/729");
        Forecast afterB = EventModel.shown(f.pair("b", "y", 1, EventModel.HOLDS, 2));
        assertEquals((3 + 2 * p0) / (4 + 2), afterB.probability(), 1e-9, "3 of the 4 risky runs: 335/486");
        assertEquals(Forecast.Basis.MATCHED, afterB.basis());
        assertEquals(4, afterB.runs());
        assertEquals(3, afterB.violated());
        assertEquals(1.5, afterB.timeToViolation(), 1e-12);
        assertNull(afterB.value(), "an event has no value to show");
        assertNull(afterB.drift());
        assertEquals("3 of 4 training runs that were in this state violated", ForecastWords.evidence(afterB));

        Forecaster g = new Forecaster(m, MACHINES);
        g.pair("a", "x", 0, EventModel.HOLDS, 1);
        Forecast afterC = EventModel.shown(g.pair("c", "z", 1, EventModel.HOLDS, 2));
        assertEquals((1 + 2 * p0) / (3 + 2), afterC.probability(), 1e-9, "1 of the 3 safe runs: 173/405");

        Forecast broken = EventModel.shown(f.reading(2.5, EventModel.BROKEN));
        assertEquals(Forecast.Basis.VIOLATED, broken.basis(), "the violation told to the forecast");
        assertEquals(1.0, broken.probability());
    }

    @Test
    void whereNothingLearnedFitsTheRunTheBaseRateSpeaks() {
        ForecastModel m = EventModel.learn(MACHINES, NO_ABORT, training(), "s").model();
        Forecaster f = new Forecaster(m, MACHINES);
        Forecast novel = EventModel.shown(f.pair("q", "q", 0, EventModel.HOLDS, 7));
        assertEquals(Forecast.Basis.BASE_RATE, novel.basis());
        assertEquals(7L, novel.novelSince());
        assertEquals((4 + 2 * 46.0 / 81) / (7 + 2), novel.probability(), 1e-9,
                "all 7 runs, 4 violating, with the same prior: the base rate smoothed");
        assertTrue(ForecastWords.evidence(novel).endsWith("(no learned state fits: the base rate speaks)"),
                ForecastWords.evidence(novel));
    }

    @Test
    void runsWithoutEvidenceAreLeftOutAndTooLittleTrainingSaysWhyItGivesNoForecast() {
        List<LogTrace.Run> runs = new ArrayList<>(training());
        runs.add(run(RISKY, Double.NaN, true));
        assertEquals(7, EventModel.learn(MACHINES, NO_ABORT, runs, "s").runs(), "a run without evidence counts not");

        List<LogTrace.Run> held = List.of(run(SAFE, Double.NaN, false), run(SAFE, Double.NaN, false),
                run(RISKY, Double.NaN, false), run(RISKY, Double.NaN, false), run(RISKY, Double.NaN, false),
                run(SAFE, Double.NaN, false));
        EventModel never = EventModel.learn(MACHINES, NO_ABORT, held, "s");
        assertFalse(never.forecasts());
        assertEquals("never violated in 6 training runs", never.why());

        EventModel few = EventModel.learn(MACHINES, NO_ABORT, training().subList(2, 6), "s");
        assertEquals("only 4 training runs gave evidence of it (a forecast is learned from 5 or more)", few.why());

        EventModel all = EventModel.learn(MACHINES, NO_ABORT, training().subList(0, 3).stream()
                .flatMap(r -> List.of(r, r).stream()).toList(), "s");
        assertEquals("violated in every one of the 6 training runs: nothing tells a run that keeps it from one that "
                + "does not", all.why());
        assertEquals("no training run gave evidence of it", new EventModel(0, 0, null).why());
        assertNull(EventModel.learn(MACHINES, NO_ABORT, training(), "s").why());
        assertThrows(IllegalArgumentException.class, () -> new EventModel(6, 0,
                EventModel.learn(MACHINES, NO_ABORT, training(), "s").model()), "a forecast from no violation");
    }

    @Test
    void itWarnsAtItsThresholdOrWhereTheBaselineWasChosenByTheBaseRateAtEvenOdds() {
        ForecastModel m = EventModel.learn(MACHINES, NO_ABORT, training(), "s").model();
        EventModel at60 = new EventModel(7, 4, m.withThreshold(0.6, "chosen", true));
        Forecaster f = new Forecaster(m, MACHINES);
        Forecast afterA = EventModel.shown(f.pair("a", "x", 0, EventModel.HOLDS, 1));
        Forecast afterB = EventModel.shown(f.pair("b", "y", 1, EventModel.HOLDS, 2));
        assertFalse(at60.warns(afterA), "416/729 = 0.571 < 0.6");
        assertTrue(at60.warns(afterB), "335/486 = 0.689 >= 0.6");
        EventModel base = new EventModel(7, 4, m.withThreshold(0.6, "chosen", true).withClauses(Clauses.BASELINE));
        assertTrue(base.warns(afterA), "the base rate 5/9 is at even odds or more: the baseline warns every run");
    }

    @Test
    void theEventInWords() {
        assertEquals("GoTo/getStatus reply 3 comes", EventModel.event(NO_ABORT));
        Precedence p = new Precedence("ready-first", "no grasp before ready", null, Scope.GLOBAL,
                Event.of(new RecordMatch(RecordKind.REPLY, "ArmService", "ready", null, null, null, null)),
                Event.of(new RecordMatch(RecordKind.COMMAND, "ArmService", "closeHand", null, null, null, null)));
        assertEquals("ArmService/closeHand command comes before any ArmService/ready reply", EventModel.event(p));
    }

    @Test
    void forecastJsonKeepsEveryEventForecastAndWhyAPropertyHasNone() {
        EventModel learned = EventModel.learn(MACHINES, NO_ABORT, training(), "s");
        EventModel none = new EventModel(43, 0, null);
        ForecastModel m = ForecastModel.of("s", 43, List.of(new PropertyModel.OfEvent("no-abort", learned),
                new PropertyModel.OfEvent("other", none)));
        String text = ForecastFile.write(m);
        assertTrue(text.contains("\"noForecast\" : \"never violated in 43 training runs\""), text);
        ForecastModel back = ForecastFile.read(text);
        assertEquals(m.events(), back.events());
        assertEquals(m, back);
        assertTrue(ForecastFile.read(ForecastFile.write(StatsLearner.learn(MACHINES, List.of(), "s", Double.NaN)))
                .events().isEmpty(), "a file without events reads as one learned before them");
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class, () -> ForecastFile.read(
                text.replace("\"runs\" : 43,\n      \"violating\" : 0", "\"runs\" : -1,\n      \"violating\" : 0")));
        assertEquals("'properties.other.runs': -1, expected 0 or more", bad.getMessage());
    }
}
