package dev.predmon.forecast;

import org.apache.commons.math3.distribution.TDistribution;

import java.util.Arrays;
import java.util.Collections;
import java.util.Map;
import java.util.TreeMap;

/**
 * How long the training runs' obligations stayed pending (a {@code goTo} until its destination, a low battery until
 * the turn to the charger): the Kaplan-Meier estimate of {@code S(t) = P(still pending after t)}, with censoring.
 *
 * <p>An obligation is observed either <em>discharged</em> after {@code d} (its response came) or <em>censored</em> at
 * {@code c}: the run ended, or was recovered, while it was still pending, so all that is known is that it took longer
 * than {@code c}. A missed deadline is censored at the time the run let go of it, or discharged late. Censored runs
 * count as at risk up to their time and no further, which is what keeps runs that stopped early from reading as fast.
 *
 * <p>The forecast of a pending obligation that has run {@code t} against a deadline {@code T} is
 * {@code P(miss) = S(T) / S(t)}, counted over the training obligations still pending at {@code t} (the runs "in the
 * same place"), shrunk towards the overall miss rate with a prior of {@link ForecastModel#PRIOR_RUNS} runs so that
 * three runs cannot claim certainty. The overall miss rate is {@code S(T)} over the {@code n} training obligations,
 * itself kept off 0 and 1 as the rule of succession does ({@code (n S(T) + 1/2) / (n + 1)}): after 40 obligations none
 * of which missed, the next one misses about once in 80, not never. Past every training obligation there is no evidence: the estimate
 * says so ({@link Estimate#novel}) and gives only the time left.
 *
 * <p>The curve may be conditioned on where the run was when the obligation began: the Mealy input of its trigger
 * record (which skill was asked for, where the robot was sent: {@code goTo_ch} is another leg than {@code goTo_ki}),
 * after the input of the property's previous trigger ({@code goTo_ch_i>goTo_ki_i}, the way on after a recharge).
 * Each condition with at least {@value #MIN_CONTEXT} discharged training obligations has a curve of its own
 * ({@link #at}); one with fewer is estimated by the pooled curve (and one with fewer than {@value #MIN_FIT} falls back
 * to its trigger's input alone, then to the pooled curve). The input, not a machine's state number, is the condition: the
 * input means the same in every model learned from the same abstraction (each fold's, and the final one's), where a
 * state number is only a name inside one machine.
 *
 * <p>A condition's curve also says when an obligation that began there is <em>late</em> ({@link #lateAfter}): past the
 * upper prediction bound, at a chosen level, of a log-normal fitted to how long its discharged obligations took, the
 * fit pooled towards the property's own with the weight of {@link ForecastModel#PRIOR_RUNS} obligations (a condition
 * with ten obligations moves the fit five sixths of the way from the property's to its own), and never later than
 * every discharged training obligation of the property: a leg that usually takes 10 ticks is late at 40, however long
 * other legs take. Censored obligations do not enter the fit: they tell how long a response was waited for, not how
 * long it takes.
 *
 * <p>Immutable; the durations are kept sorted, and one estimate is two binary searches and a product over the
 * distinct discharge times (a few hundred at most).
 */
public final class Survival {

    private final double[] discharged;
    private final double[] censored;
    /** Distinct discharge times, ascending, and the survival just after each. */
    private final double[] times;
    private final double[] after;
    /** By the trigger's input, the curve of the obligations that began there (only inputs with enough of them). */
    private final Map<String, Survival> contexts;
    /** The property's pooled curve this condition's fit is pooled towards; null for the pooled curve itself. */
    private final Survival prior;
    /**
     * Whether its estimates are its own Kaplan-Meier curve; a condition with fewer than {@link #MIN_CONTEXT}
     * discharged obligations is estimated by {@link #prior}'s, and only its late bound is its own (pooled towards it).
     */
    private final boolean ownCurve;
    /** Mean and variance of log(1 + duration) over the discharged obligations (NaN without two of them). */
    private final double logMean;
    private final double logVariance;
    /** The last {@link #lateAfter} level asked (negative: with censored legs) and its answer: asked at every tick. */
    private volatile double[] lastLate = {Double.NaN, Double.NaN};

