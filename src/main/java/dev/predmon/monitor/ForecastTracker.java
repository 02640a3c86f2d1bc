package dev.predmon.monitor;

import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.forecast.Forecaster;
import dev.predmon.matching.Matching;
import net.automatalib.automaton.transducer.CompactMealy;

import java.util.Map;

/**
 * The forecast of the run being watched: a {@link Forecaster} over the models' machines, and which of its forecasts
 * changed enough to be told (a forecast after every pair would flood a terminal; a change of a twentieth in the
 * probability, of the basis, or of a quarter in the time is news).
 */
final class ForecastTracker {

    /** How a warning of the forecast's probability says so. */
    static final String REACHES = "reaches the warning threshold ";
    /** A change of the probability at least this large is reported. */
    static final double STEP = 0.05;
    /** A relative change of the time to violation at least this large is reported. */
    static final double TIME_STEP = 0.25;

    private final Forecaster forecaster;
    private Forecast last;
    private Forecast told;
    private TickSeconds ticks = TickSeconds.NONE;

    private ForecastTracker(Forecaster forecaster) {
        this.forecaster = forecaster;
    }

    /**
     * The tracker of the forecast {@code model} over {@code machines}: a bound property's ({@link BoundFollow}, the
     * first floor's as any other's) or an event's ({@link EventFollow}).
     */
    static ForecastTracker of(ForecastModel model, Map<String, CompactMealy<String, String>> machines) {
        return new ForecastTracker(new Forecaster(model, machines));
    }

    /** The probability at which the forecast rule warns, for runs that match learned machines. */
    double threshold() {
        return forecaster.stats().threshold();
    }

    /**
     * Whether the forecast rule warns on {@code f} ({@link ForecastModel#warns}), {@code beyondNominal} when no
     * nominal machine matches the run any more.
     */
    boolean warns(Forecast f, boolean beyondNominal) {
        return forecaster.stats().warns(f, beyondNominal);
    }

    /**
     * Why the forecast rule warns on {@code f} ({@link #warns}), in an operator's words: its probability, time and
     * evidence, and {@code where} (the reading or pair that gave it).
     */
    String reason(Forecast f, String where) {
        return reason(f, where, false);
    }

    /** As above, of a ceiling when {@code ceiling} ({@link ForecastWords#evidence(Forecast, boolean)}). */
    String reason(Forecast f, String where, boolean ceiling) {
        String why = forecaster.stats().clauses().baseline()
                ? "with the value " + (ceiling ? "above the highest" : "below the lowest") + " any training run that"
                + " held went to (the raw-value rule, which did better than the forecast on the held-out folds)"
                : f.probability() >= threshold() && !f.novel()
                ? REACHES + ForecastWords.fixed(threshold(), 2)
                : "beyond what the training runs that held did, with the value " + (ceiling ? "above the highest"
                : "below the lowest") + " they went to";
        return ForecastWords.probability(f) + " " + why + "; " + ForecastWords.time(f) + "; "
                + ForecastWords.evidence(f, ceiling) + "; " + where;
    }

    /**
     * Whether the thesis's matching warns under the forecast rule: the cross-validation kept it only where it did
     * better on the held-out folds than the rule without it ({@link ForecastModel#matchingWarns}).
     */
    boolean matchingWarns() {
        return forecaster.stats().matchingWarns();
    }

    /** A gap in the trace at {@code line}: the run is novel from there ({@link Forecaster#unseen}). */
    void unseen(long line) {
        forecaster.unseen(line);
    }

    /**
     * Whether the forecast rule takes the thesis's "only faulty" verdict of {@code step}, forecast {@code f} (its
     * threshold was chosen knowing that verdict): only when every nominal machine was contradicted (it predicted
     * another output), and only while the run does what the models know. A nominal machine that has no transition
     * for what the run did, or that fails after a gap in the trace, says the run is new, not that it is faulty.
     * Models without a forecast ({@code f} null) have the thesis's rule only, and take every verdict.
     */
    static boolean takesMatching(Forecast f, Matching.Step step) {
        return f == null || (step.contradicted() && f.novelSince() == null);
    }

    void reset() {
        forecaster.reset();
        last = null;
        told = null;
    }

    /** The lowest value a training run that held went to (NaN without one). */
    double safeFloor() {
        return forecaster.stats().lows().safeFloor();
    }

    /** The run recovered: the forecast starts over from the states it is in ({@link Forecaster#recovered}). */
    void startOver() {
        forecaster.recovered();
        told = null;
    }

    /** The clause of the forecast rule that warns on {@code f} (only asked when {@link #warns} does). */
    MonitorEvent.Clause clause(Forecast f) {
        return f.probability() >= threshold() && !f.novel() && !forecaster.stats().clauses().baseline()
                ? MonitorEvent.Clause.FORECAST : MonitorEvent.Clause.NOVELTY;
    }

    /** Forecasts after one pair; returns the forecast when it is news, else null. */
    Forecast pair(String input, String output, double time, double value, long line) {
        return news(forecaster.pair(input, output, time, value, line));
    }

    /** Forecasts at a new value of the property; returns the forecast when it is news, else null. */
    Forecast reading(double time, double value) {
        return news(forecaster.reading(time, value));
    }

    /** Reports every forecast's times in seconds, a tick lasting {@code t}. */
    void countTicksAs(TickSeconds t) {
        ticks = t;
    }

    private Forecast news(Forecast f) {
        last = ticks.forecast(f);
        if (told == null || material(told, last)) {
            told = last;
            return last;
        }
        return null;
    }

    /** The latest forecast of the run, or null before its first pair. */
    Forecast last() {
        return last;
    }

    private static boolean material(Forecast before, Forecast now) {
        if (Math.abs(before.probability() - now.probability()) >= STEP || before.basis() != now.basis()
                || (before.timeToViolation() == null) != (now.timeToViolation() == null)) {
            return true;
        }
        if (now.timeToViolation() == null) {
            return false;
        }
        double a = before.timeToViolation();
        double b = now.timeToViolation();
        return Math.abs(a - b) > TIME_STEP * Math.max(Math.abs(a), 1e-9);
    }
}
