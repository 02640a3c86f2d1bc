package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.compact.IoPair;
import dev.predmon.forecast.Forecast;
import dev.predmon.matching.Matching;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Each clause of the warning decision, on the shipped models' forecast (threshold 0.94, safe floor from training). */
class WarningPolicyTest {

    private static final Abstraction A = AbstractionFiles.defaults();
    private static final IoPair PAIR = new IoPair("level_i", "o_level_low", null, null);

    private static Forecast forecast(double p, Long novelSince, double value) {
        return new Forecast(p, 10.0, 5.0, 20.0, Forecast.Basis.MATCHED, novelSince, 10, 5, value, -1.0, "s");
    }

    private static Matching.Step step(boolean nominalAlive, boolean ruleWarns, boolean contradicted) {
        return new Matching.Step(List.of(), List.of("depleted"), nominalAlive, ruleWarns, contradicted);
    }

    private static WarningPolicy policy(WarningRule rule, Alarm[] alarm) throws Exception {
        ModelSet models = ModelStore.read(Path.of("models"), A);
        ForecastTracker tracker = ForecastTracker.of(models);
        alarm[0] = new Alarm(A.safety().orElseThrow(), tracker, e -> { });
        return new WarningPolicy(rule, tracker, alarm[0]);
    }

    @Test
    void theForecastRuleWarnsAtTheThresholdAndBeyondTheSafeRunsBelowTheirFloor() throws Exception {
        Alarm[] alarm = new Alarm[1];
        WarningPolicy p = policy(WarningRule.FORECAST, alarm);
        assertNull(p.atPair(PAIR, step(true, false, false), forecast(0.5, null, 80)), "under the threshold");
        WarningPolicy.Decision at = p.atPair(PAIR, step(true, false, false), forecast(0.99, null, 80));
        assertEquals(MonitorEvent.Clause.FORECAST, at.clause());
        assertTrue(at.reason().contains("after level_i -> o_level_low"), at.reason());
        assertEquals(MonitorEvent.Clause.NOVELTY, p.atReading(forecast(0.1, 12L, 1), 1, false).clause(),
                "a novel run below every safe run's lowest value");
        assertNull(p.atReading(forecast(0.1, null, 1), 1, false), "the same value in a run the models know");
        assertEquals(MonitorEvent.Clause.NOVELTY, p.atReading(forecast(0.1, null, 1), 1, true).clause(),
                "no nominal model matching counts as beyond them");
    }

    @Test
    void theForecastRuleTakesTheMatchingOnlyWhenEveryNominalModelWasContradictedInAKnownRun() throws Exception {
        Alarm[] alarm = new Alarm[1];
        WarningPolicy p = policy(WarningRule.FORECAST, alarm);
        assertEquals(MonitorEvent.Clause.MATCHING, p.atPair(PAIR, step(false, true, true),
                forecast(0.1, null, 80)).clause());
        assertNull(p.atPair(PAIR, step(false, true, false), forecast(0.1, null, 80)),
                "a nominal model without a transition says the run is new, not faulty");
        assertNull(p.atPair(PAIR, step(false, true, true), forecast(0.1, 7L, 80)), "not once the run is novel");
    }

    @Test
    void noSecondWarningWhileOneIsUpAndNoneUnderTheForecastRuleWhileViolated() throws Exception {
        Alarm[] alarm = new Alarm[1];
        WarningPolicy p = policy(WarningRule.FORECAST, alarm);
        WarningPolicy.Decision d = p.atPair(PAIR, step(true, false, false), forecast(0.99, null, 80));
        alarm[0].warned(new MonitorEvent.Warning(1, 1, List.of(), 80.0, 1, null, 0, WarningRule.FORECAST, null,
                d.reason(), d.clause(), null, "battery", null));
        assertNull(p.atPair(PAIR, step(true, false, false), forecast(0.99, null, 80)));
        Alarm[] fresh = new Alarm[1];
        WarningPolicy q = policy(WarningRule.FORECAST, fresh);
        fresh[0].violatedNow();
        assertNull(q.atPair(PAIR, step(true, false, false), forecast(0.99, null, 80)));
        assertNull(q.atReading(forecast(0.99, null, 10), 10, false));
        Alarm[] match = new Alarm[1];
        WarningPolicy m = policy(WarningRule.MATCH, match);
        match[0].violatedNow();
        assertEquals(MonitorEvent.Clause.MATCHING, m.atPair(PAIR, step(false, true, false), null).clause(),
                "the thesis's rule warns whatever the property did");
        assertNull(m.atPair(PAIR, step(true, false, false), forecast(0.99, null, 80)),
                "the match rule never warns by the forecast");
    }
}
