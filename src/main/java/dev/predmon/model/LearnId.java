package dev.predmon.model;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;

/**
 * What ties the parts of a model directory together: a SHA-256 over the abstraction's fingerprint and the bytes of
 * every DOT file the index lists, in index order, names included. {@code learn} writes it in {@code index.json} and
 * in {@code forecast.json}; reading computes it again from the DOT files as read, so that an index, a forecast or a
 * DOT file of another learn is refused. It depends only on what was learned, so the same logs give the same id and
 * a relearned directory stays byte for byte the same.
 */
final class LearnId {

    private final MessageDigest digest;

    /** An id over models learned with the abstraction of {@code fingerprint}; add each DOT file in index order. */
    LearnId(String fingerprint) {
        try {
            digest = MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java runtime has SHA-256", e);
        }
        field(String.valueOf(fingerprint).getBytes(StandardCharsets.UTF_8));
    }

    /** Adds the DOT file {@code name} with its bytes. */
    LearnId add(String name, byte[] dot) {
        field(name.getBytes(StandardCharsets.UTF_8));
        field(dot);
        return this;
    }

    /** The id, {@code sha256:} and 64 hex digits. */
    String value() {
        return "sha256:" + HexFormat.of().formatHex(digest.digest());
    }

    /** A length-prefixed field, so that no two different sequences of names and bytes hash alike. */
    private void field(byte[] bytes) {
        digest.update((bytes.length + ":").getBytes(StandardCharsets.US_ASCII));
        digest.update(bytes);
    }
}
