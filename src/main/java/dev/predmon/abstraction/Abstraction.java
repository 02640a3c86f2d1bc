package dev.predmon.abstraction;

import dev.predmon.parse.LogRecord;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

/** The abstraction of the skill-component interface, loaded from JSON (thesis Tables 4.1/4.2, Section 5.2). */
public final class Abstraction {

    /** The embedded default: Tables 4.1/4.2 with the refined battery bands of Section 5.2. */
    public static Abstraction defaults() {
        throw new UnsupportedOperationException("TODO abstraction");
    }

    /** Loads and validates an abstraction file. */
    public static Abstraction load(Path file) throws AbstractionException {
        throw new UnsupportedOperationException("TODO abstraction");
    }

    /** Decides whether {@code r} belongs to the interface and, if so, which symbol it is. */
    public Classification classify(LogRecord r) {
        throw new UnsupportedOperationException("TODO abstraction");
    }

    /** Every input symbol the rules can produce, sorted. */
    public List<String> inputAlphabet() {
        throw new UnsupportedOperationException("TODO abstraction");
    }

    /** Every output symbol the rules can produce, sorted. */
    public List<String> outputAlphabet() {
        throw new UnsupportedOperationException("TODO abstraction");
    }

    /** The built-in safety monitor's property, if the file defines one. */
    public Optional<SafetyRule> safety() {
        throw new UnsupportedOperationException("TODO abstraction");
    }

    /** The abstraction's name from the file. */
    public String name() {
        throw new UnsupportedOperationException("TODO abstraction");
    }

    /** Canonical JSON text of this abstraction (stable key order), stored in models/index.json. */
    public String canonicalJson() {
        throw new UnsupportedOperationException("TODO abstraction");
    }

    /** SHA-256 hex of {@link #canonicalJson()}: tells whether models were learned with this abstraction. */
    public String fingerprint() {
        throw new UnsupportedOperationException("TODO abstraction");
    }
}
