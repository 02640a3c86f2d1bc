package dev.predmon.abstraction.file;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.annotation.JsonProperty;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.Band;
import dev.predmon.abstraction.Definition;
import dev.predmon.abstraction.RunRule;
import dev.predmon.property.Bound;
import dev.predmon.property.Property;
import dev.predmon.property.Scope;
import dev.predmon.property.UnderWay;
import dev.predmon.property.ValueReader;
import dev.predmon.ros2.TopicRule;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * The abstraction file as written, bound by {@link SpecBinder} before validation. Absent keys are {@code null};
 * {@link AbstractionValidator} says which are required. Written back by {@link SpecWriter} (without nulls, keys
 * sorted) it is the canonical form that {@link Abstraction#fingerprint()} hashes.
 *
 * <p>The Jackson annotations say how Jackson's data binding, which read and wrote these records before, named and
 * left out keys; the binder and writer do the same by hand (no {@code ObjectMapper} at start-up), and the tests
 * hold them to data binding's results through these annotations.
 *
 * @param name        identifies the abstraction in models/index.json and reports
 * @param description free text for readers, e.g. how band boundaries are assigned
 * @param drop        filters for records outside the skill-component interface
 * @param locations   location name, as in arguments and client ports, to its abbreviation in symbols
 * @param rules       how each (protocol, command) becomes an input symbol and its replies output symbols
 * @param safety      the older form of one bound property, optional (files now give {@code properties})
 * @param warning     how cautiously the predictive monitor warns on this system, optional
 * @param runs        where one run ends and the next begins in a log that holds several, optional
 */
@JsonInclude(JsonInclude.Include.NON_NULL)
record AbstractionSpec(String name, String description, List<DropSpec> drop, Map<String, String> locations,
                       List<RuleSpec> rules, SafetySpec safety, WarningSpec warning, RunsSpec runs) {

    /** This spec without the safety property's advice (see {@link SafetySpec#withoutAdvice()}). */
    AbstractionSpec withoutAdvice() {
        return new AbstractionSpec(name, description, drop, locations, rules,
                safety == null ? null : safety.withoutAdvice(), warning, runs);
    }

    /** Whether the safety property gives advice (an action, or what says it is under way). */
    boolean hasAdvice() {
        return safety != null && (safety.action() != null || safety.underWay() != null);
    }

    /** This spec with {@code safety} in place of its own. */
    AbstractionSpec withSafety(SafetySpec safety) {
        return new AbstractionSpec(name, description, drop, locations, rules, safety, warning, runs);
    }

    /**
     * The one bound property of the older {@code safety} object, with the id {@value #SAFETY_ID}.
     *
     * @param advice the property whose action and under-way messages are taken where the spec gives none, or null
     */
    Bound safetyProperty(Bound advice) {
        String action = safety.action() != null || advice == null ? safety.action() : advice.action();
        List<UnderWay> underWay = safety.underWay() != null
                ? safety.underWay().stream().map(UnderWaySpec::underWay).toList()
                : advice == null ? List.of() : advice.underWay();
        return new Bound(SAFETY_ID, safety.name(), action, Scope.GLOBAL, new ValueReader(safety.protocol(),
                safety.command(), safety.from() == null ? "" : safety.from(), safety.to() == null ? "" : safety.to()),
                safety.below(), Double.POSITIVE_INFINITY, underWay);
    }

    /** The id of the property an older file's {@code safety} object defines. */
    static final String SAFETY_ID = "safety";

    /**
     * What this validated spec defines, with the defaults of absent keys.
     *
     * @param properties the file's safety properties
     */
    Definition definition(List<Property> properties) {
        return definition(properties, List.of());
    }

    /**
     * What this validated spec defines, with the defaults of absent keys.
     *
     * @param properties the file's safety properties
     * @param topics     the rules of its {@code ros2} section
     */
    Definition definition(List<Property> properties, List<TopicRule> topics) {
        List<Definition.Drop> drops = new ArrayList<>();
        for (DropSpec d : drop == null ? List.<DropSpec>of() : drop) {
            drops.add(new Definition.Drop(d.kind(), d.from(), d.to(), d.protocol(), d.command()));
        }
        List<Definition.Rule> compiled = new ArrayList<>();
        for (RuleSpec r : rules) {
            List<Definition.Reply> replies = new ArrayList<>();
            for (ReplySpec p : r.replies()) {
                replies.add(new Definition.Reply(p.any() != null, p.values(),
                        p.range() == null ? null : p.range().band(), p.symbol()));
            }
            compiled.add(new Definition.Rule(r.protocol(), r.command(), r.client(), r.input(),
                    Boolean.TRUE.equals(r.continuous()), Boolean.TRUE.equals(r.carry()), r.hysteresis(), replies));
        }
        RunRule runRule = runs == null ? RunRule.DEFAULT : new RunRule(runs.tickRestart() == null || runs.tickRestart(),
                runs.silence() == null ? RunRule.DEFAULT_SILENCE : runs.silence());
        int confirm = warning == null || warning.confirm() == null ? 0 : warning.confirm();
        return new Definition(name, locations == null ? Map.of() : locations, drops, compiled, properties, confirm,
                runRule, topics);
    }

    /**
     * A log holds one run after another (a robot's day): {@code tickRestart} (default true) starts a run where the
     * tree's tick counter starts again (a {@code Tick} record whose number is not above the previous one);
     * {@code silence} (seconds, default {@value RunRule#DEFAULT_SILENCE}; 0 turns it off) starts one after that
     * long without any record, for logs with time stamps and no ticks.
     */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    record RunsSpec(Boolean tickRestart, Double silence, String description) {
    }

    /**
     * {@code confirm}: pairs a faulty model must still match after the last nominal model is eliminated before the
     * warning (absent: 0, the thesis's Algorithm 8). {@code description} says why, for readers.
     */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    record WarningSpec(Integer confirm, String description) {
    }

    /**
     * A record matching every given key is dropped; at least one key is required. {@code description} says why,
     * for readers.
     */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    record DropSpec(String kind, String from, String to, String protocol, String command, String description) {
    }

    /**
     * One message kind of the interface. {@code input} and reply symbols may contain {@code {loc}}.
     * {@code continuous: true} says the replies are bands of a continuous quantity (a battery level): between two
     * readings it crosses every band in between, so the trace must not depend on how often it is read.
     * {@code hysteresis: h} (continuous rules only) keeps a reading within {@code h} of the previous band in that
     * band, so a noisy sensor hovering at a boundary does not flip bands, see {@link Abstraction#settle}.
     * {@code carry: true} makes the query's Mealy input carry its previous answer
     * ({@code level_i_after_o_level_medium_six}, see {@code dev.predmon.mealy.CarryEncoder}).
     * {@code client}, a port pattern ({@code *} for any characters), restricts the rule to messages whose client
     * port matches (a command's {@code From}, a reply's {@code To}): one component method called by two skills
     * (a condition polling {@code hasGrasped} every tick, an action calling it while it grasps) is then two
     * messages of the interface. The first rule that matches a message is used.
     */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    record RuleSpec(String protocol, String command, String client, String input, String description, Boolean continuous,
                    Boolean carry, Double hysteresis, List<ReplySpec> replies) {
    }

    /** One reply symbol, given by exactly one of {@code any}, {@code equals} or {@code range}. */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    record ReplySpec(Boolean any, @JsonProperty("equals") List<String> values, RangeSpec range, String symbol) {
    }

    /** A numeric interval; each end is open ({@code above}/{@code below}), closed or absent (unbounded). */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    record RangeSpec(Double above, Double atLeast, Double below, Double atMost) {

        /** The interval, an absent end unbounded. */
        Band band() {
            double lo = above != null ? above : atLeast != null ? atLeast : Double.NEGATIVE_INFINITY;
            double hi = below != null ? below : atMost != null ? atMost : Double.POSITIVE_INFINITY;
            return new Band(lo, atLeast != null, hi, atMost != null);
        }
    }

    /**
     * The older form of one {@link Bound} property (a floor, {@code below}); {@code from}, {@code to}, {@code action}
     * (what an operator should do when the property is predicted to fail or fails, e.g. {@code send the robot to the
     * charging station}) and {@code underWay} (the messages that say the robot already does it) are optional.
     */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    record SafetySpec(String name, String protocol, String command, String from, String to, Double below,
                      String action, List<UnderWaySpec> underWay) {

        /** This property without its advice: what the fingerprint hashes (advice does not change a trace). */
        SafetySpec withoutAdvice() {
            return new SafetySpec(name, protocol, command, from, to, below, null, null);
        }
    }

    /**
     * A message that says the action is under way (see {@link UnderWay}): {@code skill} alone, or {@code command}
     * with an optional {@code protocol} and {@code argument}.
     */
    @JsonInclude(JsonInclude.Include.NON_NULL)
    record UnderWaySpec(String skill, String protocol, String command, String argument) {

        UnderWay underWay() {
            return new UnderWay(skill, protocol, command, argument);
        }
    }
}
