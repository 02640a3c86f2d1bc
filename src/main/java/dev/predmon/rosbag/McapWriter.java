package dev.predmon.rosbag;

import com.github.luben.zstd.Zstd;
import dev.predmon.rosbag.MsgDefinitions.DefinitionException;
import net.jpountz.lz4.LZ4FrameOutputStream;

import java.io.ByteArrayOutputStream;
import java.io.Closeable;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.CRC32;

/**
 * Writes an MCAP file with the {@code ros2} profile as {@code ros2 bag record} does: Schema ({@code ros2msg}) and
 * Channel ({@code cdr}) records and CDR messages in chunks, uncompressed, zstd (rosbag2's default) or lz4 (frame
 * format), each with its CRC-32; then DataEnd, a Footer without summary, and the closing magic. Each chunk is
 * written whole to the stream (and the stream flushed) once it holds {@code chunkBytes} of records or on {@link
 * #flush}, so a reader following the file sees whole chunks appear one after the other.
 *
 * <p>It writes to a stream: a caller that wants a file to be complete or not there writes to a temporary file and
 * moves it into place after {@link #close}.
 */
public final class McapWriter implements Closeable {

    /** How chunks are compressed. */
    public enum Compression { NONE, ZSTD, LZ4 }

    private final OutputStream out;
    private final Compression compression;
    private final int chunkBytes;
    private final ByteArrayOutputStream chunk = new ByteArrayOutputStream();
    private final Map<String, Integer> schemas = new HashMap<>();
    private final List<CdrCodec> codecs = new ArrayList<>();
    private final List<Integer> sequence = new ArrayList<>();
    private long chunkStart = Long.MAX_VALUE;
    private long chunkEnd;
    private boolean closed;

    /**
     * Starts an MCAP file on {@code out}: the magic and the Header record.
     *
     * @param chunkBytes records a chunk holds before it is written (at least 1)
     */
    public McapWriter(OutputStream out, Compression compression, int chunkBytes) throws IOException {
        if (chunkBytes < 1) {
            throw new IllegalArgumentException("chunkBytes must be at least 1, was " + chunkBytes);
        }
        this.out = out;
        this.compression = compression;
        this.chunkBytes = chunkBytes;
        out.write(McapScanner.MAGIC);
        Body header = new Body();
        header.string("ros2").string("predmon");
        header.writeTo(out, McapScanner.HEADER);
    }

    /** Declares a topic of a type predmon bundles (see {@link #channel(String, String, String)}). */
    public int channel(String topic, String type) {
        return channel(topic, type, BundledTypes.text(type));
    }