    /** A condition needs this many discharged obligations for a late bound of its own (a mean and a spread). */
    public static final int MIN_FIT = 2;

    /**
     * A condition needs this many training obligations that were discharged (their response came) for a curve of its
     * own: with ten, a new obligation from the same place outlasts all of them about once in eleven; with fewer, the
     * pooled curve is the better evidence. Censored obligations do not count towards it: they tell only that the
     * response took longer than they were watched, and a condition whose obligations were all let go early would
     * call every later one novel.
     */
    public static final int MIN_CONTEXT = 10;

    /**
     * @param discharged how long each obligation that was discharged took
     * @param censored   how long each obligation that was never discharged had been pending when it was let go
     */
    public Survival(double[] discharged, double[] censored) {
        this(discharged, censored, Map.of(), null);
    }

    private Survival(double[] discharged, double[] censored, Map<String, Survival> contexts, Survival prior) {
        this.contexts = Collections.unmodifiableMap(new TreeMap<>(contexts));
        this.prior = prior;
        this.ownCurve = prior == null || discharged.length >= MIN_CONTEXT;
        this.discharged = finiteSorted(discharged, "discharged");
        this.censored = finiteSorted(censored, "censored");
        double[] t = new double[this.discharged.length];
        double[] s = new double[this.discharged.length];
        int distinct = 0;
        double survival = 1.0;
        for (int i = 0; i < this.discharged.length; ) {
            double time = this.discharged[i];
            int events = 0;
            while (i < this.discharged.length && this.discharged[i] == time) {
                events++;
                i++;
            }
            // at risk at time: every obligation, discharged or censored, that lasted at least that long
            int atRisk = atLeast(this.discharged, time) + atLeast(this.censored, time);
            survival *= 1.0 - events / (double) atRisk;
            t[distinct] = time;
            s[distinct] = survival;
            distinct++;
        }
        this.times = Arrays.copyOf(t, distinct);
        this.after = Arrays.copyOf(s, distinct);
        double sum = 0;
        for (double d : this.discharged) {
            sum += Math.log1p(d);
        }
        int n = this.discharged.length;
        this.logMean = n < 2 ? Double.NaN : sum / n;
        double squares = 0;
        for (double d : this.discharged) {
            squares += (Math.log1p(d) - logMean) * (Math.log1p(d) - logMean);
        }
        this.logVariance = n < 2 ? Double.NaN : squares / (n - 1);
    }

    /**
     * This curve with {@code byInput} as the curves of the obligations by where they began. A condition with fewer
     * than {@link #MIN_FIT} discharged obligations is left out (judged by this pooled curve); one with fewer than
     * {@link #MIN_CONTEXT} is estimated by this pooled curve, its late bound its own pooled towards this one's.
     */
    public Survival withContexts(Map<String, Survival> byInput) {
        Survival pooled = new Survival(discharged, censored);
        Map<String, Survival> kept = new TreeMap<>();
        byInput.forEach((input, s) -> {
            if (s.discharged.length >= MIN_FIT) {
                kept.put(input, new Survival(s.discharged, s.censored, Map.of(), pooled));
            }
        });
        return new Survival(discharged, censored, kept, null);
    }

    /** The curves by trigger input ({@link #withContexts}), each with enough obligations for a late bound. */
    public Map<String, Survival> contexts() {
        return contexts;
    }

