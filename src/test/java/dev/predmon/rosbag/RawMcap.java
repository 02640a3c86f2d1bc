package dev.predmon.rosbag;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/** Builds MCAP bytes record by record, unchunked, to make files predmon's writer never writes. */
final class RawMcap {

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();

    RawMcap() {
        out.writeBytes(McapScanner.MAGIC);
        record(McapScanner.HEADER, body().string("ros2").string("test"));
    }

    static final class Body {
        final ByteArrayOutputStream b = new ByteArrayOutputStream();

        Body u16(int v) {
            b.write(v);
            b.write(v >> 8);
            return this;
        }

        Body u32(long v) {
            for (int i = 0; i < 4; i++) {
                b.write((int) (v >> (8 * i)));
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
            byte[] d = s.getBytes(StandardCharsets.UTF_8);
            u32(d.length);
            b.writeBytes(d);
            return this;
        }

        Body raw(byte[] d) {
            b.writeBytes(d);
            return this;
        }
    }

    static Body body() {
        return new Body();
    }

    RawMcap record(int op, Body body) {
        byte[] d = body.b.toByteArray();
        out.write(op);
        out.writeBytes(body().u64(d.length).b.toByteArray());
        out.writeBytes(d);
        return this;
    }

    /** A record whose length field says {@code length}, whatever follows. */
    RawMcap lyingRecord(int op, long length) {
        out.write(op);
        out.writeBytes(body().u64(length).b.toByteArray());
        return this;
    }

    RawMcap schema(int id, String name, String encoding, String text) {
        return record(McapScanner.SCHEMA, body().u16(id).string(name).string(encoding).string(text));
    }

    RawMcap channel(int id, int schema, String topic, String encoding) {
        return record(McapScanner.CHANNEL, body().u16(id).u16(schema).string(topic).string(encoding).u32(0));
    }

    RawMcap message(int channel, long time, byte[] cdr) {
        return record(McapScanner.MESSAGE, body().u16(channel).u32(0).u64(time).u64(time).raw(cdr));
    }

    byte[] end() {
        record(McapScanner.DATA_END, body().u32(0));
        record(McapScanner.FOOTER, body().u64(0).u64(0).u32(0));
        out.writeBytes(McapScanner.MAGIC);
        return out.toByteArray();
    }

    /** The top-level records of an MCAP file: {opcode, offset, length} each. */
    static List<long[]> records(byte[] file) {
        List<long[]> out = new ArrayList<>();
        int p = McapScanner.MAGIC.length;
        while (p + 9 <= file.length - McapScanner.MAGIC.length) {
            long len = McapBody.le64(file, p + 1);
            out.add(new long[] {file[p] & 0xff, p, len});
            p += 9 + (int) len;
        }
        return out;
    }

    /** A Time as CDR with its encapsulation header. */
    static byte[] battery(double percentage) {
        return codec("sensor_msgs/msg/BatteryState").encode(java.util.Map.of("percentage", percentage,
                "header", java.util.Map.of("frame_id", "base_link")));
    }

    static CdrCodec codec(String type) {
        try {
            return CdrCodec.compile(type, t -> BundledTypes.find(t, false));
        } catch (MsgDefinitions.DefinitionException e) {
            throw new IllegalStateException(e);
        }
    }
}
