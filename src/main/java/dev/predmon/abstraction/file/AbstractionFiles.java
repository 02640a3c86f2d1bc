package dev.predmon.abstraction.file;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.AbstractionException;
import dev.predmon.abstraction.SafetyRule;

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
 * {@code range: {above|atLeast, below|atMost}}), {@code safety} (see {@link SafetyRule}), {@code warning} and
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
     * Section 5.2, for the thesis's tree), and {@code scope-fetch} (the R1 fetch-and-carry tree whose monitor the
     * public SCOPE recordings show).
     */
    public static final List<String> BUILTIN_NAMES = List.of("thesis", "scope-fetch");

    /** Each built-in's resource, beside {@link Abstraction}. */
    private static final Map<String, String> BUILTIN = Map.of("thesis", "default-abstraction.json", "scope-fetch", "scope-fetch.json");

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
        AbstractionSpec spec;
        try {
            spec = SpecBinder.spec(tree.root());
            AbstractionValidator.validate(spec);
        } catch (AbstractionValidator.Invalid e) {
            throw new AbstractionException(position(source, tree.locate(e.pointer)) + at(e.pointer) + e.getMessage());
        }
        String canonical = SpecWriter.canonical(spec);
        // The recommended action, and what says it is under way, are advice to operators: they change no trace, so
        // models stay valid when they do.
        String fingerprint = sha256(spec.hasAdvice() ? SpecWriter.canonical(spec.withoutAdvice()) : canonical);
        SafetyRule advice = spec.safety() == null ? null : builtinAdvice(fingerprint);
        return new Abstraction(spec.definition(advice), canonical, fingerprint);
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
     * The safety property of the built-in abstraction with this fingerprint, for its advice (the recommended action
     * and what says it is under way), or null. An abstraction file that is a built-in but for its advice (the
     * {@code models/abstraction.json} of models learned before the advice existed) thus gets the built-in's.
     */
    static SafetyRule builtinAdvice(String fingerprint) {
        Map<String, SafetyRule> advice = BuiltinAdvice.BY_FINGERPRINT;
        return advice == null ? null : advice.get(fingerprint); // null while the built-ins themselves are read
    }

    /** The recommended action of the built-in abstraction with this fingerprint, or null. */
    static String builtinAction(String fingerprint) {
        SafetyRule advice = builtinAdvice(fingerprint);
        return advice == null ? null : advice.action();
    }

    /** Read on first use: most runs of predmon never need it. */
    private static final class BuiltinAdvice {
        static final Map<String, SafetyRule> BY_FINGERPRINT = read();

        private static Map<String, SafetyRule> read() {
            Map<String, SafetyRule> byFingerprint = new HashMap<>();
            for (String name : BUILTIN.keySet()) {
                builtin(name).ifPresent(a -> a.safety().ifPresent(s -> byFingerprint.put(a.fingerprint(), s)));
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
