package dev.predmon.event;

import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.forecast.Survival;
import dev.predmon.monitor.PropertyStatus;
import dev.predmon.property.PropertyChecker.PropertyVerdict;
import dev.predmon.property.Verdict;

import java.util.List;
import java.util.Locale;

/**
 * A property's verdict on a run as JSON: {@code property} its id, {@code name}, {@code kind}, {@code verdict}
 * ({@code holds}, {@code pending}, {@code violated} or {@code no-evidence}); a violation's {@code line}, {@code time},
 * {@code value} (of a bound) and {@code what}; for no evidence, what never occurred in {@code what}; a pending response's trigger {@code line}, {@code since}, {@code deadline} and
 * {@code unit} ({@code ticks}, {@code seconds} or {@code occurrences}); for the last run, its latest {@code forecast}
 * (null for the earlier runs).
 */
public record PropertyJson(String property, String name, String kind, String verdict, Long line, Double time,
                           Double value, String what, Double since, Double deadline, String unit, LatestJson forecast) {

    /**
     * A property's latest forecast: what forecasts it ({@code model}: {@code forecast}, {@code deadline} or
     * {@code none}), the {@code probability} of a violation (of a miss, for a deadline; null without one),
     * {@code timeLeft} (to the violation, or to the deadline) in {@code unit}, {@code novel} (pending longer than any
     * training obligation: no evidence), and the same in words.
     */
    public record LatestJson(String model, Double probability, Double timeLeft, String unit, boolean novel, String words) {
    }

    public static PropertyJson of(PropertyVerdict pv) {
        return of(pv, null);
    }

    private static PropertyJson of(PropertyVerdict pv, LatestJson forecast) {
        Verdict v = pv.verdict();
        String id = pv.property().id();
        String name = pv.property().name();
        String kind = pv.property().kind();
        if (v instanceof Verdict.Violated x) {
            return new PropertyJson(id, name, kind, v.id(), x.line(), x.time(), x.value(), x.what(), null, null, null,
                    forecast);
        }
        if (v instanceof Verdict.Pending p) {
            return new PropertyJson(id, name, kind, v.id(), p.line(), null, null, null, p.since(), p.deadline(),
                    p.unit().key, forecast);
        }
        if (v instanceof Verdict.NoEvidence n) {
            return new PropertyJson(id, name, kind, v.id(), null, null, null, n.why(), null, null, null, forecast);
        }
        return new PropertyJson(id, name, kind, v.id(), null, null, null, null, null, null, null, forecast);
    }

    public static List<PropertyJson> of(List<PropertyVerdict> verdicts) {
        return verdicts.stream().map(PropertyJson::of).toList();
    }

    /** Every property of the last run with its verdict and latest forecast. */
    public static List<PropertyJson> latest(List<PropertyStatus> statuses) {
        return statuses.stream().map(s -> of(new PropertyVerdict(s.property(), s.verdict()), latest(s)))
                .toList();
    }

    /** One line per property for the end summary: {@code no-abort (navigation never aborts): holds}. */
    public static List<String> lines(List<PropertyVerdict> verdicts) {
        return verdicts.stream().map(pv -> String.format(Locale.ROOT, "  %s (%s): %s", pv.property().id(),
                pv.property().name(), pv.verdict().describe())).toList();
    }

    /** As above, for the last run, each with its latest forecast: {@code ...: holds; no forecast: ...}. */
    public static List<String> latestLines(List<PropertyStatus> statuses) {
        return statuses.stream().map(s -> String.format(Locale.ROOT, "  %s (%s): %s; %s", s.property().id(),
                s.property().name(), s.verdict().describe(), latest(s).words())).toList();
    }

    private static LatestJson latest(PropertyStatus s) {
        String model = s.model().id();
        if (s.model() == PropertyStatus.Model.FORECAST) {
            Forecast last = s.forecast();
            return last == null ? new LatestJson(model, null, null, null, false, "no forecast yet")
                    : new LatestJson(model, round(last.probability()), !ForecastWords.inSight(last) ? null
                    : round(last.timeToViolation()), last.unit(), last.novel(),
                    last.basis() == Forecast.Basis.VIOLATED ? "no forecast: the property is violated"
                            : "forecast: " + ForecastWords.probability(last) + ", " + ForecastWords.time(last));
        }
        Survival.Estimate e = s.deadline();
        if (s.model() == PropertyStatus.Model.NONE) {
            return new LatestJson(model, null, null, null, false, s.noForecastWords());
        }
        if (e == null) {
            return new LatestJson(model, null, null, s.unit(), false, "no forecast: no obligation pending");
        }
        String left = ForecastWords.fixed(e.timeLeft(), 0) + " " + s.unit() + " left";
        return e.novel() ? new LatestJson(model, null, e.timeLeft(), s.unit(), true,
                "no forecast: pending longer than any training obligation (no evidence); " + left)
                : new LatestJson(model, round(e.probability()), e.timeLeft(), s.unit(), false, "forecast: P(miss) "
                + ForecastWords.fixed(e.probability(), 2) + ", " + left);
    }

    private static double round(double x) {
        return Math.round(x * 1e4) / 1e4;
    }
}
