package dev.predmon.forecast;

import java.util.List;

/**
 * Platt scaling of the forecast: {@code P = 1 / (1 + exp(-(slope * logit(p) + intercept)))} for the forecaster's raw
 * estimate {@code p}. It is fitted on held-out forecasts (the runs of each cross-validation fold, forecast by the
 * machines and statistics learned without them), so it corrects what the per-state tables get wrong on runs they did
 * not see: a slope below one when the raw estimates were too sure, an intercept when they leaned one way.
 *
 * <p>The map is strictly increasing (the slope is kept at {@value #MIN_SLOPE} or more), so a run reaches a threshold
 * mapped through it exactly when its raw estimate reaches the raw threshold: calibration changes what the probability
 * says, never who is warned.
 *
 * @param slope     the factor on the raw estimate's log-odds
 * @param intercept the shift of the log-odds
 * @param runs      the held-out runs it was fitted on, 0 for the identity
 */
public record Calibration(double slope, double intercept, int runs) {

    /** The map that changes nothing: what a model directory without a calibration uses. */
    public static final Calibration IDENTITY = new Calibration(1, 0, 0);

    /** The slope is never lower: the map stays strictly increasing. */
    static final double MIN_SLOPE = 0.1;
    /**
     * The prior's weight, in runs: the fit is pulled towards the identity as if this many runs had agreed with the
     * raw estimate, so that a handful of held-out runs cannot flatten the forecast.
     */
    static final double PRIOR_RUNS = 2.0;
    /** A trace of a Gaussian prior on the slope and intercept, so that the fit is defined on any sample. */
    private static final double RIDGE = 1e-3;
    /** Raw estimates are kept this far from 0 and 1 before taking their log-odds. */
    private static final double EDGE = 1e-3;

    /**
     * One held-out run: its raw forecasts before its violation (or its end), and whether it violated. A run weighs
     * one, shared by its forecasts, so that a long run does not outvote a short one.
     */
    public record Sample(List<Double> probabilities, boolean violated) {

        public Sample {
            probabilities = List.copyOf(probabilities);
        }
    }

    /** The calibrated probability of the raw estimate {@code p}. */
    public double apply(double p) {
        if (runs == 0) {
            return p;
        }
        return sigmoid(slope * logit(p) + intercept);
    }

    /**
     * The map that makes {@code samples} most likely (weighted logistic regression of the outcome on the raw
     * estimate's log-odds, by Newton's method), pulled towards the identity by pseudo-runs worth
     * {@link #PRIOR_RUNS} runs that say what the raw estimate says. The identity when no sample has a forecast.
     */
    public static Calibration fit(List<Sample> samples) {
        List<Sample> used = samples.stream().filter(s -> !s.probabilities().isEmpty()).toList();
        if (used.isEmpty()) {
            return IDENTITY;
        }
        double pseudo = PRIOR_RUNS / used.size();
        double a = 1;
        double b = 0;
        double loss = loss(used, pseudo, a, b);
        for (int iteration = 0; iteration < 100; iteration++) {
            // gradient and Hessian of the loss (see loss)
            double ga = RIDGE * (a - 1);
            double gb = RIDGE * b;
            double haa = RIDGE;
            double hab = 0;
            double hbb = RIDGE;
            for (Sample s : used) {
                double y = s.violated() ? 1 : 0;
                double w = 1.0 / s.probabilities().size();
                for (double p : s.probabilities()) {
                    double x = logit(p);
                    double q = sigmoid(a * x + b);
                    double r = w * (q - y) + w * pseudo * (q - p);
                    double v = w * (1 + pseudo) * q * (1 - q);
                    ga += r * x;
                    gb += r;
                    haa += v * x * x;
                    hab += v * x;
                    hbb += v;
                }
            }
            double det = haa * hbb - hab * hab;
            double da = (hbb * ga - hab * gb) / det;
            double db = (haa * gb - hab * ga) / det;
            if (!(det > 0) || a - da < MIN_SLOPE) {
                // the slope rests on its floor (or the step is undefined): a step of the intercept alone
                da = det > 0 ? a - MIN_SLOPE : 0; // a is never below the floor
                db = gb / hbb;
            }
            // Newton's step, halved until the loss goes down (the loss is convex; a long step may overshoot)
            double step = 1;
            double next = loss(used, pseudo, a - da, b - db);
            while (next > loss && step > 1e-6) {
                step /= 2;
                next = loss(used, pseudo, a - step * da, b - step * db);
            }
            if (!(next <= loss)) {
                break;
            }
            a = Math.max(MIN_SLOPE, a - step * da);
            b -= step * db;
            boolean done = loss - next < 1e-12;
            loss = next;
            if (done) {
                break;
            }
        }
        return new Calibration(a, b, used.size());
    }

    /**
     * The negative log-likelihood of the runs' outcomes, each run weighing one shared by its forecasts, plus that of
     * the prior's pseudo-runs, {@link #PRIOR_RUNS} runs' worth whose outcome is exactly what the raw estimate says (a
     * soft outcome), plus a trace of ridge that keeps the minimum defined.
     */
    private static double loss(List<Sample> used, double pseudo, double a, double b) {
        double sum = RIDGE / 2 * ((a - 1) * (a - 1) + b * b);
        for (Sample s : used) {
            double y = s.violated() ? 1 : 0;
            double w = 1.0 / s.probabilities().size();
            for (double p : s.probabilities()) {
                double z = a * logit(p) + b;
                // -log sigmoid(z) = log(1 + e^-z), computed without overflow
                double up = Math.max(0, -z) + Math.log1p(Math.exp(-Math.abs(z)));
                double down = up + z;
                sum += w * (y * up + (1 - y) * down) + w * pseudo * (p * up + (1 - p) * down);
            }
        }
        return sum;
    }

    private static double logit(double p) {
        double c = Math.min(1 - EDGE, Math.max(EDGE, p));
        return Math.log(c / (1 - c));
    }

    private static double sigmoid(double x) {
        return 1 / (1 + Math.exp(-x));
    }
}
