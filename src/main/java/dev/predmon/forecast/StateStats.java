package dev.predmon.forecast;

/**
 * What the training runs did from one state of one learned machine on: the per-state violation table of Prevent
 * (Babaee et al., RV 2018), with the time to the violation and the drift of the property. Times are in the log's
 * unit (seconds, or ticks); NaN where no run gave one.
 *
 * @param runs        training runs that passed through the state before any violation
 * @param violated    how many of them went on to violate the property
 * @param toViolationLow    over the violating runs, the 10th percentile of the time from the first visit to the
 *                          violation
 * @param toViolationMedian its median
 * @param toViolationHigh   its 90th percentile
 * @param toEnd       over the runs that held, the median time from the first visit to the end of the run (a censored
 *                    time: they did not violate within it)
 * @param drift       mean rate of change of the property per unit of time while in the state, over the runs with two
 *                    readings there
 * @param driftSpread the standard deviation of that rate between runs (0 with a single run)
 * @param driftRuns   the runs the drift is measured on
 * @param lows        how low each run went while safe from its first visit here on (violating and safe runs apart):
 *                    what the state's violation rate at the property's current value is counted from
 */
public record StateStats(int runs, int violated, double toViolationLow, double toViolationMedian,
                         double toViolationHigh, double toEnd, double drift, double driftSpread, int driftRuns,
                         Lows lows) {

    public StateStats {
        if (runs < 0 || violated < 0 || violated > runs) {
            throw new IllegalArgumentException("counts out of range: " + violated + " of " + runs);
        }
    }
}
