package dev.predmon.abstraction.file;

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
import java.util.Collection;
import java.util.stream.Collectors;

/**
 * How abstraction files were bound and written before {@link SpecBinder} and {@link SpecWriter}: Jackson's data
 * binding with the strict mapper {@code AbstractionFiles} used to build. The tests hold the hand-written binder
 * and writer to exactly its results, error messages and bytes, so that no file reads differently and no
 * fingerprint changes.
 */
final class DatabindOracle {

    static final JsonMapper MAPPER = JsonMapper.builder()
            .enable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES)
            .enable(DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES)
            .disable(MapperFeature.ALLOW_COERCION_OF_SCALARS)
            .enable(MapperFeature.SORT_PROPERTIES_ALPHABETICALLY)
            .enable(SerializationFeature.ORDER_MAP_ENTRIES_BY_KEYS)
            .build();

    /** What reading a text gave: its canonical JSON and spec, or the one-line error. */
    record Outcome(String canonical, AbstractionSpec spec, String error) {
    }

    private DatabindOracle() {
    }

    /** The canonical JSON of a spec as data binding wrote it. */
    static String canonical(AbstractionSpec spec) {
        try {
            return MAPPER.writeValueAsString(spec);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
    }

    /** The former {@code AbstractionFiles.fromJson}, step for step; {@code canonical} is set when it loads. */
    static Outcome fromJson(String source, String json) {
        LocatedJson tree;
        try {
            tree = LocatedJson.parse(MAPPER.getFactory(), json);
        } catch (JsonProcessingException e) {
            return error(position(source, e.getLocation()) + "invalid JSON: " + firstLine(e.getOriginalMessage()));
        } catch (IOException e) {
            return error(source + ": cannot read: " + e);
        }
        if (!tree.root().isObject()) {
            return error(position(source, tree.locate("")) + "expected a JSON object at the top");
        }
        Outcome bound = bind(source, tree);
        if (bound.error() != null) {
            return bound;
        }
        try {
            AbstractionValidator.validate(bound.spec());
        } catch (AbstractionValidator.Invalid e) {
            return error(position(source, tree.locate(e.pointer)) + at(e.pointer) + e.getMessage());
        }
        return new Outcome(canonical(bound.spec()), bound.spec(), null);
    }

    /** Binding alone: the spec, or the error message. */
    static Outcome bind(String source, LocatedJson tree) {
        AbstractionSpec spec;
        try {
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
            return error(position(source, tree.locate(pointer)) + at(pointer) + reason);
        } catch (JsonProcessingException e) {
            return error(source + ": " + firstLine(e.getOriginalMessage()));
        }
        return new Outcome(null, spec, null);
    }

    private static Outcome error(String message) {
        return new Outcome(null, null, message);
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
        return Collection.class.isAssignableFrom(type) ? "an array" : "an object";
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
        return AbstractionFiles.position(source, l);
    }

    private static String firstLine(String message) {
        return AbstractionFiles.firstLine(message);
    }
}
