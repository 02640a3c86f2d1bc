package dev.predmon.rosbag;

import dev.predmon.rosbag.MsgDefinitions.DefinitionException;

import java.util.Map;

/**
 * Messages of one type as CDR bytes outside a recording (a live stream that sends each message serialised, as
 * rosbridge's {@code cbor-raw} does): decoded and encoded with predmon's bundled definition of the type, which a
 * stream does not carry. A type whose fields changed between distributions is decoded as {@link TopicDecoder} does
 * a recording's without definitions: the first message picks the form that fits it.
 *
 * <p>Not thread-safe: one instance per topic.
 */
public final class CdrMessages {

    private final String type;
    private final TopicDecoder decoder;

    private CdrMessages(String type, TopicDecoder decoder) {
        this.type = type;
        this.decoder = decoder;
    }

    /**
     * The messages of {@code type} ({@code pkg/msg/Type} or {@code pkg/Type}).
     *
     * @throws IllegalArgumentException naming the type, when predmon bundles no definition of it (or of a type it uses)
     */
    public static CdrMessages of(String type) {
        try {
            return new CdrMessages(type, TopicDecoder.of(type, "", ""));
        } catch (DefinitionException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
    }

    public String type() {
        return type;
    }

    /**
     * The fields of the message in {@code cdr} (with its 4-byte encapsulation header), as {@link BagMessage} holds
     * them.
     *
     * @throws IllegalArgumentException saying where the bytes stop holding a message of the type
     */
    public Map<String, Object> decode(byte[] cdr) {
        try {
            return decoder.decode(cdr, 0, cdr.length);
        } catch (CdrException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
    }

    /**
     * {@code fields} as CDR with its encapsulation header, by the newest bundled definition (a field left out is its
     * zero value).
     *
     * @throws IllegalArgumentException for a type not bundled, a field it does not have, or a value of the wrong kind
     */
    public static byte[] encode(String type, Map<String, ?> fields) {
        try {
            return CdrCodec.compile(type, t -> BundledTypes.find(t, false)).encode(fields);
        } catch (DefinitionException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
    }
}
