package dev.predmon.forecast;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.TreeSet;

/**
 * Chooses the probability at which the forecast rule warns, from held-out runs: each run's highest calibrated forecast
 * before its violation (or before its end, when it held). A threshold warns on every run whose peak reaches it; it is
 * chosen to make the fewest wrong calls (a false alarm and a missed violation cost the same), never below
 * {@link #FLOOR}; among the equally good ones, the one that warns the most violations (at the same cost, a missed
 * violation is the call that cannot be taken back: on a handful of runs, a tie between warning nothing and warning
 * every violation at the price of as many false alarms is common, and goes to the warning); and among those, the
 * middle of the widest gap between peaks, so that a run not seen in training is least likely to fall on the wrong side.
 */
public final class ThresholdChoice {

    /** The threshold used when the held-out runs cannot choose one (none of one kind). */
    public static final double DEFAULT = 0.5;
    /**
     * Never warn below even odds, whatever the data. The peaks are calibrated probabilities, and with a false alarm
     * and a missed violation costing the same, a warning whose own probability says the run more likely holds is not
     * a prediction: on runs like the training runs, more of those warnings would be false than true.
     */
    public static final double FLOOR = 0.5;

    private ThresholdChoice() {
    }

    /**
     * One held-out run: its highest forecast before the violation or the end, whether it violated, and whether the
     * thesis's matching warned it anyway (before its violation), whatever the threshold.
     */
    public record Peak(double probability, boolean violated, boolean caught) {

        public Peak(double probability, boolean violated) {
            this(probability, violated, false);
        }

        boolean warnedAt(double t) {
            return caught || probability >= t;
        }
    }

    /**
     * The chosen threshold, why in one line (without the threshold: the rule that uses it says it), and whether
     * held-out runs of both outcomes chose it.
     */
    public record Choice(double threshold, String note, boolean validated) {
    }

    /** Chooses from {@code peaks}, held-out runs. */
    public static Choice choose(List<Peak> peaks) {
        return choose(peaks, "runs");
    }

    /**
     * Chooses from {@code peaks}; {@code what} names what each peak is the peak of, for the note ({@code runs},
     * {@code obligations}).
     */
    public static Choice choose(List<Peak> peaks, String what) {
        long bad = peaks.stream().filter(Peak::violated).count();
        long good = peaks.size() - bad;
        if (bad == 0 || good == 0) {
            return new Choice(DEFAULT, String.format(Locale.ROOT, "the %d held-out %s %s", peaks.size(), what,
                    bad == 0 ? "all held" : "all violated"), false);
        }
        TreeSet<Double> distinct = new TreeSet<>();
        peaks.forEach(p -> distinct.add(p.probability()));
        distinct.add(FLOOR);
        distinct.add(1.0);
        List<Double> cuts = new ArrayList<>(distinct.tailSet(FLOOR, true));
        int bestErrors = Integer.MAX_VALUE;
        int bestHits = -1;
        double bestGap = -1;
        double best = DEFAULT;
        // A threshold between two neighbouring peaks: the calls are the same anywhere in the gap.
        for (int i = 0; i < cuts.size(); i++) {
            double lowSide = i == 0 ? FLOOR : cuts.get(i - 1);
            double t = i == 0 ? FLOOR : (lowSide + cuts.get(i)) / 2;
            double gap = i == 0 ? 0 : cuts.get(i) - lowSide;
            int errors = errors(peaks, t);
            int hits = (int) peaks.stream().filter(p -> p.violated() && p.warnedAt(t)).count();
            if (errors < bestErrors || (errors == bestErrors && (hits > bestHits
                    || (hits == bestHits && gap > bestGap)))) {
                bestErrors = errors;
                bestHits = hits;
                bestGap = gap;
                best = t;
            }
        }
        int alarms = 0;
        int hits = 0;
        for (Peak p : peaks) {
            if (p.warnedAt(best)) {
                if (p.violated()) {
                    hits++;
                } else {
                    alarms++;
                }
            }
        }
        return new Choice(best, String.format(Locale.ROOT,
                "by cross-validation on %d held-out %s: warned %d of %d violations, %d false alarm(s) in %d",
                peaks.size(), what, hits, bad, alarms, good), true);
    }

    private static int errors(List<Peak> peaks, double t) {
        int errors = 0;
        for (Peak p : peaks) {
            if (p.warnedAt(t) != p.violated()) {
                errors++;
            }
        }
        return errors;
    }
}
