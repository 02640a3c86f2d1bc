package dev.predmon.forecast;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.property.Absence;
import dev.predmon.property.Bound;
import dev.predmon.property.Deadline;
import dev.predmon.property.Precedence;
import dev.predmon.property.Property;
import dev.predmon.property.Response;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.BiFunction;
import java.util.function.BiPredicate;
import java.util.function.Function;

/**
 * The per-property parts of a forecast ({@code forecast.json}'s {@code obligations}, {@code bounds} and
 * {@code events}), which
 * properties of the abstraction each covers, and the check of a forecast read from a file against the abstraction
 * its models were learned with. {@code learn} writes an entry for every property a part covers, an empty one when no
 * training run gave it anything (a bounded response no run triggered), so that a part or an entry deleted from the
 * file is told from "nothing learned": a forecast without the part a property needs would silently drop that
 * property's warnings.
 *
 * <p>A new per-property part is one more {@link Part} in {@link #PARTS}: its key, the properties it covers, whether
 * every one of them must have an entry (false for an optional part, which an older file lacks), and what makes one
 * entry wrong.
 */
public final class PropertyParts {

    /**
     * One per-property part of the file.
     *
     * @param key      its key in the file
     * @param what     the properties it covers, in words ({@code a bounded response})
     * @param covers   whether property {@code p} of abstraction {@code a} gets an entry
     * @param required whether every property it covers must have one
     * @param entries  the part's entries in a forecast, by property id
     * @param problem  what is wrong with the entry of a property, or null when nothing is
     * @param <T>      an entry
     */
    record Part<T>(String key, String what, BiPredicate<Property, Abstraction> covers, boolean required,
                   Function<ForecastModel, Map<String, T>> entries, BiFunction<Property, T, String> problem) {

        void check(ForecastModel m, Abstraction a) {
            Map<String, T> have = entries.apply(m);
            Map<String, Property> byId = new TreeMap<>();
            a.properties().forEach(p -> byId.put(p.id(), p));
            for (Map.Entry<String, T> e : new TreeMap<>(have).entrySet()) {
                Property p = byId.get(e.getKey());
                if (p == null || !covers.test(p, a)) {
                    throw new IllegalArgumentException("'" + key + "/" + e.getKey() + "': not " + what
                            + " of the abstraction");
                }
                String wrong = problem.apply(p, e.getValue());
                if (wrong != null) {
                    throw new IllegalArgumentException("'" + key + "/" + e.getKey() + "': " + wrong);
                }
            }
            if (!required) {
                return;
            }
            for (Property p : a.properties()) {
                if (covers.test(p, a) && !have.containsKey(p.id())) {
                    throw new IllegalArgumentException("'" + key + "' has no entry for '" + p.id() + "', " + what
                            + " of the abstraction the models were learned with (learn writes one for each, empty when "
                            + "training gave it nothing)");
                }
            }
        }
    }

    /** The parts, in the order they are checked. */
    static final List<Part<?>> PARTS = List.of(
            new Part<>("obligations", "a bounded response", (p, a) -> p instanceof Response, true,
                    ForecastModel::obligations, (p, s) -> obligationProblem((Response) p, s)),
            new Part<>("bounds", "a bound with a floor or a ceiling other than the safety property",
                    (p, a) -> p instanceof Bound b && others(a).contains(b), true, ForecastModel::bounds,
                    (p, b) -> boundProblem((Bound) p, b)),
            new Part<>("events", "an absence or a precedence", (p, a) -> p instanceof Absence || p instanceof Precedence,
                    false, ForecastModel::events, (p, e) -> e.forecasts() && Double.compare(e.model().limit(),
                    EventModel.HOLDS) != 0 ? "limit " + shown(e.model().limit()) + " is not the indicator's floor ("
                    + EventModel.HOLDS + ")" : null));

    private PropertyParts() {
    }

    /**
     * Checks every per-property part of {@code m} against {@code abstraction}.
     *
     * @throws IllegalArgumentException what is wrong, naming the part and the entry
     */
    public static void check(ForecastModel m, Abstraction abstraction) {
        for (Part<?> part : PARTS) {
            part.check(m, abstraction);
        }
    }

    /**
     * The bound properties that get a value forecast of their own: every one but the abstraction's safety property
     * (which the forecast itself is of) that has a floor or a ceiling.
     */
    public static List<Bound> others(Abstraction abstraction) {
        String safety = abstraction.safety().map(Bound::id).orElse(null);
        List<Bound> out = new ArrayList<>();
        for (Property p : abstraction.properties()) {
            if (p instanceof Bound b && !b.id().equals(safety)
                    && (b.hasFloor() || b.ceiling() != Double.POSITIVE_INFINITY)) {
                out.add(b);
            }
        }
        return out;
    }

    /**
     * {@code m} with an entry under {@code obligations} for every bounded response of {@code abstraction}: an empty
     * one (no duration) for a property no training run opened an obligation of, which gets no deadline forecast.
     */
    public static ForecastModel covering(ForecastModel m, Abstraction abstraction) {
        Map<String, Survival> all = new TreeMap<>(m.obligations());
        for (Property p : abstraction.properties()) {
            if (p instanceof Response) {
                all.putIfAbsent(p.id(), new Survival(new double[0], new double[0]));
            }
        }
        return m.withObligations(all);
    }

    /**
     * A training obligation discharged after more than its deadline would have been a violation, never a discharge
     * (a response on the record past the deadline comes too late). A censored one may have been let go later than the
     * deadline, at the record that passed it: for a deadline in ticks or occurrences one tick or occurrence past it at
     * most, for one in seconds as late as the next record came.
     */
    private static String obligationProblem(Response r, Survival s) {
        double amount = r.within().amount();
        for (double d : s.discharged()) {
            if (d > amount + 1e-9 * Math.max(1, amount)) {
                return String.format(Locale.ROOT, "an obligation discharged after %s %s, past the deadline of %s: "
                        + "training records no such discharge", shown(d), r.within().unit().key, r.within().describe());
            }
        }
        if (r.within().unit() != Deadline.Unit.SECONDS) {
            for (double c : s.censored()) {
                if (c > Math.floor(amount) + 1) {
                    return String.format(Locale.ROOT, "an obligation let go after %s %s, more than one past the "
                            + "deadline of %s, where training lets go of it", shown(c), r.within().unit().key,
                            r.within().describe());
                }
            }
        }
        return null;
    }

    /** The side must be one the property has, and the limit that side's bound (mirrored for a ceiling). */
    private static String boundProblem(Bound b, BoundModel m) {
        if (BoundModel.FLOOR.equals(m.side()) && !b.hasFloor()) {
            return "side 'floor', but '" + b.id() + "' has no floor";
        }
        if (BoundModel.CEILING.equals(m.side()) && b.ceiling() == Double.POSITIVE_INFINITY) {
            return "side 'ceiling', but '" + b.id() + "' has no ceiling";
        }
        double limit = BoundModel.limit(b, m.side());
        if (Double.compare(m.model().limit(), limit) != 0) {
            return "limit " + shown(m.model().limit()) + " is not the property's " + m.side() + " (" + (m.mirrored()
                    ? "written " + shown(limit) + ", the ceiling " + shown(b.ceiling()) + " mirrored" : shown(limit))
                    + ")";
        }
        return null;
    }

    private static String shown(double v) {
        return Double.isNaN(v) ? "none" : Double.toString(v);
    }
}
