package dev.predmon.abstraction;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import dev.predmon.BadInputException;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.Map;
import java.util.Optional;

/**
 * Abstraction files: the built-in ones, reading and validating a file into an {@link Abstraction} with one-line
 * errors ({@code file:line:column: path: reason}), and the canonical form its fingerprint hashes. The public entry
 * points are {@link Abstraction#load}, {@link Abstraction#fromJson} and {@link Abstraction#builtin}.
 *
 * <p>A file is parsed by {@link LocatedJson} and bound by {@link SpecBinder}, its canonical form written by
 * {@link SpecWriter}: jackson-core and databind's tree nodes only, no {@code ObjectMapper}, whose construction and
 * data binding were half a second of every start of predmon.
 */
final class AbstractionFiles {

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
    static Abstraction fromJson(String source, String json) throws AbstractionException {
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
        return Abstraction.of(spec);
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
     * The recommended action of the built-in abstraction with this fingerprint, or null. An abstraction file that is
     * a built-in but for its action (the {@code models/abstraction.json} of models learned before actions existed)
     * thus gets the built-in's.
     */
    static String builtinAction(String fingerprint) {
        Map<String, String> actions = BuiltinActions.BY_FINGERPRINT;
        return actions == null ? null : actions.get(fingerprint); // null while the built-ins themselves are read
    }

    /** Read on first use: most runs of predmon never need it. */
    private static final class BuiltinActions {
        static final Map<String, String> BY_FINGERPRINT = read();

        private static Map<String, String> read() {
            Map<String, String> byFingerprint = new HashMap<>();
            for (String name : BUILTIN.keySet()) {
                builtin(name).ifPresent(a -> a.safety().map(SafetyRule::action)
                        .ifPresent(action -> byFingerprint.put(a.fingerprint(), action)));
            }
            return Map.copyOf(byFingerprint);
        }
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
