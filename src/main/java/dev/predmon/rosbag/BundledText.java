package dev.predmon.rosbag;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashSet;
import java.util.Set;

/**
 * The {@code ros2msg} text of a bundled type as a recorder embeds it: the type's {@code .msg} text, then, for each
 * message type it uses (depth first, each once), a line of 80 {@code =}, {@code MSG: pkg/Type} and that type's text.
 */
final class BundledText {

    static final String SEPARATOR = "=".repeat(80);

    private BundledText() {
    }

    /**
     * @throws IllegalArgumentException if {@code type} or a type it uses is not bundled
     */
    static String of(String type) {
        String top = MsgDefinitions.normalise(type, "");
        StringBuilder b = new StringBuilder(raw(top));
        Set<String> seen = new LinkedHashSet<>();
        seen.add(top);
        Deque<String> todo = new ArrayDeque<>(uses(top));
        while (!todo.isEmpty()) {
            String t = todo.pop();
            if (!seen.add(t)) {
                continue;
            }
            String[] parts = t.split("/", -1);
            b.append(b.charAt(b.length() - 1) == '\n' ? "" : "\n").append(SEPARATOR).append("\nMSG: ")
                    .append(parts[0]).append('/').append(parts[2]).append('\n').append(raw(t));
            todo.addAll(uses(t));
        }
        return b.toString();
    }

    private static Set<String> uses(String type) {
        Set<String> out = new LinkedHashSet<>();
        MsgDefinitions.Type t = BundledTypes.find(type, false);
        for (MsgDefinitions.Field f : t.fields()) {
            if (!MsgDefinitions.PRIMITIVES.contains(f.type())) {
                out.add(f.type());
            }
        }
        return out;
    }

    private static String raw(String type) {
        String[] parts = type.split("/", -1);
        String resource = "msg/" + parts[0] + "/" + parts[parts.length - 1] + ".msg";
        try (InputStream in = BundledText.class.getResourceAsStream(resource)) {
            if (in == null || parts.length != 3) {
                throw new IllegalArgumentException("no bundled definition of " + type);
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
