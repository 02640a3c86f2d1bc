package dev.predmon.rosbag;

import dev.predmon.rosbag.MsgDefinitions.DefinitionException;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * Decodes the messages of one topic: with the definition the recording carries for its type, or, where it carries
 * none ({@code ros2idl}, or a sqlite3 bag of Humble), with the bundled one. A bundled type whose fields changed
 * between distributions has two candidates, newest first; the first message picks the one that decodes it exactly
 * (at most 3 bytes of padding left), and the topic keeps it.
 */
final class TopicDecoder {

    private final List<CdrCodec> candidates;
    private final boolean bundled;
    private CdrCodec chosen;

    private TopicDecoder(List<CdrCodec> candidates, boolean bundled) {
        this.candidates = candidates;
        this.bundled = bundled;
        this.chosen = candidates.size() == 1 ? candidates.get(0) : null;
    }

    /**
     * The decoder of {@code type} from {@code encoding} and {@code text} (the recording's definition; empty if it
     * has none).
     *
     * @throws DefinitionException naming the type and what is missing or malformed
     */
    static TopicDecoder of(String type, String encoding, String text) throws DefinitionException {
        String name = MsgDefinitions.normalise(type, "");
        if (name.isEmpty()) {
            throw new DefinitionException("the recording names no type for it");
        }
        if (!text.isBlank() && (encoding.equals("ros2msg") || encoding.isEmpty())) {
            Map<String, MsgDefinitions.Type> own = MsgDefinitions.parse(name, text);
            // A dependency the recording left out is looked up among the bundled types.
            return new TopicDecoder(List.of(CdrCodec.compile(name, t -> {
                MsgDefinitions.Type d = own.get(t);
                return d != null ? d : BundledTypes.find(t, false);
            })), false);
        }
        List<CdrCodec> candidates = new ArrayList<>();
        try {
            candidates.add(CdrCodec.compile(name, t -> BundledTypes.find(t, false)));
        } catch (DefinitionException e) {
            String why = text.isBlank() ? "the recording carries no definition of " + name
                    : "its definition is in the encoding '" + encoding + "' (expected ros2msg)";
            throw new DefinitionException(why + ", and predmon has none bundled (" + e.getMessage() + ")");
        }
        boolean[] older = {false};
        CdrCodec humble = CdrCodec.compile(name, t -> {
            older[0] |= BundledTypes.hasHumbleForm(t);
            return BundledTypes.find(t, true);
        });
        if (older[0]) {
            candidates.add(humble);
        }
        return new TopicDecoder(List.copyOf(candidates), true);
    }

    /** Whether the definition is predmon's bundled one rather than the recording's. */
    boolean bundled() {
        return bundled;
    }

    Map<String, Object> decode(byte[] data, int offset, int length) throws CdrException {
        if (chosen != null) {
            return chosen.decode(data, offset, length, null);
        }
        CdrException first = null;
        Map<String, Object> loose = null;
        CdrCodec looseCodec = null;
        int[] slack = new int[1];
        for (CdrCodec c : candidates) {
            try {
                Map<String, Object> m = c.decode(data, offset, length, slack);
                if (slack[0] < 4) {
                    chosen = c;
                    return m;
                }
                if (loose == null) {
                    loose = m;
                    looseCodec = c;
                }
            } catch (CdrException e) {
                first = first == null ? e : first;
            }
        }
        if (loose != null) {
            chosen = looseCodec;
            return loose;
        }
        throw first;
    }
}