    /**
     * The curve of obligations that began under {@code condition} ({@code goTo_ch_i>goTo_ki_i}: a trigger's input
     * after the previous trigger's): its own when it has one, else that of the trigger's input alone (the part after
     * the last {@code >}), else this pooled one.
     */
    public Survival at(String condition) {
        if (condition == null) {
            return this;
        }
        Survival s = contexts.get(condition);
        if (s == null) {
            int at = condition.lastIndexOf('>');
            s = at < 0 ? null : contexts.get(condition.substring(at + 1));
        }
        return s == null ? this : s;
    }

    /** How long each discharged obligation took, sorted. */
    public double[] discharged() {
        return discharged.clone();
    }

    /** How long each censored obligation had been pending when it was let go, sorted. */
    public double[] censored() {
        return censored.clone();
    }

    /**
     * How long an obligation of this condition may be pending before it is late: the upper {@code level} prediction
     * bound of the next duration, from a log-normal fitted to the discharged obligations and pooled towards the
     * property's fit with the weight of {@link ForecastModel#PRIOR_RUNS} obligations; for {@code n} obligations with
     * mean {@code m} and variance {@code v} of {@code log(1 + d)}, and the property's {@code M} and {@code V} (with
     * {@code k} the prior's weight):
     * {@code mu = (n m + k M) / (n + k)}, {@code s2 = ((n-1) v + k V) / (n - 1 + k)},
     * {@code bound = exp(mu + t(level; n - 1 + k) sqrt(s2 (1 + 1 / (n + k)))) - 1}. Never before this condition's
     * longest discharged obligation (a leg that long was seen to end), and never after the property's (one pending
     * longer than every navigation took is late whatever its condition). NaN with fewer than two discharged
     * obligations in the property.
     *
     * @param level    the prediction bound's level, above 0.5 and below 1
     * @param censored whether the ceiling is every training obligation of the property, those its run let go still
     *                 pending included (the elapsed-time rule's), rather than every discharged one
     */
    public double lateAfter(double level, boolean censored) {
        if (!(level > 0.5 && level < 1)) {
            throw new IllegalArgumentException("a prediction level is above 0.5 and below 1: " + level);
        }
        double key = censored ? -level : level;
        double[] last = lastLate;
        if (last[0] == key) {
            return last[1];
        }
        double late = late(level, censored);
        lastLate = new double[] {key, late};
        return late;
    }

    /** {@link #lateAfter(double, boolean)} with the ceiling at every discharged training obligation. */
    public double lateAfter(double level) {
        return lateAfter(level, false);
    }

    private double late(double level, boolean censored) {
        Survival pooled = prior == null ? this : prior;
        if (Double.isNaN(pooled.logMean)) {
            return Double.NaN;
        }
        double n = discharged.length;
        double k = prior == null || n < 2 ? 0 : ForecastModel.PRIOR_RUNS;
        Survival own = n < 2 ? pooled : this;
        double mu = (own.discharged.length * own.logMean + k * pooled.logMean) / (own.discharged.length + k);
        double df = own.discharged.length - 1 + k;
        double s2 = ((own.discharged.length - 1) * own.logVariance + k * pooled.logVariance) / df;
        double t = new TDistribution(null, df).inverseCumulativeProbability(level);
        double bound = Math.expm1(mu + t * Math.sqrt(s2 * (1 + 1 / (own.discharged.length + k))));
        double ceiling = censored ? pooled.longest() : pooled.discharged[pooled.discharged.length - 1];
        double floor = own.discharged[own.discharged.length - 1];
        return Math.min(Math.max(bound, floor), ceiling);
    }

    /** Training obligations, discharged or not (the pooled curve's for a condition estimated by it). */
    public int size() {
        if (!ownCurve) {
            return prior.size();
        }
        return discharged.length + censored.length;
    }

    /** The longest any training obligation was seen pending (discharged or censored); NaN without one. */
    public double longest() {
        if (!ownCurve) {
            return prior.longest();
        }
        double d = discharged.length == 0 ? Double.NEGATIVE_INFINITY : discharged[discharged.length - 1];
        double c = censored.length == 0 ? Double.NEGATIVE_INFINITY : censored[censored.length - 1];
        double m = Math.max(d, c);
        return Double.isInfinite(m) ? Double.NaN : m;
    }

