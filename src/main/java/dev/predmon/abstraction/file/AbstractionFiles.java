package dev.predmon.abstraction.file;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.AbstractionException;
import dev.predmon.abstraction.file.AbstractionSpec.SafetySpec;
import dev.predmon.property.Bound;
import dev.predmon.property.Property;
import dev.predmon.ros2.TopicRule;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * Abstraction files, the one entry point for them: the built-in ones, reading and validating a file into an
 * {@link Abstraction} with one-line errors ({@code file:line:column: path: reason}), and the canonical form its
 * fingerprint hashes.
 *
 * <p>A file has the keys {@code name} (required), {@code description}, {@code drop} (filters, where {@code *}
 * matches any characters, on {@code kind}/{@code from}/{@code to}/{@code protocol}/{@code command}),
 * {@code locations} (name to abbreviation, used for {@code {loc}} in symbols), {@code rules} (required:
 * {@code protocol}, {@code command}, {@code input}, {@code replies}, optional {@code description}; each reply has a
 * {@code symbol} and exactly one of {@code any: true}, {@code equals: [strings]},
 * {@code range: {above|atLeast, below|atMost}}), {@code properties} (see {@link PropertySpecs}; older files give one {@code safety} object), {@code warning} and
 * {@code runs} ({@link AbstractionSpec} says what each means).
 *
 * <p>Band boundaries of the default: bands are upper-inclusive, {@code (lower, upper]}, like the thesis's
 * notation and the behaviour tree's {@code level > 50} early-warning condition, so exactly 50.0 is already
 * {@code o_level_medium_six} and exactly 45.0 {@code o_level_medium_five}; the exception is
 * {@code o_level_medium_one = [20, 25]}, so that {@code o_level_low = (0, 20)} coincides exactly with the safety
 * monitor's violation {@code level < 20.0}. {@code o_level_zero} is 0 and below. Validation guarantees the
 * bands of one rule neither overlap nor leave gaps.
 *
 * <p>A file is parsed by {@link LocatedJson} and bound by {@link SpecBinder}, its canonical form written by
 * {@link SpecWriter}: jackson-core and databind's tree nodes only, no {@code ObjectMapper}, whose construction and
 * data binding were half a second of every start of predmon.
 */
public final class AbstractionFiles {

    /**
     * The built-in abstractions by name: {@code thesis}, the default (Tables 4.1/4.2 with the battery bands of
     * Section 5.2, for the thesis's tree), {@code scope-fetch} (the R1 fetch-and-carry tree whose monitor the
     * public SCOPE recordings show) and {@code nav2} (a robot on ROS 2 navigation, from its recorded topics).
     */
    public static final List<String> BUILTIN_NAMES = List.of("thesis", "scope-fetch", "nav2");

    /** Each built-in's resource, beside {@link Abstraction}. */
    private static final Map<String, String> BUILTIN = Map.of("thesis", "default-abstraction.json",
            "scope-fetch", "scope-fetch.json", "nav2", "nav2.json");

    private AbstractionFiles() {
    }

    /** The embedded default: the built-in {@code thesis}. */
    public static Abstraction defaults() {
        return builtin("thesis").orElseThrow();
    }

