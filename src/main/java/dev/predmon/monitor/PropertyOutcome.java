package dev.predmon.monitor;

import dev.predmon.property.Property;
import dev.predmon.property.PropertyChecker.PropertyVerdict;
import dev.predmon.property.Verdict;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.function.DoubleFunction;

/**
 * What became of one property in a run: its verdict and its first warning. A run's outcome is the set of properties
 * it violated and warned of; every output ranks them the same way, worst first: violated, then warned, then anything
 * that is neither held nor broken (a pending obligation, no evidence, a value never read, a verdict this class does
 * not know), then held. Within a rank the abstraction's order stays.
 *
 * @param property the property
 * @param verdict  its verdict on the run
 * @param warning  its first warning in the run, or null
 * @param observed false for a property whose value the run never read (its "holds" would be a verdict on no evidence)
 */
public record PropertyOutcome(Property property, Verdict verdict, MonitorEvent.Warning warning, boolean observed) {

    /** Ranks, worst first. */
    public static final int VIOLATED = 0;
    public static final int WARNED = 1;
    public static final int OPEN = 2;
    public static final int HOLDS = 3;

    public PropertyOutcome {
        Objects.requireNonNull(property);
        Objects.requireNonNull(verdict);
    }

    /**
     * Every property of {@code run}, worst first.
     *
     * @param forecastId the id of the forecast's property, whose value {@link RunOutcome#safetyObserved} tells whether
     *                   the run read (null when there is none)
     */
    public static List<PropertyOutcome> of(RunOutcome run, String forecastId) {
        List<PropertyOutcome> all = new ArrayList<>();
        for (PropertyVerdict pv : run.properties()) {
            String id = pv.property().id();
            all.add(new PropertyOutcome(pv.property(), pv.verdict(), run.warnings().get(id),
                    !id.equals(forecastId) || run.safetyObserved() || pv.verdict() instanceof Verdict.Violated));
        }
        return worstFirst(all);
    }

    /** {@code all} sorted worst first; stable, so the abstraction's order stays within a rank. */
    public static List<PropertyOutcome> worstFirst(List<PropertyOutcome> all) {
        List<PropertyOutcome> sorted = new ArrayList<>(all);
        sorted.sort(Comparator.comparingInt(PropertyOutcome::rank));
        return List.copyOf(sorted);
    }

    /**
     * Where a verdict ranks, a warning aside: {@link #VIOLATED}, {@link #HOLDS}, or {@link #OPEN} for any other
     * verdict (pending, no evidence, or one added later: never as good as holds).
     */
    public static int rank(String verdictId) {
        return switch (verdictId) {
            case "violated" -> VIOLATED;
            case "holds" -> HOLDS;
            default -> OPEN;
        };
    }

    /** Where this property ranks: violated, warned, open, holds. */
    public int rank() {
        int r = observed ? rank(verdict.id()) : OPEN;
        return r == VIOLATED ? VIOLATED : warning != null ? WARNED : r;
    }

    /** The property's id. */
    public String id() {
        return property.id();
    }

    /** Whether a warning of it came before its violation (the violation was predicted). */
    public boolean warnedBefore() {
        return verdict instanceof Verdict.Violated v && warning != null && warning.line() < v.line();
    }

    /** Violation time minus warning time, for a violation warned of before it. */
    public Optional<Double> lead() {
        return warnedBefore() ? Optional.of(((Verdict.Violated) verdict).time() - warning.time()) : Optional.empty();
    }

    /**
     * Its state in one word, as outputs name it: {@code violated}, {@code warned}, {@code not observed}, the verdict's
     * own id for another open verdict ({@code pending}, ...), {@code holds}.
     */
    public String state() {
        return switch (rank()) {
            case VIOLATED -> "violated";
            case WARNED -> "warned";
            case HOLDS -> "holds";
            default -> observed ? verdict.id().replace('-', ' ') : "not observed";
        };
    }

    /**
     * The property's outcome in an operator's words, its id first: {@code grasp-in-time VIOLATED at line 7568 with no
     * warning before it: 8 closeHand commands since line 6168, none answered by hasGrasped 1|27503}.
     *
     * @param span a duration in the log's unit, in words ({@code 30.0 s}, {@code 12 ticks})
     */
    public String words(DoubleFunction<String> span) {
        if (verdict instanceof Verdict.Violated v) {
            return id() + " VIOLATED at line " + v.line()
                    + (warnedBefore() ? ", warned " + span.apply(v.time() - warning.time()) + " before (line "
                    + warning.line() + ")" : " with no warning before it") + ": " + v.what();
        }
        if (warning != null) {
            return id() + " warned at line " + warning.line() + ", not violated";
        }
        if (observed && verdict instanceof Verdict.NoEvidence n) {
            return id() + " " + n.describe(); // what never occurred
        }
        return id() + " " + state();
    }

    /**
     * A run's outcome in one clause, worst first: each violated and warned property in {@link #words}' terms (without
     * what violated it, which the violation's own line says), any other open one with its state, then those that
     * hold, by id: {@code grasp-in-time VIOLATED with no warning before it; battery, no-abort hold}. A run with no
     * property says whether it was warned.
     */
    public static String sentence(List<PropertyOutcome> worstFirst, boolean warned, DoubleFunction<String> span) {
        if (worstFirst.isEmpty()) {
            return warned ? "warning raised" : "no warning";
        }
        List<String> parts = new ArrayList<>();
        List<String> hold = new ArrayList<>();
        boolean alarm = false;
        for (PropertyOutcome p : worstFirst) {
            switch (p.rank()) {
                case VIOLATED -> {
                    alarm = true;
                    parts.add(p.id() + " VIOLATED" + p.lead().map(l -> ", warned " + span.apply(l) + " before")
                            .orElse(" with no warning before it"));
                }
                case WARNED -> {
                    alarm = true;
                    parts.add(p.id() + " warned");
                }
                case HOLDS -> hold.add(p.id());
                default -> parts.add(p.id() + " " + p.state());
            }
        }
        if (!alarm) {
            parts.add(0, "no warning");
        }
        if (!hold.isEmpty()) {
            parts.add(String.join(", ", hold) + (hold.size() == 1 ? " holds" : " hold"));
        }
        return String.join("; ", parts);
    }

    /**
     * Several runs' outcomes as one, worst first: each property's worst outcome over the runs (its earliest at that
     * rank), so that a log of several runs says every property any run violated or warned.
     */
    public static List<PropertyOutcome> worstOver(List<List<PropertyOutcome>> runs) {
        java.util.Map<String, PropertyOutcome> worst = new java.util.LinkedHashMap<>();
        for (List<PropertyOutcome> run : runs) {
            for (PropertyOutcome p : run) {
                worst.merge(p.id(), p, (a, b) -> b.rank() < a.rank() ? b : a);
            }
        }
        return worstFirst(new ArrayList<>(worst.values()));
    }

    /** The worst property of {@code worstFirst}, when one is violated or warned. */
    public static Optional<PropertyOutcome> alarm(List<PropertyOutcome> worstFirst) {
        return worstFirst.stream().filter(p -> p.rank() <= WARNED).findFirst();
    }
}
