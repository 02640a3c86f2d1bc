package dev.predmon.ros2;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;

/**
 * A path to a field of a decoded message: names separated by dots ({@code header.stamp.sec}), a name followed by
 * {@code [i]} for one element of a list and, once at most, by {@code []} for each element
 * ({@code status_list[].status}).
 */
public final class FieldPath {

    private static final Pattern SEGMENT = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*(\\[[0-9]{0,6}])?");

    private final String text;
    /** The segments up to and including the one with {@code []}, or all of them when there is none. */
    private final List<String> head;
    /** The segments after the one with {@code []}; null when there is none. */
    private final List<String> tail;

    private FieldPath(String text, List<String> head, List<String> tail) {
        this.text = text;
        this.head = head;
        this.tail = tail;
    }

    /**
     * Parses {@code text}.
     *
     * @throws IllegalArgumentException with the reason, for a path that is not one
     */
    public static FieldPath parse(String text) {
        List<String> head = new ArrayList<>();
        List<String> tail = null;
        for (String s : text.split("\\.", -1)) {
            if (!SEGMENT.matcher(s).matches()) {
                throw new IllegalArgumentException("'" + text + "' is not a field path (names separated by dots, a"
                        + " name may end in [] for each element of a list or [i] for one): '" + s + "'");
            }
            if (tail != null) {
                if (s.endsWith("[]")) {
                    throw new IllegalArgumentException("'" + text + "' has more than one [] (each element of one"
                            + " list at most)");
                }
                tail.add(s);
            } else {
                head.add(s);
                if (s.endsWith("[]")) {
                    tail = new ArrayList<>();
                }
            }
        }
        return new FieldPath(text, List.copyOf(head), tail == null ? null : List.copyOf(tail));
    }

    /** Whether the path goes through each element of a list. */
    public boolean each() {
        return tail != null;
    }

    /** The path up to and including its {@code []}, the list it goes through; the whole path when there is none. */
    public String listPart() {
        return String.join(".", head);
    }

    /**
     * The values the path reaches in {@code fields}: one (or none, when a field is missing) for a path without
     * {@code []}, one per element of the list (null where the element lacks the field) for a path with it.
     */
    public List<Object> values(Map<String, Object> fields) {
        if (tail == null) {
            Object v = walk(fields, head, head.size());
            List<Object> one = new ArrayList<>(1);
            if (v != null) {
                one.add(v);
            }
            return one;
        }
        Object list = walk(fields, head, head.size() - 1);
        String last = head.get(head.size() - 1);
        Object elements = list instanceof Map<?, ?> m ? m.get(last.substring(0, last.length() - 2)) : null;
        List<Object> out = new ArrayList<>();
        if (elements instanceof List<?> l) {
            for (Object e : l) {
                out.add(walk(e, tail, tail.size()));
            }
        }
        return out;
    }

    /** The value at the first {@code n} segments from {@code at}, or null when a step is missing. */
    private static Object walk(Object at, List<String> segments, int n) {
        Object v = at;
        for (int i = 0; i < n && v != null; i++) {
            String s = segments.get(i);
            int bracket = s.indexOf('[');
            String name = bracket < 0 ? s : s.substring(0, bracket);
            v = v instanceof Map<?, ?> m ? m.get(name) : null;
            if (bracket >= 0 && v != null) {
                int index = Integer.parseInt(s.substring(bracket + 1, s.length() - 1));
                v = v instanceof List<?> l && index < l.size() ? l.get(index) : null;
            }
        }
        return v;
    }

    @Override
    public String toString() {
        return text;
    }
}
