package dev.predmon.abstraction;

import dev.predmon.property.Property;
import dev.predmon.ros2.TopicRule;

import java.util.List;
import java.util.Map;

/**
 * What an {@link Abstraction} is made of: the content of an abstraction file, validated and with its defaults
 * filled in. {@code dev.predmon.abstraction.file} reads, checks and writes the files; this is what they mean.
 *
 * @param name      identifies the abstraction in models/index.json and reports
 * @param locations location name, as in arguments and client ports, to its abbreviation in symbols
 * @param drop      filters for records outside the skill-component interface, in file order
 * @param rules     how each message kind becomes symbols, in file order (the first that matches is used)
 * @param properties the safety properties the monitor checks, in file order (possibly none)
 * @param confirm   pairs a faulty model must still match after the last nominal model is eliminated before the
 *                  warning
 * @param runs      where one run ends and the next begins in a log that holds several
 * @param topics    how the messages of ROS 2 recordings become records (the file's {@code ros2} section), in file
 *                  order; empty when the file has none
 */
public record Definition(String name, Map<String, String> locations, List<Drop> drop, List<Rule> rules,
                         List<Property> properties, int confirm, RunRule runs, List<TopicRule> topics) {

    /** The placeholder for a location's abbreviation in input and reply symbols. */
    public static final String LOC = "{loc}";

    public Definition {
        locations = Map.copyOf(locations);
        drop = List.copyOf(drop);
        rules = List.copyOf(rules);
        properties = List.copyOf(properties);
        topics = List.copyOf(topics);
    }

    /** A definition for YARP logs only: no {@code ros2} section. */
    public Definition(String name, Map<String, String> locations, List<Drop> drop, List<Rule> rules,
                      List<Property> properties, int confirm, RunRule runs) {
        this(name, locations, drop, rules, properties, confirm, runs, List.of());
    }

    /** A record matching every non-null key is dropped; {@code *} in a value matches any characters. */
    public record Drop(String kind, String from, String to, String protocol, String command) {
    }

    /**
     * One message kind of the interface; {@code input} and reply symbols may contain {@link #LOC}.
     *
     * @param client     a client port pattern ({@code *} for any characters) the rule is restricted to, or null
     * @param continuous the replies are bands of a continuous quantity (between two readings it crosses every band
     *                   in between)
     * @param carry      the query's Mealy input carries its previous answer
     * @param hysteresis how far a reading may leave the previous band and stay in it, or null
     */
    public record Rule(String protocol, String command, String client, String input, boolean continuous,
                       boolean carry, Double hysteresis, List<Reply> replies) {

        /** This rule with {@code hysteresis} {@code h}. */
        Rule withHysteresis(double h) {
            return new Rule(protocol, command, client, input, continuous, carry, h, replies);
        }
    }

    /** One reply symbol, given by exactly one of {@code any}, {@code values} (non-null) or {@code range} (non-null). */
    public record Reply(boolean any, List<String> values, Band range, String symbol) {
    }
}
