package dev.predmon.rosbag;

import dev.predmon.rosbag.MsgDefinitions.DefinitionException;
import dev.predmon.rosbag.MsgDefinitions.Field;
import dev.predmon.rosbag.MsgDefinitions.Shape;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * A message type compiled from its {@code ros2msg} definitions into a tree that decodes CDR bytes to the values
 * {@link BagMessage} describes and encodes such values back to CDR: nested messages inline, fixed arrays without a
 * count, sequences and strings with a u32 count, each primitive aligned to its size.
 */
final class CdrCodec {

    /** Where the definitions of the types a message uses come from. */
    @FunctionalInterface
    interface Lookup {
        /** The type named {@code name} ({@code pkg/msg/Type}), or null if there is no definition of it. */
        MsgDefinitions.Type find(String name);
    }

    private final Struct root;

    private CdrCodec(Struct root) {
        this.root = root;
    }

    /** Compiles {@code type}, finding it and every type it uses with {@code lookup}. */
    static CdrCodec compile(String type, Lookup lookup) throws DefinitionException {
        return new CdrCodec(struct(MsgDefinitions.normalise(type, ""), lookup, new HashMap<>(), new HashSet<>()));
    }

    /** The type's name, {@code pkg/msg/Type}. */
    String type() {
        return root.name;
    }

    /**
     * Decodes the message in {@code data[offset, offset + length)}; {@code slack}, if not null, receives the bytes
     * left after the last field.
     */
    Map<String, Object> decode(byte[] data, int offset, int length, int[] slack) throws CdrException {
        CdrReader r = new CdrReader(data, offset, length);
        Map<String, Object> m = root.read(r);
        if (slack != null) {
            slack[0] = r.remaining();
        }
        return m;
    }

    /**
     * Encodes {@code fields} (the value types of {@link BagMessage}; any {@link Number} for a number, a {@code List}
     * or array for an array) as little-endian CDR. A field left out is written as its zero value.
     *
     * @throws IllegalArgumentException for a field the type does not have, or a value of the wrong kind
     */
    byte[] encode(Map<String, ?> fields) {
        CdrWriter w = new CdrWriter();
        root.write(w, fields, "");
        return w.bytes();
    }

    private static Struct struct(String name, Lookup lookup, Map<String, Struct> done, Set<String> open)
            throws DefinitionException {
        Struct s = done.get(name);
        if (s != null) {
            return s;
        }
        if (!open.add(name)) {
            throw new DefinitionException("the definition of " + name + " contains itself");
        }
        MsgDefinitions.Type t = lookup.find(name);
        if (t == null) {
            throw new DefinitionException("no definition of " + name);
        }
        String[] names = new String[t.fields().size()];
        Node[] nodes = new Node[names.length];
        for (int i = 0; i < names.length; i++) {
            Field f = t.fields().get(i);
            names[i] = f.name();
            Node element = switch (f.type()) {
                case "string" -> new Str(f.stringBound());
                case "wstring" -> throw new DefinitionException("field " + f.name() + " of " + name
                        + " is a wstring, which is not supported");
                default -> MsgDefinitions.PRIMITIVES.contains(f.type()) ? Prim.of(f.type())
                        : struct(f.type(), lookup, done, open);
            };
            nodes[i] = f.shape() == Shape.SINGLE ? element
                    : new Arr(element, f.shape() == Shape.FIXED, f.length(), f.name());
        }
        open.remove(name);
        s = new Struct(name, names, nodes);
        done.put(name, s);
        return s;
    }

    /** One node of the compiled tree. */
    private interface Node {
        Object read(CdrReader r) throws CdrException;

        void write(CdrWriter w, Object value, String path);

        /** The value a field left out is written as. */
        Object zero();

        /** The fewest bytes one value takes, to bound a sequence's count by the bytes left. */
        long minBytes();
    }

    private enum Prim implements Node {
        BOOL(1), INT8(1), UINT8(1), INT16(2), UINT16(2), INT32(4), UINT32(4), INT64(8), UINT64(8), FLOAT32(4),
        FLOAT64(8);

        private final int size;

        Prim(int size) {
            this.size = size;
        }

        static Prim of(String type) {
            return switch (type) {
                case "bool" -> BOOL;
                case "byte", "char", "uint8" -> UINT8;
                case "int8" -> INT8;
                case "int16" -> INT16;
                case "uint16" -> UINT16;
                case "int32" -> INT32;
                case "uint32" -> UINT32;
                case "int64" -> INT64;
                case "uint64" -> UINT64;
                case "float32" -> FLOAT32;
                case "float64" -> FLOAT64;
                default -> throw new IllegalArgumentException(type);
            };
        }

        @Override
        public Object read(CdrReader r) throws CdrException {
            return switch (this) {
                case BOOL -> r.u8() != 0;
                case INT8 -> (long) (byte) r.u8();
                case UINT8 -> (long) r.u8();
                case INT16 -> (long) (short) r.i16();
                case UINT16 -> (long) (r.i16() & 0xffff);
                case INT32 -> (long) r.i32();
                case UINT32 -> r.i32() & 0xffffffffL;
                case INT64, UINT64 -> r.i64();
                case FLOAT32 -> (double) Float.intBitsToFloat(r.i32());
                case FLOAT64 -> Double.longBitsToDouble(r.i64());
            };
        }

