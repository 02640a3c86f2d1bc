package dev.predmon.rosbag;

import dev.predmon.rosbag.MsgDefinitions.DefinitionException;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;

/**
 * The topics of one data file and the delivery of its messages, for every storage: numbers the messages, asks the
 * sink whether it wants a topic, decodes, and turns what cannot be decoded into one problem line per topic. A topic
 * that cannot be decoded (another encoding than CDR, a type with no definition, a message that does not hold its
 * type) is reported once and its later messages are skipped: the other topics go on.
 */
final class Topics {

    /** A topic as the file declares it. */
    private static final class Topic {
        final String name;
        final String type;
        final String messageEncoding;
        final String schemaEncoding;
        final String definition;
        Boolean wanted;
        TopicDecoder decoder;
        boolean skipped;

        Topic(String name, String type, String messageEncoding, String schemaEncoding, String definition) {
            this.name = name;
            this.type = type;
            this.messageEncoding = messageEncoding;
            this.schemaEncoding = schemaEncoding;
            this.definition = definition;
        }
    }

    private final Path file;
    private final BagSink sink;
    private final Map<Integer, Topic> topics = new HashMap<>();
    private final Set<Integer> undeclared = new HashSet<>();
    private long index;
    private long delivered;

    Topics(Path file, BagSink sink) {
        this.file = file;
        this.sink = sink;
    }

    /** Declares topic {@code id} (a channel id or a row id); a later declaration of the same id replaces it. */
    void declare(int id, String topic, String type, String messageEncoding, String schemaEncoding, String definition) {
        topics.put(id, new Topic(topic, type, messageEncoding, schemaEncoding, definition));
    }

    /** Messages delivered so far. */
    long delivered() {
        return delivered;
    }

    /** Reports one problem about {@code where} in this file. */
    void problem(String where, String what) {
        sink.problem(file + ": " + where + ": " + what);
    }

    /**
     * One message of topic {@code id} at {@code where} (e.g. "record at byte 1234"), its CDR bytes in
     * {@code data[offset, offset + length)}.
     */
    void message(int id, long logTimeNanos, byte[] data, int offset, int length, String where) {
        index++;
        Topic t = topics.get(id);
        if (t == null) {
            if (undeclared.add(id)) {
                problem(where, "expected a message of a declared topic, found channel (topic id) " + id
                        + ", which nothing before it declares; its messages are skipped");
            }
            return;
        }
        if (t.skipped) {
            return;
        }
        if (t.wanted == null) {
            t.wanted = sink.wants(t.name, t.type);
        }
        if (!t.wanted) {
            return;
        }
        if (t.decoder == null && !prepare(t, where)) {
            return;
        }
        try {
            sink.message(new BagMessage(file, index, t.name, t.type, logTimeNanos,
                    t.decoder.decode(data, offset, length)));
            delivered++;
        } catch (CdrException e) {
            t.skipped = true;
            problem(where, "message " + index + " of topic " + t.name + " (" + t.type + "): " + e.getMessage()
                    + (t.decoder.bundled() ? " (decoded with predmon's bundled definition: the recording has none)"
                    : "") + "; the topic's later messages are skipped");
        }
    }

    private boolean prepare(Topic t, String where) {
        if (!t.messageEncoding.equals("cdr")) {
            t.skipped = true;
            problem(where, "topic " + t.name + " (" + t.type + ") has the message encoding '" + t.messageEncoding
                    + "', expected cdr; its messages are skipped");
            return false;
        }
        try {
            t.decoder = TopicDecoder.of(t.type, t.schemaEncoding, t.definition);
            return true;
        } catch (DefinitionException e) {
            t.skipped = true;
            problem(where, "cannot decode topic " + t.name + " (" + (t.type.isEmpty() ? "no type" : t.type) + "): "
                    + e.getMessage() + "; its messages are skipped");
            return false;
        }
    }
}
