package dev.predmon.rosbag;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/**
 * A linear scan of one MCAP file (foxglove/mcap's specification): the magic, then records of {@code opcode u8,
 * length u64, body}. Schema, Channel and Message records are read, Chunks decompressed and read the same way, and
 * every other record skipped; DataEnd or Footer ends the data. The scan can stop at the end of what is there and go
 * on later from the same record, which is how a file still being recorded is followed: a record is read only once
 * all its bytes are there.
 *
 * <p>Every length is checked against the bytes the file has before anything is allocated for it; a length no
 * record can have, a chunk that does not decompress or fails its CRC, or a file cut inside a record is one problem
 * line, after which the scan stops ({@link State#FAILED}) with every message before it delivered.
 */
final class McapScanner {

    /** Where a scan stands after {@link #advance}. */
    enum State { MORE, DONE, FAILED }

    static final byte[] MAGIC = {(byte) 0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
    static final int HEADER = 0x01;
    static final int FOOTER = 0x02;
    static final int SCHEMA = 0x03;
    static final int CHANNEL = 0x04;
    static final int MESSAGE = 0x05;
    static final int CHUNK = 0x06;
    static final int DATA_END = 0x0F;
    /** The longest record read: a record's body is read whole into one array. */
    private static final long MAX_RECORD = Integer.MAX_VALUE - 64;

    private record Schema(String name, String encoding, String text) {
    }

    private final FileChannel channel;
    private final Topics topics;
    private final Map<Integer, Schema> schemas = new HashMap<>();
    private long pos;
    private State state = State.MORE;
    private byte[] buf = new byte[1 << 16];
    private long bufStart;
    private int bufLen;

    McapScanner(FileChannel channel, Topics topics) {
        this.channel = channel;
        this.topics = topics;
    }

    State state() {
        return state;
    }

    /** Bytes of the file scanned: every record before this offset has been read. */
    long position() {
        return pos;
    }

    /**
     * Reads every complete record in {@code [position(), size)}. With {@code last}, the file will not grow: a record
     * cut short, or no end record, is then a problem; otherwise the scan waits there for more.
     */
    State advance(long size, boolean last) throws IOException {
        while (state == State.MORE) {
            if (pos == 0) {
                if (!window(0, MAGIC.length, size)) {
                    return cut(size, last, "the MCAP magic (89 4D 43 41 50 30 0D 0A)");
                }
                if (!Arrays.equals(buf, 0, MAGIC.length, MAGIC, 0, MAGIC.length)) {
                    return fail("byte 0", "expected the MCAP magic (89 4D 43 41 50 30 0D 0A), found other bytes");
                }
                pos = MAGIC.length;
                continue;
            }
            if (!window(pos, 9, size)) {
                return cut(size, last, "a record (an opcode and a length)");
            }
            int at = (int) (pos - bufStart);
            int op = buf[at] & 0xff;
            long len = McapBody.le64(buf, at + 1);
            if (len < 0 || len > MAX_RECORD) {
                return fail("record at byte " + pos, "impossible length " + Long.toUnsignedString(len)
                        + " of a record (opcode 0x" + Integer.toHexString(op) + ")");
            }
            if (!window(pos + 9, len, size)) {
                if (last && len > size - pos - 9) {
                    return fail("record at byte " + pos, "the record (opcode 0x" + Integer.toHexString(op)
                            + ") claims " + len + " byte(s), only " + (size - pos - 9) + " follow: the file is cut");
                }
                return State.MORE;
            }
            int body = (int) (pos + 9 - bufStart);
            String where = (op == CHUNK ? "chunk" : "record") + " at byte " + pos;
            long next = pos + 9 + len;
            if (op == DATA_END || op == FOOTER) {
                pos = next;
                state = State.DONE;
                return state;
            }
            try {
                if (op == CHUNK) {
                    chunk(buf, body, body + (int) len, where);
                } else {
                    record(op, buf, body, body + (int) len, where);
                }
            } catch (McapBody.Truncated | Chunks.Bad e) {
                return fail(where, e.getMessage());
            }
            pos = next;
        }
        return state;
    }

    private State cut(long size, boolean last, String expected) {
        if (!last) {
            return State.MORE;
        }
        if (pos == size && pos > 0) {
            return fail("byte " + pos, "the file ends without the records that close an MCAP file (DataEnd, "
                    + "Footer): it was cut while it was written");
        }
        return fail("byte " + pos, "expected " + expected + ", the file ends after " + (size - pos) + " byte(s)");
    }

    private State fail(String where, String what) {
        topics.problem(where, what);
        state = State.FAILED;
        return state;
    }

    private void record(int op, byte[] data, int start, int end, String where) throws McapBody.Truncated {
        McapBody b = new McapBody(data, start, end);
        switch (op) {
            case SCHEMA -> {
                int id = b.u16("the schema id");
                String name = b.string("the schema name");
                String encoding = b.string("the schema encoding");
                long n = b.u32("the length of the schema data");
                if (n > end - b.pos) {
                    throw new McapBody.Truncated("expected schema data of " + n + " byte(s), the record has "
                            + (end - b.pos) + " left");
                }
                schemas.put(id, new Schema(name, encoding, new String(data, b.pos, (int) n,
                        StandardCharsets.UTF_8)));
            }
            case CHANNEL -> {
                int id = b.u16("the channel id");
                int schemaId = b.u16("the schema id");
                String topic = b.string("the topic");
                String encoding = b.string("the message encoding");
                Schema s = schemas.getOrDefault(schemaId, new Schema("", "", ""));
                topics.declare(id, topic, s.name(), encoding, s.encoding(), s.text());
            }
            case MESSAGE -> {
                int id = b.u16("the channel id");
                b.u32("the sequence number");
                long logTime = b.u64("the log time");
                b.u64("the publish time");
                topics.message(id, logTime, data, b.pos, end - b.pos, where);
            }
            default -> {
                // Header, indexes, attachments, metadata, summary records: nothing a message needs.
            }
        }
    }

    private void chunk(byte[] data, int start, int end, String where) throws McapBody.Truncated, Chunks.Bad {
        McapBody b = new McapBody(data, start, end);
        b.u64("the chunk's start time");
        b.u64("the chunk's end time");
        long uncompressed = b.u64("the uncompressed size");
        long crc = b.u32("the uncompressed CRC");
        String compression = b.string("the compression");
        long n = b.u64("the length of the records");
        if (n < 0 || n != end - b.pos) {
            throw new McapBody.Truncated("expected records of " + Long.toUnsignedString(n) + " byte(s), the chunk has "
                    + (end - b.pos) + " left");
        }
        byte[] records = Chunks.records(compression, data, b.pos, (int) n, uncompressed, crc);
        int p = 0;
        while (p < records.length) {
            String inner = "record at byte " + p + " of the " + where;
            if (records.length - p < 9) {
                throw new McapBody.Truncated("its record at byte " + p + ": expected an opcode and a length, "
                        + (records.length - p) + " byte(s) left");
            }
            int op = records[p] & 0xff;
            long len = McapBody.le64(records, p + 1);
            if (len < 0 || len > records.length - p - 9) {
                throw new McapBody.Truncated("its record at byte " + p + ": impossible length "
                        + Long.toUnsignedString(len) + ", " + (records.length - p - 9) + " byte(s) left in the chunk");
            }
            try {
                record(op, records, p + 9, p + 9 + (int) len, inner);
            } catch (McapBody.Truncated e) {
                throw new McapBody.Truncated("its record at byte " + p + ": " + e.getMessage());
            }
            p += 9 + (int) len;
        }
    }

    /** Makes {@code [at, at + n)} of the file available in {@link #buf}; false if the file does not have it yet. */
    private boolean window(long at, long n, long size) throws IOException {
        if (at >= bufStart && at + n <= bufStart + bufLen) {
            return true;
        }
        if (n > size - at) {
            return false;
        }
        int want = (int) Math.min(Math.max(n, 1 << 16), size - at);
        if (buf.length < want) {
            buf = new byte[want];
        }
        ByteBuffer bb = ByteBuffer.wrap(buf, 0, want);
        long from = at;
        while (bb.hasRemaining()) {
            int r = channel.read(bb, from);
            if (r < 0) {
                break;
            }
            from += r;
        }
        bufStart = at;
        bufLen = bb.position();
        return bufLen >= n;
    }
}