    /**
     * Declares a topic: its Schema record (once per type) and Channel record, and returns the channel's id.
     *
     * @param type       {@code pkg/msg/Type}
     * @param definition the type's {@code ros2msg} text with its dependencies, as recordings embed it
     * @throws IllegalArgumentException if the definition cannot be parsed or a type it uses is not defined
     */
    public int channel(String topic, String type, String definition) {
        CdrCodec codec;
        try {
            Map<String, MsgDefinitions.Type> own = MsgDefinitions.parse(type, definition);
            codec = CdrCodec.compile(type, own::get);
        } catch (DefinitionException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
        Integer schema = schemas.get(type);
        if (schema == null) {
            schema = schemas.size() + 1;
            schemas.put(type, schema);
            Body r = new Body();
            r.u16(schema).string(type).string("ros2msg").bytes(definition.getBytes(StandardCharsets.UTF_8));
            r.writeTo(chunk, McapScanner.SCHEMA);
        }
        int id = codecs.size() + 1;
        codecs.add(codec);
        sequence.add(0);
        Body r = new Body();
        r.u16(id).u16(schema).string(topic).string("cdr").u32(0); // metadata: an empty map
        r.writeTo(chunk, McapScanner.CHANNEL);
        return id;
    }

    /**
     * Writes one message of {@code channel}, encoded as CDR from {@code fields} (see {@link BagMessage} for the value
     * types; a field left out is its zero value).
     *
     * @throws IllegalArgumentException for a field the type does not have or a value of the wrong kind
     */
    public void write(int channel, long logTimeNanos, Map<String, ?> fields) throws IOException {
        write(channel, logTimeNanos, codec(channel).encode(fields));
    }

    /** Writes one message of {@code channel} whose CDR bytes (with their encapsulation header) are {@code cdr}. */
    public void write(int channel, long logTimeNanos, byte[] cdr) throws IOException {
        codec(channel);
        int seq = sequence.get(channel - 1);
        sequence.set(channel - 1, seq + 1);
        Body r = new Body();
        r.u16(channel).u32(seq).u64(logTimeNanos).u64(logTimeNanos).raw(cdr);
        r.writeTo(chunk, McapScanner.MESSAGE);
        chunkStart = Math.min(chunkStart, logTimeNanos);
        chunkEnd = Math.max(chunkEnd, logTimeNanos);
        if (chunk.size() >= chunkBytes) {
            flush();
        }
    }

    private CdrCodec codec(int channel) {
        if (channel < 1 || channel > codecs.size()) {
            throw new IllegalArgumentException("no channel " + channel + " (declared: 1.." + codecs.size() + ")");
        }
        return codecs.get(channel - 1);
    }

    /** Writes the records held as one chunk, if there are any, and flushes the stream. */
    public void flush() throws IOException {
        if (chunk.size() > 0) {
            byte[] records = chunk.toByteArray();
            chunk.reset();
            CRC32 crc = new CRC32();
            crc.update(records, 0, records.length);
            byte[] packed = switch (compression) {
                case NONE -> records;
                case ZSTD -> Zstd.compress(records, 3);
                case LZ4 -> lz4(records);
            };
            Body r = new Body();
            r.u64(chunkStart == Long.MAX_VALUE ? 0 : chunkStart).u64(chunkEnd).u64(records.length)
                    .u32((int) crc.getValue())
                    .string(switch (compression) {
                        case NONE -> "";
                        case ZSTD -> "zstd";
                        case LZ4 -> "lz4";
                    })
                    .u64(packed.length).raw(packed);
            r.writeTo(out, McapScanner.CHUNK);
            chunkStart = Long.MAX_VALUE;
            chunkEnd = 0;
        }
        out.flush();
    }

    private static byte[] lz4(byte[] records) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        try (LZ4FrameOutputStream z = new LZ4FrameOutputStream(b)) {
            z.write(records);
        }
        return b.toByteArray();
    }

    /** Writes the last chunk, DataEnd, the Footer and the closing magic, then closes the stream. */
    @Override
    public void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        try (out) {
            flush();
            new Body().u32(0).writeTo(out, McapScanner.DATA_END);
            new Body().u64(0).u64(0).u32(0).writeTo(out, McapScanner.FOOTER);
            out.write(McapScanner.MAGIC);
            out.flush();
        }
    }

    /** The body of one record, little-endian. */
    private static final class Body {
        private final ByteArrayOutputStream b = new ByteArrayOutputStream();

        Body u16(int v) {
            b.write(v);
            b.write(v >> 8);
            return this;
        }

        Body u32(int v) {
            for (int i = 0; i < 4; i++) {
                b.write(v >> (8 * i));
            }
            return this;
        }

        Body u64(long v) {
            for (int i = 0; i < 8; i++) {
                b.write((int) (v >> (8 * i)));
            }
            return this;
        }

        Body string(String s) {
            return bytes(s.getBytes(StandardCharsets.UTF_8));
        }

        Body bytes(byte[] data) {
            u32(data.length);
            return raw(data);
        }

        Body raw(byte[] data) {
            b.write(data, 0, data.length);
            return this;
        }

        void writeTo(OutputStream to, int opcode) throws IOException {
            to.write(head(opcode));
            b.writeTo(to);
        }

        void writeTo(ByteArrayOutputStream to, int opcode) {
            to.writeBytes(head(opcode));
            to.writeBytes(b.toByteArray());
        }

        private byte[] head(int opcode) {
            byte[] head = new byte[9];
            head[0] = (byte) opcode;
            long n = b.size();
            for (int i = 0; i < 8; i++) {
                head[1 + i] = (byte) (n >> (8 * i));
            }
            return head;
        }
    }
}