    /** The Kaplan-Meier estimate of P(still pending after {@code t}); 1 before the first discharge. */
    public double survival(double t) {
        if (!ownCurve) {
            return prior.survival(t);
        }
        int i = Lows.atMost(times, t);
        return i == 0 ? 1.0 : after[i - 1];
    }

    /** Training obligations still pending after {@code t}: at risk of missing a deadline beyond it. */
    public int pendingAfter(double t) {
        if (!ownCurve) {
            return prior.pendingAfter(t);
        }
        return discharged.length - Lows.atMost(discharged, t) + censored.length - Lows.atMost(censored, t);
    }

    /**
     * The forecast of an obligation pending for {@code elapsed} against {@code deadline} (same unit).
     *
     * @return the estimate; {@link Estimate#novel} when {@code elapsed} is longer than every training obligation (or
     *         there is none), and then its probability is NaN
     */
    public Estimate estimate(double elapsed, double deadline) {
        if (!ownCurve) {
            return prior.estimate(elapsed, deadline);
        }
        double left = Math.max(0.0, deadline - elapsed);
        int atRisk = pendingAfter(elapsed);
        if (atRisk == 0 && !(elapsed <= longest())) {
            // Past every training obligation. One pending exactly as long as the longest is not: in ticks or
            // attempts, the longest training one was still pending at that count too, until its response came.
            return new Estimate(Double.NaN, left, 0, 0, true);
        }
        double base = missRate(deadline);
        double now = survival(elapsed);
        double km = now <= 0 ? 1.0 : Math.min(1.0, survival(Math.max(elapsed, deadline)) / now);
        double p = (atRisk * km + ForecastModel.PRIOR_RUNS * base) / (atRisk + ForecastModel.PRIOR_RUNS);
        return new Estimate(p, left, atRisk, pendingAfter(Math.max(elapsed, deadline)), false);
    }

    /**
     * The overall share of obligations that miss {@code deadline}, from the {@code n} training ones: the Kaplan-Meier
     * {@code S(deadline)} with half an obligation each way ({@code (n S + 1/2) / (n + 1)}, Jeffreys' prior), so that no
     * finite number of obligations that all made it reads as a certainty that the next one will.
     */
    public double missRate(double deadline) {
        if (!ownCurve) {
            return prior.missRate(deadline);
        }
        int n = size();
        return (n * survival(deadline) + 0.5) / (n + 1);
    }

    /**
     * A deadline forecast.
     *
     * @param probability P(the deadline passes with the obligation still pending); NaN when novel
     * @param timeLeft    time until the deadline, in the log's unit (0 once it is due)
     * @param atRisk      training obligations that had been pending this long
     * @param longer      of them, how many were still pending at the deadline
     * @param novel       the obligation has been pending longer than any training obligation: no evidence
     */
    public record Estimate(double probability, double timeLeft, int atRisk, int longer, boolean novel) {
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Survival s && Arrays.equals(discharged, s.discharged) && Arrays.equals(censored, s.censored)
                && contexts.equals(s.contexts);
    }

    @Override
    public int hashCode() {
        return 31 * Arrays.hashCode(discharged) + Arrays.hashCode(censored); // the prior follows from the pooled curve
    }

    private static double[] finiteSorted(double[] values, String what) {
        for (double v : values) {
            if (!Double.isFinite(v) || v < 0) {
                throw new IllegalArgumentException(what + " duration must be finite and not negative: " + v);
            }
        }
        double[] copy = values.clone();
        Arrays.sort(copy);
        return copy;
    }

    private static int atLeast(double[] sorted, double value) {
        int lo = 0;
        int hi = sorted.length;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (sorted[mid] < value) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return sorted.length - lo;
    }
}
