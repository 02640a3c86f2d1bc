package dev.predmon.event;

import dev.predmon.property.PropertyChecker.PropertyVerdict;
import dev.predmon.property.Verdict;

import java.util.List;
import java.util.Locale;

/**
 * A property's verdict on a run as JSON: {@code property} its id, {@code name}, {@code kind}, {@code verdict}
 * ({@code holds}, {@code pending} or {@code violated}); a violation's {@code line}, {@code time}, {@code value} (of a
 * bound) and {@code what}; a pending response's trigger {@code line}, {@code since}, {@code deadline} and
 * {@code unit} ({@code ticks}, {@code seconds} or {@code occurrences}).
 */
public record PropertyJson(String property, String name, String kind, String verdict, Long line, Double time, Double value,
                    String what, Double since, Double deadline, String unit) {

    public static PropertyJson of(PropertyVerdict pv) {
        Verdict v = pv.verdict();
        String id = pv.property().id();
        String name = pv.property().name();
        String kind = pv.property().kind();
        if (v instanceof Verdict.Violated x) {
            return new PropertyJson(id, name, kind, v.id(), x.line(), x.time(), x.value(), x.what(), null, null, null);
        }
        if (v instanceof Verdict.Pending p) {
            return new PropertyJson(id, name, kind, v.id(), p.line(), null, null, null, p.since(), p.deadline(),
                    p.unit().key);
        }
        return new PropertyJson(id, name, kind, v.id(), null, null, null, null, null, null, null);
    }

    public static List<PropertyJson> of(List<PropertyVerdict> verdicts) {
        return verdicts.stream().map(PropertyJson::of).toList();
    }

    /** One line per property for the end summary: {@code no-abort (navigation never aborts): holds}. */
    public static List<String> lines(List<PropertyVerdict> verdicts) {
        return verdicts.stream().map(pv -> String.format(Locale.ROOT, "  %s (%s): %s", pv.property().id(),
                pv.property().name(), pv.verdict().describe())).toList();
    }
}