        @Override
        public void write(CdrWriter w, Object value, String path) {
            if (this == BOOL) {
                if (!(value instanceof Boolean b)) {
                    throw new IllegalArgumentException(path + ": expected a Boolean, found " + value);
                }
                w.u8(b ? 1 : 0);
                return;
            }
            if (!(value instanceof Number n)) {
                throw new IllegalArgumentException(path + ": expected a number, found " + value);
            }
            switch (this) {
                case INT8, UINT8 -> w.u8(n.intValue());
                case INT16, UINT16 -> w.i16(n.intValue());
                case INT32, UINT32 -> w.i32((int) n.longValue());
                case INT64, UINT64 -> w.i64(n.longValue());
                case FLOAT32 -> w.i32(Float.floatToRawIntBits(n.floatValue()));
                case FLOAT64 -> w.i64(Double.doubleToRawLongBits(n.doubleValue()));
                default -> throw new IllegalStateException(name());
            }
        }

        @Override
        public Object zero() {
            if (this == BOOL) {
                return false;
            }
            return this == FLOAT32 || this == FLOAT64 ? (Object) 0.0 : (Object) 0L;
        }

        @Override
        public long minBytes() {
            return size;
        }
    }

    private record Str(int bound) implements Node {
        @Override
        public Object read(CdrReader r) throws CdrException {
            return r.string("a string", bound);
        }

        @Override
        public void write(CdrWriter w, Object value, String path) {
            if (!(value instanceof CharSequence s)) {
                throw new IllegalArgumentException(path + ": expected a String, found " + value);
            }
            w.string(s.toString());
        }

        @Override
        public Object zero() {
            return "";
        }

        @Override
        public long minBytes() {
            return 4;
        }
    }

    private record Arr(Node element, boolean fixed, int length, String field) implements Node {
        @Override
        public Object read(CdrReader r) throws CdrException {
            int n;
            if (fixed) {
                n = length;
                if (n * element.minBytes() > r.remaining()) {
                    throw new CdrException("expected " + n + " elements of " + field + " at byte "
                            + (r.position() + 4) + " of the message: only " + r.remaining() + " byte(s) follow");
                }
            } else {
                n = r.count("sequence " + field, element.minBytes());
                if (length > 0 && n > length) {
                    throw new CdrException("sequence " + field + " has " + n + " elements, more than its bound "
                            + length);
                }
            }
            Object[] values = new Object[n];
            for (int i = 0; i < n; i++) {
                values[i] = element.read(r);
            }
            return Collections.unmodifiableList(Arrays.asList(values));
        }

        @Override
        public void write(CdrWriter w, Object value, String path) {
            List<?> values = asList(value, path);
            if (fixed && values.size() != length) {
                throw new IllegalArgumentException(path + ": expected " + length + " elements, found "
                        + values.size());
            }
            if (!fixed) {
                w.i32(values.size());
            }
            for (int i = 0; i < values.size(); i++) {
                element.write(w, values.get(i), path + "[" + i + "]");
            }
        }

        private static List<?> asList(Object value, String path) {
            if (value instanceof List<?> l) {
                return l;
            }
            if (value != null && value.getClass().isArray()) {
                int n = java.lang.reflect.Array.getLength(value);
                List<Object> l = new ArrayList<>(n);
                for (int i = 0; i < n; i++) {
                    l.add(java.lang.reflect.Array.get(value, i));
                }
                return l;
            }
            throw new IllegalArgumentException(path + ": expected a List or an array, found " + value);
        }

        @Override
        public Object zero() {
            return fixed ? Collections.nCopies(length, element.zero()) : List.of();
        }

        @Override
        public long minBytes() {
            return fixed ? Math.min(Integer.MAX_VALUE, length * element.minBytes()) : 4;
        }
    }

    private static final class Struct implements Node {
        final String name;
        final String[] names;
        final Node[] nodes;

        Struct(String name, String[] names, Node[] nodes) {
            this.name = name;
            this.names = names;
            this.nodes = nodes;
        }

        @Override
        public Map<String, Object> read(CdrReader r) throws CdrException {
            Map<String, Object> m = new LinkedHashMap<>((int) (names.length / 0.75f) + 1);
            for (int i = 0; i < names.length; i++) {
                m.put(names[i], nodes[i].read(r));
            }
            return Collections.unmodifiableMap(m);
        }

        @Override
        public void write(CdrWriter w, Object value, String path) {
            if (!(value instanceof Map<?, ?> m)) {
                throw new IllegalArgumentException(path + ": expected a Map for " + name + ", found " + value);
            }
            for (Object key : m.keySet()) {
                if (!Arrays.asList(names).contains(String.valueOf(key))) {
                    throw new IllegalArgumentException(path + ": " + name + " has no field '" + key + "' (it has "
                            + String.join(", ", names) + ")");
                }
            }
            for (int i = 0; i < names.length; i++) {
                Object v = m.get(names[i]);
                nodes[i].write(w, v == null ? nodes[i].zero() : v, path.isEmpty() ? names[i] : path + "." + names[i]);
            }
        }

        @Override
        public Object zero() {
            return Map.of();
        }

        @Override
        public long minBytes() {
            long sum = 0;
            for (Node n : nodes) {
                sum = Math.min(Integer.MAX_VALUE, sum + n.minBytes());
            }
            return Math.max(1, sum);
        }
    }
}
