package dev.predmon.forecast;

import dev.predmon.mealy.MealyMapping;
import net.automatalib.automaton.transducer.CompactMealy;

import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import java.util.Map;

/**
 * The forecast of one run, pair by pair: it follows every learned machine as a set of candidate states, and looks the
 * states up in the learned {@link ForecastModel}.
 *
 * <p>The probability is Prevent's per-state violation rate with a Beta prior: with {@code k} of {@code n} training
 * runs through the current states violating, {@code (k + s p0) / (n + s)}, where {@code s} is
 * {@link ForecastModel#PRIOR_RUNS} and the prior's mean {@code p0} is the violation rate of the training runs that went
 * as low as the property's current value ({@link ForecastModel#valueRate}). A state seen by few runs thus cannot claim
 * certainty, and leans on what the battery level says. Several machines alive at once are weighted by the runs behind
 * their states.
 *
 * <p>Never blind: when no machine takes a pair, the run is novel from that line on. The forecaster re-synchronises on
 * the longest suffix of the latest {@link #WINDOW} pairs that some state of some machine accepts (a k-tails back-off,
 * which also finds the initial state when the tree starts over) and goes on from there, its evidence discounted by how
 * short that suffix is. Where nothing accepts even the last pair, the value table alone answers.
 *
 * <p>The time to violation is the property's distance to its threshold over its drift: the run's own rate from its
 * latest readings, else the states' learned drift, with an interval from the spread of the rates. Without a falling
 * property it is the training runs' time from these states to their violation.
 */
public final class Forecaster {

    /** Pairs remembered for re-synchronisation, and the suffix length at which the evidence counts in full. */
    public static final int WINDOW = 8;
    /** Distinct readings of the property the run's own drift is measured over. */
    static final int READINGS = 6;

    private final ForecastModel stats;
    private final List<String> ids = new ArrayList<>();
    private final List<CompactMealy<String, String>> machines = new ArrayList<>();
    private final BitSet[] candidates;
    private final String[] recentIn = new String[WINDOW];
    private final String[] recentOut = new String[WINDOW];
    private int recent;
    private final double[] readT = new double[READINGS];
    private final double[] readV = new double[READINGS];
    private int readings;
    private Long novelSince;
    /** Pairs the current candidates rest on since the last re-synchronisation; WINDOW or more is full evidence. */
    private int depth;
    private boolean violated;

    /** @param machines the learned machines by id, as {@code stats} knows them */
    public Forecaster(ForecastModel stats, Map<String, CompactMealy<String, String>> machines) {
        this.stats = stats;
        machines.forEach((id, m) -> {
            ids.add(id);
            this.machines.add(m);
        });
        candidates = new BitSet[this.machines.size()];
        reset();
    }

    /** A new run: every machine back to its initial state. */
    public void reset() {
        for (int m = 0; m < machines.size(); m++) {
            candidates[m] = new BitSet();
            candidates[m].set(machines.get(m).getInitialState());
        }
        recent = 0;
        readings = 0;
        novelSince = null;
        depth = WINDOW;
        violated = false;
    }

    /**
     * The run recovered (the property holds again, or the alarm's cause ended): the forecast starts over in the states
     * the run is in, no longer violated, its drift measured afresh from the next readings.
     */
    public void recovered() {
        readings = 0;
        violated = false;
    }

    /** The learned statistics. */
    public ForecastModel stats() {
        return stats;
    }

    /**
     * Takes the next pair and forecasts.
     *
     * @param time  the time of its completing record, in the log's unit
     * @param value the property's last value (NaN before the first reading)
     * @param line  its line, for "novel since"
     */
    public Forecast pair(String input, String output, double time, double value, long line) {
        recentIn[recent % WINDOW] = input;
        recentOut[recent % WINDOW] = output;
        recent++;
        remember(time, value);
        violated |= !Double.isNaN(value) && !Double.isNaN(stats.limit()) && value < stats.limit();
        boolean any = false;
        for (int m = 0; m < machines.size(); m++) {
            BitSet next = new BitSet();
            CompactMealy<String, String> machine = machines.get(m);
            for (int q = candidates[m].nextSetBit(0); q >= 0; q = candidates[m].nextSetBit(q + 1)) {
                int s = MealyMapping.pairStep(machine, q, input, output);
                if (s >= 0) {
                    next.set(s);
                }
            }
            candidates[m] = next;
            any |= !next.isEmpty();
        }
        if (any) {
            depth++;
        } else {
            if (novelSince == null) {
                novelSince = line;
            }
            resynchronise();
        }
        return forecast(value);
    }

