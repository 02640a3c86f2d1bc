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
                    throw new IllegalArgumentException("'" + entry(m, key, e.getKey()) + "': not " + what
                            + " of the abstraction");
                }
                String wrong = problem.apply(p, e.getValue());
                if (wrong != null) {
                    throw new IllegalArgumentException("'" + entry(m, key, e.getKey()) + "': " + wrong);
                }
            }
            if (!required) {
                return;
            }
            for (Property p : a.properties()) {
                if (covers.test(p, a) && !have.containsKey(p.id())) {
                    throw new IllegalArgumentException("'" + part(m, key) + "' has no entry for '" + p.id() + "', "
                            + what
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
     * Checks every per-property part of {@code m} against {@code abstraction}: in a file of format 2, first that its
     * first floor is the abstraction's, and that floor as any other bound.
     *
     * @throws IllegalArgumentException what is wrong, naming the part and the entry as the file has them
     */
    public static void check(ForecastModel m, Abstraction abstraction) {
        if (m.format() >= ForecastModel.FORMAT) {
            firstFloor(m, abstraction);
        }
        for (Part<?> part : PARTS) {
            part.check(m, abstraction);
        }
    }

    /** The first floor of a file that names it is the abstraction's, and its limit the property's floor. */
    private static void firstFloor(ForecastModel m, Abstraction abstraction) {
        Bound safety = abstraction.safety().orElse(null);
        if (safety == null && m.first() != null) {
            throw new IllegalArgumentException("'properties." + m.first() + "': forecast on its floor as the first "
                    + "floor, but the abstraction has no bound with a floor");
        }
        if (safety == null) {
            return;
        }
        if (m.first() == null) {
            throw new IllegalArgumentException("'properties' has no entry for '" + safety.id() + "', the first floor of"
                    + " the abstraction the models were learned with (the first bound with a floor)");
        }
        if (!m.first().equals(safety.id())) {
            throw new IllegalArgumentException("'properties." + m.first() + "': the first bound forecast on its floor, "
                    + "but the abstraction's first floor is '" + safety.id() + "'");
        }
        if (Double.compare(m.limit(), safety.floor()) != 0) {
            throw new IllegalArgumentException("'properties." + m.first() + ".limit': " + shown(m.limit())
                    + " is not the property's floor (" + shown(safety.floor()) + ")");
        }
    }

    /** Where a part is in the file {@code m} was read from: under {@code properties} from format 2 on. */
    private static String part(ForecastModel m, String key) {
        return m.format() >= ForecastModel.FORMAT ? "properties" : key;
    }

    /** Where the entry of property {@code id} of a part is in the file {@code m} was read from. */
    private static String entry(ForecastModel m, String key, String id) {
        return part(m, key) + "." + id;
    }

    /**
     * {@code m} with its properties named by {@code abstraction}, the one its models were learned with: the first
     * floor is the abstraction's (a model of format 1 does not say), the properties in its order, and each scorecard
     * of a deadline that a model of format 1 keeps beside the first floor's given to its property (by its name).
     */
    public static ForecastModel named(ForecastModel m, Abstraction abstraction) {
        String first = m.first() != null || Double.isNaN(m.limit()) ? m.first()
                : abstraction.safety().map(Bound::id).orElse(null);
        List<String> order = abstraction.properties().stream().map(Property::id).toList();
        List<Scorecard> own = new ArrayList<>();
        Map<String, List<Scorecard>> deadlines = new TreeMap<>(m.deadlineCards());
        for (Scorecard c : m.scorecards()) {
            Response r = Scorecard.OBLIGATIONS.equals(c.counted()) ? response(abstraction, c.property()) : null;
            if (r == null) {
                own.add(c);
            } else {
                deadlines.merge(r.id(), List.of(c), (a, b) -> {
                    List<Scorecard> both = new ArrayList<>(a);
                    both.addAll(b);
                    return both;
                });
            }
        }
        return m.withScorecards(own).withDeadlineScorecards(deadlines).named(first, order);
    }

    private static Response response(Abstraction abstraction, String name) {
        for (Property p : abstraction.properties()) {
            if (p instanceof Response r && r.name().equals(name)) {
                return r;
            }
        }
        return null;
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
     * {@code m}, learned with {@code abstraction}, as {@code forecast.json} holds it: named ({@link #named}), with an
     * entry for every bounded response (an empty one, no duration, for a property no training run opened an
     * obligation of, which gets no deadline forecast), each property's forecast its own only, and without a first
     * floor nothing at the top level ({@link ForecastModel#of}). What learn keeps is what watch reads.
     */
    public static ForecastModel covering(ForecastModel m, Abstraction abstraction) {
        Map<String, Survival> all = new TreeMap<>(m.obligations());
        for (Property p : abstraction.properties()) {
            if (p instanceof Response) {
                all.putIfAbsent(p.id(), new Survival(new double[0], new double[0]));
            }
        }
        ForecastModel named = named(m.withObligations(all), abstraction);
        return ForecastModel.of(m.unit(), m.runs(), named.properties());
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
