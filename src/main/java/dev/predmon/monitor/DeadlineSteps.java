package dev.predmon.monitor;

import dev.predmon.forecast.Survival;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Response;

/**
 * Told every deadline forecast the monitor makes and how each obligation it forecast ended, with the record and the
 * run: the per-obligation stream of the replay ({@code dev.predmon.replay}), on which {@code learn} chooses each
 * deadline's threshold and calibration. {@link MonitorEvent.ForecastChanged} tells only the changes the page shows,
 * calibrated; this tells every judgement, raw.
 */
public interface DeadlineSteps {

    /**
     * {@code property}'s pending obligation judged at {@code record}.
     *
     * @param elapsed how long it had been pending, in its deadline's unit
     * @param raw     the estimate before the deadline rule's calibration
     * @param curve   the training obligations it is judged against: those that began where it did
     *                ({@link Survival#at}), from which its late clause is computed
     */
    void forecast(int run, Response property, LogRecord record, double elapsed, Survival.Estimate raw,
                  Survival curve);

    /**
     * An obligation of {@code property} that had a forecast ended at {@code record}.
     *
     * @param duration   how long it was pending, in its deadline's unit
     * @param discharged whether its response came; else it was let go still pending (its deadline passed, or its
     *                   scope closed)
     */
    void ended(int run, Response property, LogRecord record, double duration, boolean discharged);
}
