package dev.predmon.ros2;

import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import dev.predmon.rosbag.BagMessage;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

/**
 * Turns ROS 2 messages into monitor records by the {@link TopicRule}s of an abstraction, message after message: each
 * value a rule reaches becomes a command record and its reply, numbered by the message's index and timed by its log
 * time in seconds. It remembers what {@code changes} and {@code auto} scales need, so one mapping reads one recording
 * (or one live stream): the messages need not come from a file ({@link BagMessage#file()} may be null).
 *
 * <p>Not thread-safe.
 */
public final class TopicMapping {

    /**
     * The client port of every record: the monitor, which "calls" each topic; with a rule's key, the key after it
     * ({@code /predmon/FollowPath}).
     */
    public static final String CLIENT = "/predmon";

    private final List<TopicRule> rules;
    private final List<FieldPath> fields = new ArrayList<>();
    private final List<FieldPath> keys = new ArrayList<>();
    /** Per rule, the last word or value given for each key. */
    private final List<Map<String, String>> last = new ArrayList<>();
    /** Per rule with an {@code auto} scale: whether the topic was seen to publish percentages. */
    private final boolean[] percent;
    /** The rules for each topic and type seen, in rule order. */
    private final Map<String, int[]> byTopic = new HashMap<>();

    public TopicMapping(List<TopicRule> rules) {
        this.rules = List.copyOf(rules);
        for (TopicRule r : this.rules) {
            fields.add(FieldPath.parse(r.field()));
            keys.add(r.key() == null ? null : FieldPath.parse(r.key()));
            last.add(new HashMap<>());
        }
        this.percent = new boolean[this.rules.size()];
    }

    /** Whether some rule maps messages of this topic and type. */
    public boolean maps(String topic, String type) {
        return rulesOf(topic, type).length > 0;
    }

    /** Every rule's topic pattern, in rule order: what a live client subscribes to. */
    public List<String> topics() {
        return rules.stream().map(TopicRule::topic).distinct().toList();
    }

    /** Forgets what earlier messages said (a new recording, a new run). */
    public void reset() {
        last.forEach(Map::clear);
        java.util.Arrays.fill(percent, false);
    }

    /** Delivers the records {@code message} maps to, in order, to {@code out}. */
    public void map(BagMessage message, Consumer<LogRecord> out) {
        int[] which = rulesOf(message.topic(), message.type());
        if (which.length == 0) {
            return;
        }
        double time = message.logTimeNanos() / 1e9;
        for (int i : which) {
            TopicRule rule = rules.get(i);
            List<Object> values = fields.get(i).values(message.fields());
            List<Object> keyValues = keys.get(i) == null ? null : keys.get(i).values(message.fields());
            for (int j = 0; j < values.size(); j++) {
                Object v = values.get(j);
                String key = keyValues == null ? "" : keyValues.size() > j ? text(keyValues.get(j)) : "";
                String reply = rule.isValue() ? number(i, rule, v) : word(rule, v);
                if (reply == null) {
                    continue;
                }
                if (rule.changes() && reply.equals(last.get(i).put(key, reply))) {
                    continue;
                }
                // The key is the client's port (one connection per goal, node or logger: what tells them apart); an
                // event's word is its argument too, so that a matcher on the argument (a property's event, what says
                // an action is under way) tells a goal that starts from one that ends.
                String client = key.isEmpty() ? CLIENT : CLIENT + "/" + key;
                String arguments = rule.isValue() ? "" : reply;
                out.accept(new LogRecord(message.index(), time, "DEBUG", RecordKind.COMMAND, client, message.topic(),
                        rule.protocol(), rule.command(), arguments, ""));
                out.accept(new LogRecord(message.index(), time, "DEBUG", RecordKind.REPLY, message.topic(), client,
                        rule.protocol(), rule.command(), arguments, reply));
            }
        }
    }

    private int[] rulesOf(String topic, String type) {
        return byTopic.computeIfAbsent(topic + "\n" + type, k -> {
            List<Integer> found = new ArrayList<>();
            for (int i = 0; i < rules.size(); i++) {
                if (rules.get(i).matches(topic, type)) {
                    found.add(i);
                }
            }
            return found.stream().mapToInt(Integer::intValue).toArray();
        });
    }

    /** A value rule's reply: the number as a plain decimal, or null for no reading (NaN, not a number). */
    private String number(int i, TopicRule rule, Object v) {
        double d;
        if (v instanceof Double x) {
            d = x;
        } else if (v instanceof Long x) {
            d = x;
        } else {
            return null;
        }
        if (!Double.isFinite(d)) {
            return null;
        }
        double scaled = switch (rule.scale()) {
            case AS_IS, PERCENT -> d;
            case FRACTION -> d * 100;
            case AUTO -> {
                percent[i] |= d > 1.5;
                yield percent[i] ? d : d * 100;
            }
        };
        return BigDecimal.valueOf(scaled).stripTrailingZeros().toPlainString();
    }

    /** An event rule's reply: the value's word, or null when the rule leaves the value out. */
    private static String word(TopicRule rule, Object v) {
        if (v == null) {
            return null;
        }
        if (rule.atLeast() != null && !(v instanceof Number n && n.doubleValue() >= rule.atLeast())) {
            return null;
        }
        String s = text(v);
        return rule.names() == null ? (s.isEmpty() ? null : s) : rule.names().get(s);
    }

    /**
     * A value as record text: numbers as decimals, a list of integers (a goal's UUID) as hex, text on one line.
     */
    static String text(Object v) {
        if (v == null) {
            return "";
        }
        if (v instanceof Double d) {
            return Double.isFinite(d) ? BigDecimal.valueOf(d).stripTrailingZeros().toPlainString() : d.toString();
        }
        if (v instanceof List<?> l && l.stream().allMatch(e -> e instanceof Long)) {
            StringBuilder b = new StringBuilder(l.size() * 2);
            for (Object e : l) {
                b.append(String.format("%02x", ((Long) e) & 0xff));
            }
            return b.toString();
        }
        return v.toString().replace('\n', ' ').replace('\r', ' ').strip();
    }
}
