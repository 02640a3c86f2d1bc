package dev.predmon.rosbridge;

import dev.predmon.monitor.MonitorEvent;
import dev.predmon.parse.LogFormat;
import dev.predmon.parse.RecordSink;
import dev.predmon.parse.RecordSource;
import dev.predmon.ros2.TopicMapping;
import dev.predmon.ros2.TopicRule;
import dev.predmon.rosbag.BagMessage;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * A live robot as an input format: the messages a {@link RosbridgeClient} receives, mapped by the abstraction's
 * {@link TopicRule}s exactly as a recording's, so that the monitor above gives the same warnings and verdicts. The
 * path a log is followed at only names it. When the connection is made again after a drop, the records that follow
 * begin a new run ({@link RecordSink#restarted}): nothing is judged across the gap.
 */
public final class RosbridgeFormat implements LogFormat {

    private final List<TopicRule> rules;
    private final RosbridgeClient client;

    public RosbridgeFormat(List<TopicRule> rules, RosbridgeClient client) {
        this.rules = List.copyOf(rules);
        this.client = client;
    }

    /** What to subscribe to for {@code rules}: each topic named (a pattern cannot be subscribed to) and its type. */
    public static List<RosbridgeClient.Subscription> subscriptions(List<TopicRule> rules) {
        List<RosbridgeClient.Subscription> out = new ArrayList<>();
        for (TopicRule r : rules) {
            if (r.topic().contains("*") || out.stream().anyMatch(s -> s.topic().equals(r.topic()))) {
                continue;
            }
            out.add(new RosbridgeClient.Subscription(r.topic(), r.type() == null ? null
                    : r.type().contains("/msg/") ? r.type() : r.type().replaceFirst("/", "/msg/")));
        }
        return out;
    }

    /** The rules' topic patterns, which rosbridge cannot subscribe to. */
    public static List<String> patterns(List<TopicRule> rules) {
        return rules.stream().map(TopicRule::topic).filter(t -> t.contains("*")).distinct().toList();
    }

    @Override
    public RecordSource follow(Path log, RecordSink sink, Duration quiet, Duration release) {
        return new Live(sink);
    }

    @Override
    public RecordSource read(Path file, RecordSink sink) {
        throw new UnsupportedOperationException("a live robot is followed, never read to its end");
    }

    @Override
    public String toString() {
        return "ROS 2 topics through rosbridge at " + client.uri();
    }

    private final class Live implements RecordSource {

        private final RecordSink sink;
        private final TopicMapping mapping = new TopicMapping(rules);
        private long messages;

        Live(RecordSink sink) {
            this.sink = sink;
        }

        @Override
        public boolean poll() {
            boolean any = false;
            if (client.takeReconnected()) {
                mapping.reset();
                sink.restarted(MonitorEvent.Restarted.RECONNECTED);
                any = true;
            }
            for (BagMessage m = client.next(); m != null; m = client.next()) {
                messages++;
                mapping.map(m, sink::record);
                any = true;
            }
            return any;
        }

        @Override
        public void drain() {
            poll();
        }

        @Override
        public long lines() {
            return messages;
        }

        @Override
        public Optional<String> takeNotice() {
            List<String> n = client.takeNotices();
            return n.isEmpty() ? Optional.empty() : Optional.of(String.join("; ", n));
        }

        @Override
        public void close() throws IOException {
            // the client is the command's to close
        }
    }
}