    /**
     * The robot did something the abstraction cannot name ({@code UnmappedMessages.novelty}: a place no training
     * run went to, a reply no rule takes): the trace misses a step here. The run is novel from this line, and the
     * pairs before it no longer join those after it: until the next pair re-synchronises, the value alone speaks.
     */
    public void unseen(long line) {
        if (novelSince == null) {
            novelSince = line;
        }
        recent = 0;
        depth = 0;
        for (int m = 0; m < machines.size(); m++) {
            candidates[m] = new BitSet();
        }
    }

    /**
     * The property read a new value between pairs: the same states, forecast again at that value (the battery moves
     * while the interface repeats itself, and the compacted trace then has no pair to tell).
     */
    public Forecast reading(double time, double value) {
        remember(time, value);
        violated |= !Double.isNaN(value) && !Double.isNaN(stats.limit()) && value < stats.limit();
        return forecast(value);
    }

    /** Finds the states that accept the longest suffix of the latest pairs; none when not even the last one. */
    private void resynchronise() {
        int have = Math.min(recent, WINDOW);
        BitSet[] best = null;
        for (int j = 1; j <= have; j++) {
            BitSet[] found = new BitSet[machines.size()];
            boolean any = false;
            for (int m = 0; m < machines.size(); m++) {
                found[m] = acceptingSuffix(machines.get(m), j);
                any |= !found[m].isEmpty();
            }
            if (!any) {
                break;
            }
            best = found;
            depth = j;
        }
        if (best == null) {
            depth = 0;
            for (int m = 0; m < machines.size(); m++) {
                candidates[m] = new BitSet();
            }
        } else {
            System.arraycopy(best, 0, candidates, 0, best.length);
        }
    }

    /** The states {@code machine} reaches on the last {@code j} pairs, from every state that accepts them. */
    private BitSet acceptingSuffix(CompactMealy<String, String> machine, int j) {
        BitSet ends = new BitSet();
        for (int q = 0; q < machine.size(); q++) {
            int s = q;
            for (int k = recent - j; k < recent && s >= 0; k++) {
                s = MealyMapping.pairStep(machine, s, recentIn[k % WINDOW], recentOut[k % WINDOW]);
            }
            if (s >= 0) {
                ends.set(s);
            }
        }
        return ends;
    }

    private void remember(double time, double value) {
        if (Double.isNaN(value) || Double.isNaN(time)) {
            return;
        }
        int last = (readings - 1) % READINGS;
        if (readings > 0 && readV[last] == value) {
            return; // only changes of the value tell its drift; a repeated reading would dilute it
        }
        readT[readings % READINGS] = time;
        readV[readings % READINGS] = value;
        readings++;
    }

