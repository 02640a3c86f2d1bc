package dev.predmon.ros2;

import dev.predmon.parse.LogFormat;
import dev.predmon.parse.ParseProblem;
import dev.predmon.parse.RecordSink;
import dev.predmon.parse.RecordSource;
import dev.predmon.rosbag.BagMessage;
import dev.predmon.rosbag.BagSink;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

/**
 * The input format of an abstraction: a ROS 2 recording, recognised by its content, is read by {@link BagInput} and
 * mapped by the abstraction's {@link TopicRule}s; anything else is a YARP monitor log ({@link LogFormat#yarp()}).
 */
public final class Ros2Format implements LogFormat {

    private final List<TopicRule> rules;
    private final BagInput input;

    public Ros2Format(List<TopicRule> rules, BagInput input) {
        this.rules = List.copyOf(rules);
        this.input = input;
    }

    @Override
    public RecordSource follow(Path log, RecordSink sink, Duration quiet, Duration release) {
        if (isBag(log)) {
            return new BagSource(log, sink, true);
        }
        return LogFormat.yarp().follow(log, sink, quiet, release);
    }

    @Override
    public RecordSource read(Path file, RecordSink sink) {
        if (isBag(file)) {
            return new BagSource(file, sink, false);
        }
        return LogFormat.yarp().read(file, sink);
    }

    /**
     * Whether {@code path} is read as a recording: a folder (never a YARP log; its data files may not be written yet),
     * a file by its content, or, not written yet, by its name.
     */
    private boolean isBag(Path path) {
        if (Files.isDirectory(path)) {
            return true;
        }
        if (Files.exists(path)) {
            return input.looksLikeBag(path);
        }
        String name = path.getFileName() == null ? "" : path.getFileName().toString();
        return name.endsWith(".mcap") || name.endsWith(".db3");
    }

    @Override
    public String toString() {
        return "YARP monitor log or ROS 2 recording";
    }

    /** A recording read once or followed, mapped to records as it is read. */
    private final class BagSource implements RecordSource, BagSink {

        private final Path path;
        private final RecordSink sink;
        private final TopicMapping mapping = new TopicMapping(rules);
        private final boolean follow;
        private BagInput.Follow following;
        private long messages;
        private boolean read;

        BagSource(Path path, RecordSink sink, boolean follow) {
            this.path = path;
            this.sink = sink;
            this.follow = follow;
        }

        @Override
        public void message(BagMessage message) {
            messages++;
            mapping.map(message, sink::record);
        }

        @Override
        public boolean wants(String topic, String type) {
            return mapping.maps(topic, type); // a topic no rule maps is not even decoded
        }

        @Override
        public void problem(String line) {
            sink.problem(new ParseProblem(messages + 1, ParseProblem.Severity.ERROR, line));
        }

        private void noRules() throws IOException {
            if (rules.isEmpty()) {
                throw new IOException(path + " is a ROS 2 recording, and the abstraction maps no ROS 2 topic: give"
                        + " --abstraction nav2, or an abstraction file with a ros2 section");
            }
        }

        @Override
        public boolean poll() throws IOException {
            if (!follow) {
                if (read) {
                    return false;
                }
                drain();
                return true;
            }
            if (following == null) {
                noRules();
                following = input.follow(path, this);
            }
            return following.poll();
        }

        @Override
        public void drain() throws IOException {
            if (follow) {
                while (poll()) {
                    // to the end of what is written
                }
                return;
            }
            if (read) {
                return;
            }
            read = true;
            if (!Files.exists(path)) {
                throw new NoSuchFileException(path.toString());
            }
            noRules();
            input.read(path, this);
        }

        @Override
        public long lines() {
            return messages;
        }

        @Override
        public int openFiles() {
            return following == null ? 0 : 1;
        }

        @Override
        public void close() throws IOException {
            if (following != null) {
                following.close();
            }
        }
    }
}
