package dev.predmon.abstraction.file;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParseException;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.StreamReadConstraints;
import com.fasterxml.jackson.core.exc.StreamConstraintsException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.io.File;
import java.io.IOException;
import java.util.HashMap;
import java.util.Map;

/**
 * A JSON tree together with where each of its values starts in the text, keyed by JSON pointer
 * ({@code /rules/4/replies/2}). A plain Jackson tree forgets positions, but validation errors found after
 * binding must still say "line:column", so the tree is read token by token here.
 *
 * <p>It needs only jackson-core's streaming parser and databind's node classes, never an {@code ObjectMapper}:
 * building one, and its data binding, cost a third of a second of every start of predmon. Abstraction files and
 * {@code models/index.json} are read with it and bound by hand.
 */
public final class LocatedJson {

    /** Nesting a predmon file never needs (its deepest value is a few levels down); the parser stops at once past it. */
    public static final int MAX_DEPTH = 64;
    /** The longest string a predmon file holds is a description: a million characters is far beyond any. */
    public static final int MAX_STRING = 1_000_000;
    /** The largest file read as JSON, in bytes; an index of thousands of runs is a few megabytes. */
    public static final long MAX_BYTES = 64L << 20;

    /**
     * The one factory of parsers and generators: stateless once built, so shared. Its limits make a deep or huge
     * file one line of error instead of a stack overflow or an exhausted heap.
     */
    static final JsonFactory FACTORY = JsonFactory.builder()
            .streamReadConstraints(StreamReadConstraints.builder().maxNestingDepth(MAX_DEPTH)
                    .maxStringLength(MAX_STRING).maxDocumentLength(MAX_BYTES).build())
            .build();

    private final JsonNode root;
    private final Map<String, JsonLocation> locations;

    private LocatedJson(JsonNode root, Map<String, JsonLocation> locations) {
        this.root = root;
        this.locations = locations;
    }

    /** The value at the top. */
    public JsonNode root() {
        return root;
    }

    /**
     * Parses {@code text}; duplicate keys and trailing content are errors.
     *
     * @throws JsonProcessingException with the position of the first syntax error
     */
    public static LocatedJson parse(String text) throws IOException {
        return parse(FACTORY, text);
    }

    /**
     * Reads the first JSON value of {@code file} as {@code ObjectMapper.readValue} did, so that a file it took still
     * reads: what follows the value is not read, and of duplicate keys the last counts.
     *
     * @throws JsonProcessingException with the position of the first syntax error, or of the end of an empty file
     * @throws java.io.FileNotFoundException when the file cannot be opened, as {@link java.io.FileInputStream} says
     */
    public static LocatedJson readValue(File file) throws IOException {
        Map<String, JsonLocation> locations = new HashMap<>();
        try (JsonParser p = FACTORY.createParser(file)) {
            try {
                if (p.nextToken() == null) {
                    throw new JsonParseException(p, "No content to map due to end-of-input");
                }
                return new LocatedJson(read(p, "", locations), locations);
            } catch (StreamConstraintsException e) {
                throw located(p, e);
            }
        }
    }

    /** As {@link #parse(String)}, with parsers from {@code factory}. */
    static LocatedJson parse(JsonFactory factory, String text) throws IOException {
        Map<String, JsonLocation> locations = new HashMap<>();
        try (JsonParser p = factory.createParser(text)) {
            p.enable(JsonParser.Feature.STRICT_DUPLICATE_DETECTION);
            try {
                if (p.nextToken() == null) {
                    throw new JsonParseException(p, "empty file, expected a JSON object");
                }
                JsonNode root = read(p, "", locations);
                if (p.nextToken() != null) {
                    throw new JsonParseException(p, "unexpected content after the top-level value");
                }
                return new LocatedJson(root, locations);
            } catch (StreamConstraintsException e) {
                throw located(p, e);
            }
        }
    }

    /**
     * A limit of {@link #FACTORY} that was passed, as a parse error at the parser's position and in words: Jackson's
     * own exception has no position and names its Java classes.
     */
    private static JsonParseException located(JsonParser p, StreamConstraintsException e) {
        String m = e.getOriginalMessage() == null ? "" : e.getOriginalMessage();
        String reason;
        if (m.startsWith("Document nesting depth")) {
            reason = "nested more than " + MAX_DEPTH + " levels deep";
        } else if (m.startsWith("String value length")) {
            reason = "a string longer than " + MAX_STRING + " characters";
        } else if (m.startsWith("Number value length")) {
            reason = "a number longer than " + StreamReadConstraints.DEFAULT_MAX_NUM_LEN + " digits";
        } else if (m.startsWith("Document length")) {
            reason = "longer than " + MAX_BYTES + " bytes";
        } else {
            reason = m.replaceAll(",? ?\\(?from `[^`]*`\\)?", "");
        }
        return new JsonParseException(p, reason, e);
    }

    private static JsonNode read(JsonParser p, String pointer, Map<String, JsonLocation> locations)
            throws IOException {
        locations.putIfAbsent(pointer, p.currentTokenLocation());
        JsonNodeFactory nodes = JsonNodeFactory.instance;
        JsonToken t = p.currentToken();
        switch (t) {
            case START_OBJECT -> {
                ObjectNode object = nodes.objectNode();
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String name = p.currentName();
                    String child = pointer + "/" + escape(name);
                    locations.put(child, p.currentTokenLocation());
                    p.nextToken();
                    object.set(name, read(p, child, locations));
                }
                return object;
            }
            case START_ARRAY -> {
                ArrayNode array = nodes.arrayNode();
                int i = 0;
                while (p.nextToken() != JsonToken.END_ARRAY) {
                    array.add(read(p, pointer + "/" + i++, locations));
                }
                return array;
            }
            case VALUE_STRING -> {
                return nodes.textNode(p.getText());
            }
            case VALUE_NUMBER_INT -> {
                return p.getNumberType() == JsonParser.NumberType.BIG_INTEGER
                        ? nodes.numberNode(p.getBigIntegerValue()) : nodes.numberNode(p.getLongValue());
            }
            case VALUE_NUMBER_FLOAT -> {
                return nodes.numberNode(p.getDoubleValue());
            }
            case VALUE_TRUE, VALUE_FALSE -> {
                return nodes.booleanNode(p.getBooleanValue());
            }
            case VALUE_NULL -> {
                return nodes.nullNode();
            }
            default -> throw new JsonParseException(p, "unexpected token " + t);
        }
    }

    /** The position of {@code pointer}, or of its nearest enclosing value, or {@code null} if unknown. */
    public JsonLocation locate(String pointer) {
        String p = pointer;
        while (true) {
            JsonLocation l = locations.get(p);
            if (l != null || p.isEmpty()) {
                return l;
            }
            p = p.substring(0, p.lastIndexOf('/'));
        }
    }

    /** A key as a JSON pointer segment. */
    public static String escape(String name) {
        return name.replace("~", "~0").replace("/", "~1");
    }

    /** {@code /rules/4/replies/2} as a reader writes it: {@code rules[4].replies[2]}; the root is {@code (top)}. */
    public static String readable(String pointer) {
        if (pointer.isEmpty()) {
            return "(top)";
        }
        StringBuilder b = new StringBuilder();
        for (String segment : pointer.substring(1).split("/", -1)) {
            String s = segment.replace("~1", "/").replace("~0", "~");
            if (!s.isEmpty() && s.chars().allMatch(Character::isDigit)) {
                b.append('[').append(s).append(']');
            } else {
                b.append(b.length() == 0 ? "" : ".").append(s);
            }
        }
        return b.toString();
    }
}
