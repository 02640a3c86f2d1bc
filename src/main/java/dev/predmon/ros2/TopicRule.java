package dev.predmon.ros2;

import dev.predmon.parse.Glob;

import java.util.Map;

/**
 * One rule of an abstraction file's {@code ros2} section: which messages of a topic become which records.
 *
 * <p>Each value the {@code field} path reaches in a message of {@code topic} (and {@code type}, when given) becomes a
 * command record and its reply, as the YARP monitor prints a call: the command on {@code protocol}/{@code command}
 * with the {@code key} as its argument, the reply carrying the value. A value rule ({@code scale} not null) gives the
 * reply a number; an event rule gives it a word ({@code names} turn values into words and leave out the others).
 *
 * @param topic    the topic, {@code *} matching any characters ({@code /*}{@code /_action/status})
 * @param type     the message type ({@code sensor_msgs/msg/BatteryState}; {@code pkg/Type} is the same), or null
 * @param field    the field path ({@code percentage}, {@code status_list[].status}); one {@code []} at most, for
 *                 each element of a list
 * @param key      what tells the things a message speaks of apart ({@code status_list[].goal_info.goal_id.uuid}),
 *                 the argument of the records; null for none. A {@code []} in it is the field's
 * @param protocol the records' protocol
 * @param command  the records' command
 * @param scale    for a value rule, how the number is read; null for an event rule
 * @param names    for an event rule, the word for each value (values not named give no record), or null: every value
 *                 as it is
 * @param atLeast  for an event rule, only numeric values at least this give a record, or null
 * @param changes  only a value that differs from the key's previous one gives a record (the first one does)
 */
public record TopicRule(String topic, String type, String field, String key, String protocol, String command,
                        Scale scale, Map<String, String> names, Double atLeast, boolean changes) {

    public TopicRule {
        names = names == null ? null : Map.copyOf(names);
    }

    /** How a value rule reads its number. */
    public enum Scale {
        /** As it is. */
        AS_IS,
        /** A fraction (0..1) made a percentage: times 100. */
        FRACTION,
        /** A percentage already (0..100). */
        PERCENT,
        /**
         * A fraction until a reading above 1.5 shows that the topic publishes percentages; from then on, as it is.
         * NaN is no reading.
         */
        AUTO
    }

    /** Whether this is a value rule. */
    public boolean isValue() {
        return scale != null;
    }

    /** Whether a message of {@code topic} and {@code type} is this rule's. */
    public boolean matches(String messageTopic, String messageType) {
        return glob(topic, messageTopic) && (type == null || sameType(type, messageType));
    }

    /** {@code pkg/msg/Type} and {@code pkg/Type} name one type. */
    static boolean sameType(String a, String b) {
        return b != null && a.replace("/msg/", "/").equals(b.replace("/msg/", "/"));
    }

    static boolean glob(String pattern, String text) {
        if (text == null) {
            return false;
        }
        int star = pattern.indexOf('*');
        if (star < 0) {
            return pattern.equals(text);
        }
        return Glob.matches(pattern, text);
    }
}
