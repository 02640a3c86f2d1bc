package dev.predmon.abstraction;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonMappingException;
import com.fasterxml.jackson.databind.MapperFeature;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.exc.MismatchedInputException;
import com.fasterxml.jackson.databind.exc.UnrecognizedPropertyException;
import com.fasterxml.jackson.databind.json.JsonMapper;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.Map;
import java.util.Optional;
import java.util.stream.Collectors;

/**
 * Abstraction files: the built-in ones, reading and validating a file into an {@link Abstraction} with one-line
 * errors ({@code file:line:column: path: reason}), and the canonical form its fingerprint hashes. The public entry
 * points are {@link Abstraction#load}, {@link Abstraction#fromJson} and {@link Abstraction#builtin}.
 */
final class AbstractionFiles {

    /** Strict binding: unknown keys and coerced scalars are errors; keys sorted in the canonical form. */
    static final JsonMapper MAPPER = JsonMapper.builder()
            .enable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES)
            .enable(DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES)
            .disable(MapperFeature.ALLOW_COERCION_OF_SCALARS)
            .enable(MapperFeature.SORT_PROPERTIES_ALPHABETICALLY)
            .enable(SerializationFeature.ORDER_MAP_ENTRIES_BY_KEYS)
            .build();

    private AbstractionFiles() {
    }

    /**
     * The built-in abstractions by name: {@code thesis}, the default (Tables 4.1/4.2 with the battery bands of
     * Section 5.2, for the thesis's tree), and {@code scope-fetch} (the R1 fetch-and-carry tree whose monitor the
     * public SCOPE recordings show).
     */
    private static final Map<String, String> BUILTIN = Map.of("thesis", "default-abstraction.json", "scope-fetch", "scope-fetch.json");

    /** The built-in abstraction of that name, if there is one. */
    static Optional<Abstraction> builtin(String name) {
        String resource = BUILTIN.get(name);
        if (resource == null) {
            return Optional.empty();
        }
        try {
            return Optional.of(fromJson("(built-in " + name + ")", builtinJson(name).orElseThrow()));
        } catch (AbstractionException e) {
            // The resource ships with the code and is tested, so this is a build defect, not user input.
            throw new IllegalStateException("the built-in abstraction " + name + " is broken: " + e.getMessage(), e);
        }
    }

    /** The JSON text of a built-in abstraction, as shipped, for users to start their own from. */
    static Optional<String> builtinJson(String name) {
        String resource = BUILTIN.get(name);
        if (resource == null) {
            return Optional.empty();
        }
        try (InputStream in = Abstraction.class.getResourceAsStream(resource)) {
            if (in == null) {
                throw new IllegalStateException("resource " + resource + " is missing from the build");
            }
            return Optional.of(new String(in.readAllBytes(), StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new IllegalStateException("cannot read the built-in abstraction " + name, e);
        }
    }

    /** Loads and validates an abstraction file. */
    static Abstraction load(Path file) throws AbstractionException {
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new AbstractionException(file + ": cannot read: " + dev.predmon.BadInputException.reason(e), e);
        }
        return fromJson(file.toString(), text);
    }

    /**
     * Parses and validates abstraction JSON text.
     *
     * @param source names the text in error messages, usually its file
     * @throws AbstractionException one line, {@code source:line:column: reason}, on the first problem
     */
    static Abstraction fromJson(String source, String json) throws AbstractionException {
        LocatedJson tree;
        try {
            tree = LocatedJson.parse(MAPPER.getFactory(), json);
        } catch (JsonProcessingException e) {
            throw new AbstractionException(position(source, e.getLocation()) + "invalid JSON: "
                    + firstLine(e.getOriginalMessage()), e);
        } catch (IOException e) {
            throw new AbstractionException(source + ": cannot read: " + e, e);
        }
        AbstractionSpec spec;
        try {
            if (!tree.root().isObject()) {
                throw new AbstractionException(position(source, tree.locate("")) + "expected a JSON object at the top");
            }
            spec = MAPPER.treeToValue(tree.root(), AbstractionSpec.class);
        } catch (JsonMappingException e) {
            String pointer = pointer(e);
            String reason;
            if (e instanceof UnrecognizedPropertyException u) {
                reason = "unknown key '" + u.getPropertyName() + "' (allowed: " + u.getKnownPropertyIds().stream()
                        .map(Object::toString).sorted().collect(Collectors.joining(", ")) + ")";
            } else if (e instanceof MismatchedInputException m && m.getTargetType() != null) {
                reason = "expected " + describe(m.getTargetType());
            } else {
                reason = firstLine(e.getOriginalMessage());
            }
            throw new AbstractionException(position(source, tree.locate(pointer)) + at(pointer) + reason, e);
        } catch (JsonProcessingException e) {
            throw new AbstractionException(source + ": " + firstLine(e.getOriginalMessage()), e);
        }
        try {
            AbstractionValidator.validate(spec);
        } catch (AbstractionValidator.Invalid e) {
            throw new AbstractionException(position(source, tree.locate(e.pointer)) + at(e.pointer) + e.getMessage());
        }
        return Abstraction.of(spec);
    }

    private static String describe(Class<?> type) {
        if (Number.class.isAssignableFrom(type)) {
            return "a number";
        }
        if (type == String.class) {
            return "a string";
        }
        if (type == Boolean.class) {
            return "true or false";
        }
        return java.util.Collection.class.isAssignableFrom(type) ? "an array" : "an object";
    }

    private static String at(String pointer) {
        return pointer.isEmpty() ? "" : LocatedJson.readable(pointer) + ": ";
    }

    private static String pointer(JsonMappingException e) {
        StringBuilder b = new StringBuilder();
        for (JsonMappingException.Reference ref : e.getPath()) {
            if (ref.getFieldName() != null) {
                b.append('/').append(LocatedJson.escape(ref.getFieldName()));
            } else if (ref.getIndex() >= 0) {
                b.append('/').append(ref.getIndex());
            }
        }
        return b.toString();
    }

    private static String position(String source, JsonLocation l) {
        if (l == null || l.getLineNr() < 1) {
            return source + ": ";
        }
        return source + ":" + l.getLineNr() + ":" + l.getColumnNr() + ": ";
    }

    private static String firstLine(String message) {
        String m = message == null ? "" : message.strip();
        int nl = m.indexOf('\n');
        return nl < 0 ? m : m.substring(0, nl).strip();
    }

    static String sha256(String text) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256")
                    .digest(text.getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java platform has SHA-256", e);
        }
    }

}
