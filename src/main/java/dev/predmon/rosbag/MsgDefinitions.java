package dev.predmon.rosbag;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Parses ROS 2 message definitions in the {@code ros2msg} form a recording carries: the top type's {@code .msg}
 * text, then each type it uses after a line of {@code =} and a line {@code MSG: pkg/Type}.
 *
 * <p>A field line is {@code type name [default]}, with {@code type} a primitive, {@code string<=N}, a message type
 * ({@code pkg/Type}, {@code pkg/msg/Type}, or a bare {@code Type} of the section's own package; {@code Header} is
 * {@code std_msgs/msg/Header}, and ROS 1's {@code time}/{@code duration}, which some writers emit, are
 * {@code builtin_interfaces}'), optionally followed by {@code []}, {@code [N]} or {@code [<=N]}. Constants ({@code
 * type NAME=value}), default values and comments are ignored: they do not change the bytes. Type names are
 * normalised to {@code pkg/msg/Type}.
 */
final class MsgDefinitions {

    /** One field: {@code type} is a primitive name or a normalised message type. */
    record Field(String name, String type, Shape shape, int length, int stringBound) {
    }

    /** How many values a field holds: one, a fixed array of {@code length}, or a sequence (bounded if length > 0). */
    enum Shape { SINGLE, FIXED, SEQUENCE }

    /** One message type, its fields in order. */
    record Type(String name, List<Field> fields) {
    }

    /** A definition that cannot be parsed; the message says which line and why. */
    static final class DefinitionException extends Exception {
        private static final long serialVersionUID = 1L;

        DefinitionException(String message) {
            super(message);
        }
    }

    static final Set<String> PRIMITIVES = Set.of("bool", "byte", "char", "int8", "uint8", "int16", "uint16", "int32",
            "uint32", "int64", "uint64", "float32", "float64", "string", "wstring");

    private static final Pattern SEPARATOR = Pattern.compile("^={3,}\\s*$");
    private static final Pattern FIELD_TYPE = Pattern.compile(
            "([A-Za-z][A-Za-z0-9_]*(?:/[A-Za-z][A-Za-z0-9_]*){0,2})(?:<=(\\d+))?(?:\\[(<=)?(\\d*)])?");
    private static final Pattern NAME = Pattern.compile("[A-Za-z][A-Za-z0-9_]*");

    private MsgDefinitions() {
    }

    /**
     * The types defined by {@code text}, the definition of {@code topType} with its dependencies, by normalised name.
     */
    static Map<String, Type> parse(String topType, String text) throws DefinitionException {
        Map<String, Type> types = new LinkedHashMap<>();
        String current = normalise(topType, "");
        List<String> section = new ArrayList<>();
        String[] lines = text.split("\r?\n", -1);
        int first = 1;
        for (int i = 0; i <= lines.length; i++) {
            String line = i < lines.length ? lines[i] : null;
            if (line == null || SEPARATOR.matcher(line).matches()) {
                if (current != null) {
                    types.putIfAbsent(current, type(current, section, first));
                }
                current = null;
                section.clear();
                first = i + 2;
            } else if (current == null && line.trim().startsWith("MSG:")) {
                current = normalise(line.trim().substring(4).trim(), "");
                first = i + 2;
            } else if (current == null && line.isBlank()) {
                first = i + 2;
            } else if (current == null) {
                throw new DefinitionException("line " + (i + 1) + " of the definition of " + topType
                        + ": expected 'MSG: pkg/Type' after a line of '=', found '" + line.trim() + "'");
            } else {
                section.add(line);
            }
        }
        return types;
    }

    private static Type type(String name, List<String> lines, int firstLine) throws DefinitionException {
        String pkg = name.indexOf('/') < 0 ? "" : name.substring(0, name.indexOf('/'));
        List<Field> fields = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i).strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String[] tokens = line.split("\\s+", 3);
            String where = "line " + (firstLine + i) + " of the definition of " + name;
            if (tokens.length < 2) {
                throw new DefinitionException(where + ": expected 'type name', found '" + line + "'");
            }
            String fieldName = tokens[1];
            int hash = fieldName.indexOf('#');
            if (hash >= 0) {
                fieldName = fieldName.substring(0, hash);
            }
            if (fieldName.contains("=") || (tokens.length == 3 && tokens[2].startsWith("="))) {
                continue; // a constant: no bytes on the wire
            }
            if (!NAME.matcher(fieldName).matches()) {
                throw new DefinitionException(where + ": expected a field name, found '" + tokens[1] + "'");
            }
            Matcher m = FIELD_TYPE.matcher(tokens[0]);
            if (!m.matches()) {
                throw new DefinitionException(where + ": expected a field type, found '" + tokens[0] + "'");
            }
            String base = m.group(1);
            int stringBound = m.group(2) == null ? 0 : parseBound(m.group(2), where);
            if (stringBound > 0 && !base.equals("string") && !base.equals("wstring")) {
                throw new DefinitionException(where + ": only a string can have a bound, found '" + tokens[0] + "'");
            }
            Shape shape = Shape.SINGLE;
            int length = 0;
            if (tokens[0].endsWith("]")) {
                boolean bounded = m.group(3) != null;
                String digits = m.group(4);
                if (digits.isEmpty() && bounded) {
                    throw new DefinitionException(where + ": expected a bound after '<=', found '" + tokens[0] + "'");
                }
                shape = digits.isEmpty() || bounded ? Shape.SEQUENCE : Shape.FIXED;
                length = digits.isEmpty() ? 0 : parseBound(digits, where);
            }
            fields.add(new Field(fieldName, PRIMITIVES.contains(base) ? base : normalise(base, pkg), shape, length,
                    stringBound));
        }
        return new Type(name, List.copyOf(fields));
    }

    private static int parseBound(String digits, String where) throws DefinitionException {
        try {
            return Integer.parseInt(digits);
        } catch (NumberFormatException e) {
            throw new DefinitionException(where + ": the bound " + digits + " is too large");
        }
    }

    /**
     * {@code pkg/msg/Type} for a type as a definition names it; {@code pkg} is the package a bare name belongs to
     * ("" when it has none).
     */
    static String normalise(String type, String pkg) {
        String builtin = switch (type) {
            case "time" -> "builtin_interfaces/msg/Time";
            case "duration" -> "builtin_interfaces/msg/Duration";
            case "Header" -> "std_msgs/msg/Header";
            default -> null;
        };
        if (builtin != null) {
            return builtin;
        }
        String[] parts = type.split("/", -1);
        if (parts.length == 3) {
            return type;
        }
        if (parts.length == 2) {
            return parts[0] + "/msg/" + parts[1];
        }
        return pkg.isEmpty() ? type : pkg + "/msg/" + type;
    }
}