    private Forecast forecast(double value) {
        Double v = Double.isNaN(value) ? null : value;
        if (violated) {
            return new Forecast(1.0, 0.0, 0.0, 0.0, Forecast.Basis.VIOLATED, novelSince, 0, 0, v, null, stats.unit());
        }
        double prior = stats.valueRate(value);
        double weight = Math.min(1.0, depth / (double) WINDOW);
        double sum = 0;
        double weights = 0;
        int runs = 0;
        int bad = 0;
        double[] drift = {0, 0, 0}; // rate times runs, spread times runs, runs
        StateStats timed = null;
        for (int m = 0; m < machines.size(); m++) {
            Map<Integer, StateStats> table = stats.states().getOrDefault(ids.get(m), Map.of());
            double n = 0; // runs as low, with the safe runs' edge (Lows#weight)
            int count = 0; // runs as low, as the words count them
            int k = 0;
            for (int q = candidates[m].nextSetBit(0); q >= 0; q = candidates[m].nextSetBit(q + 1)) {
                StateStats s = table.get(q);
                if (s == null) {
                    continue;
                }
                n += s.lows().weight(value);
                count += s.lows().runs(value);
                k += s.lows().violating(value);
                if (s.driftRuns() > 0) {
                    drift[0] += s.drift() * s.driftRuns();
                    drift[1] += s.driftSpread() * s.driftRuns();
                    drift[2] += s.driftRuns();
                }
                if (s.violated() > 0 && (timed == null || s.violated() > timed.violated())) {
                    timed = s;
                }
            }
            if (n > 0) {
                double p = (weight * k + ForecastModel.PRIOR_RUNS * prior) / (weight * n + ForecastModel.PRIOR_RUNS);
                sum += n * p;
                weights += n;
                if (count > runs) {
                    runs = count;
                    bad = k;
                }
            }
        }
        Forecast.Basis basis;
        double p;
        if (weights > 0 && novelSince == null) {
            basis = Forecast.Basis.MATCHED;
            p = sum / weights;
        } else {
            // the same estimate as in a state, the state being "anywhere": so that a run that left every learned
            // state is judged on the same scale as one that did not
            double anywhere = stats.valueOnly(value, prior);
            if (weights > 0 && sum / weights >= anywhere) {
                basis = Forecast.Basis.RESYNCHRONISED;
                p = sum / weights;
            } else {
                // through novelty, the forecast is never less than what the property's value alone says
                basis = weights > 0 ? Forecast.Basis.RESYNCHRONISED : Forecast.Basis.VALUE_ONLY;
                p = anywhere;
                runs = stats.lows().runs(value);
                bad = stats.lows().violating(value);
                timed = weights > 0 ? timed : null;
            }
        }
        return timed(stats.calibration().apply(Math.max(0.0, Math.min(1.0, p))), basis, runs, bad, v, drift, timed);
    }

    /** Adds the time to violation: the property's drift first, the states' recorded times else. */
    private Forecast timed(double p, Forecast.Basis basis, int runs, int bad, Double value, double[] learned,
                           StateStats timed) {
        double limit = stats.limit();
        double[] own = ownDrift();
        double rate = Double.NaN;
        double fast = Double.NaN;
        double slow = Double.NaN;
        if (own != null) {
            rate = own[0];
            fast = own[1];
            slow = own[2];
        } else if (learned[2] > 0) {
            rate = learned[0] / learned[2];
            double spread = learned[1] / learned[2];
            fast = rate - spread;
            slow = rate + spread;
        }
        if (value != null && !Double.isNaN(limit) && rate < 0) {
            double gap = value - limit;
            Double high = slow < 0 ? gap / -slow : null;
            return new Forecast(p, gap / -rate, gap / -Math.min(fast, rate), high, basis, novelSince, runs, bad, value,
                    rate, stats.unit());
        }
        Double r = Double.isNaN(rate) ? null : rate;
        if (timed != null && !Double.isNaN(timed.toViolationMedian())) {
            return new Forecast(p, timed.toViolationMedian(), timed.toViolationLow(), timed.toViolationHigh(), basis,
                    novelSince, runs, bad, value, r, stats.unit());
        }
        return new Forecast(p, null, null, null, basis, novelSince, runs, bad, value, r, stats.unit());
    }

    /**
     * The run's own drift over its latest distinct readings: {rate by least squares, fastest and slowest rate between
     * two consecutive readings}; null with fewer than three readings.
     */
    private double[] ownDrift() {
        int n = Math.min(readings, READINGS);
        if (n < 3) {
            return null;
        }
        double mt = 0;
        double mv = 0;
        for (int i = readings - n; i < readings; i++) {
            mt += readT[i % READINGS];
            mv += readV[i % READINGS];
        }
        mt /= n;
        mv /= n;
        double cov = 0;
        double var = 0;
        double fast = Double.POSITIVE_INFINITY;
        double slow = Double.NEGATIVE_INFINITY;
        for (int i = readings - n; i < readings; i++) {
            double dt = readT[i % READINGS] - mt;
            cov += dt * (readV[i % READINGS] - mv);
            var += dt * dt;
            if (i > readings - n) {
                double step = readT[i % READINGS] - readT[(i - 1) % READINGS];
                if (step > 0) {
                    double r = (readV[i % READINGS] - readV[(i - 1) % READINGS]) / step;
                    fast = Math.min(fast, r);
                    slow = Math.max(slow, r);
                }
            }
        }
        if (var <= 0 || Double.isInfinite(fast)) {
            return null;
        }
        return new double[] {cov / var, fast, slow};
    }
}