    /** The built-in abstraction of that name, if there is one. */
    public static Optional<Abstraction> builtin(String name) {
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
    public static Optional<String> builtinJson(String name) {
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
    public static Abstraction load(Path file) throws AbstractionException {
        String text;
        try {
            // Read whole before parsing: a file of gigabytes would exhaust the heap before the parser's limit
            if (Files.isRegularFile(file) && Files.size(file) > LocatedJson.MAX_BYTES) {
                throw new AbstractionException(file + ": " + Files.size(file) + " bytes, more than the "
                        + LocatedJson.MAX_BYTES + " an abstraction file may have");
            }
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new AbstractionException(file + ": cannot read: " + BadInputException.reason(e), e);
        }
        return fromJson(file.toString(), text);
    }

    /**
     * Parses and validates abstraction JSON text.
     *
     * @param source names the text in error messages, usually its file
     * @throws AbstractionException one line, {@code source:line:column: reason}, on the first problem
     */
    public static Abstraction fromJson(String source, String json) throws AbstractionException {
        LocatedJson tree;
        try {
            tree = LocatedJson.parse(json);
        } catch (JsonProcessingException e) {
            throw new AbstractionException(position(source, e.getLocation()) + "invalid JSON: "
                    + firstLine(e.getOriginalMessage()), e);
        } catch (IOException e) {
            throw new AbstractionException(source + ": cannot read: " + e, e);
        }
        if (!tree.root().isObject()) {
            throw new AbstractionException(position(source, tree.locate("")) + "expected a JSON object at the top");
        }
        // The properties list is read on its own (PropertySpecs); the rest binds as files always have.
        JsonNode properties = tree.root() instanceof ObjectNode o ? o.remove("properties") : null;
        JsonNode ros2 = tree.root() instanceof ObjectNode o ? o.remove("ros2") : null;
        AbstractionSpec spec;
        List<Property> read = null;
        List<TopicRule> topics = List.of();
        try {
            spec = SpecBinder.spec(tree.root());
            AbstractionValidator.validate(spec);
            if (ros2 != null) {
                topics = Ros2Specs.read(ros2);
            }
            if (properties != null) {
                if (spec.safety() != null) {
                    throw new AbstractionValidator.Invalid("/safety", "'safety' is the older form of one bound"
                            + " property: give it in 'properties' instead, with an id");
                }
                read = PropertySpecs.read(properties);
            }
        } catch (AbstractionValidator.Invalid e) {
            throw new AbstractionException(position(source, tree.locate(e.pointer)) + at(e.pointer) + e.getMessage());
        }
        String ros2Text = ros2 == null ? null : SpecWriter.properties(ros2);
        if (read == null) {
            return older(spec, ros2Text, topics);
        }
        String canonical = SpecWriter.canonical(spec, SpecWriter.properties(properties), ros2Text);
        // What is learned depends on the forecast's property only: the fingerprint hashes the file with that property
        // in the older form, so that models learned before properties came, or with other properties, stay valid.
        Bound forecast = read.stream().filter(p -> p instanceof Bound b && b.hasFloor()).map(p -> (Bound) p)
                .findFirst().orElse(null);
        String text = SpecWriter.canonical(spec.withSafety(forecast == null ? null : new SafetySpec(forecast.name(),
                forecast.value().protocol(), forecast.value().command(), orNull(forecast.value().from()),
                orNull(forecast.value().to()), forecast.floor(), null, null)));
        if (forecast != null && forecast.ceiling() != Double.POSITIVE_INFINITY) {
            text += "\nceiling " + forecast.ceiling();
        }
        // A ros2 section decides which records a recording gives, so it is part of what models were learned with.
        if (ros2Text != null) {
            text += "\nros2 " + ros2Text;
        }
        return new Abstraction(spec.definition(read, topics), canonical, sha256(text));
    }

    /**
     * A file of the older form: at most one property, its {@code safety} object. One that is a built-in but for its
     * action or its form (the {@code models/abstraction.json} of models learned before properties came) gets the
     * built-in's properties, its own action kept.
     */
    private static Abstraction older(AbstractionSpec spec, String ros2Text, List<TopicRule> topics) {
        String canonical = SpecWriter.canonical(spec, null, ros2Text);
        // The recommended action, and what says it is under way, are advice to operators: they change no trace, so
        // models stay valid when they do.
        String fingerprint = sha256(spec.hasAdvice() ? SpecWriter.canonical(spec.withoutAdvice(), null, ros2Text)
                : canonical);
        List<Property> builtin = builtinProperties(fingerprint);
        List<Property> properties;
        if (builtin != null) {
            // the built-in's properties; its forecast property with this file's own advice where it gives some
            properties = builtin.stream().map(p -> spec.hasAdvice() && p instanceof Bound b && b.hasFloor()
                    ? withIdAndBounds(spec.safetyProperty(b), b) : p).toList();
        } else {
            properties = spec.safety() == null ? List.of() : List.of(spec.safetyProperty(null));
        }
        return new Abstraction(spec.definition(properties, topics), canonical, fingerprint);
    }

    /** {@code advised} (an older file's property with its advice) under the id, name and bounds of {@code b}. */
    private static Bound withIdAndBounds(Bound advised, Bound b) {
        return new Bound(b.id(), b.name(), advised.action(), b.scope(), b.value(), b.floor(), b.ceiling(),
                advised.underWay());
    }

    private static String orNull(String port) {
        return port.isEmpty() ? null : port;
    }

    private static String at(String pointer) {
        return pointer.isEmpty() ? "" : LocatedJson.readable(pointer) + ": ";
    }

    static String position(String source, JsonLocation l) {
        if (l == null || l.getLineNr() < 1) {
            return source + ": ";
        }
        return source + ":" + l.getLineNr() + ":" + l.getColumnNr() + ": ";
    }

    static String firstLine(String message) {
        String m = message == null ? "" : message.strip();
        int nl = m.indexOf('\n');
        return nl < 0 ? m : m.substring(0, nl).strip();
    }

    /**
     * The properties, with their actions, of the built-in abstraction with this fingerprint, or null. An older
     * abstraction file that is a built-in but for its action and its form thus gets the built-in's.
     */
    static List<Property> builtinProperties(String fingerprint) {
        Map<String, List<Property>> byFingerprint = BuiltinProperties.BY_FINGERPRINT;
        return byFingerprint == null ? null : byFingerprint.get(fingerprint); // null while the built-ins are read
    }

    /** Read on first use: most runs of predmon never need it. */
    private static final class BuiltinProperties {
        static final Map<String, List<Property>> BY_FINGERPRINT = read();

        private static Map<String, List<Property>> read() {
            Map<String, List<Property>> byFingerprint = new HashMap<>();
            for (String name : BUILTIN.keySet()) {
                builtin(name).ifPresent(a -> byFingerprint.put(a.fingerprint(), a.properties()));
            }
            return Map.copyOf(byFingerprint);
        }
    }

    private static String sha256(String text) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256")
                    .digest(text.getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java platform has SHA-256", e);
        }
    }

}
