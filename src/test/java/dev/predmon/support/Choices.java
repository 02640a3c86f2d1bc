package dev.predmon.support;

import java.util.Arrays;

/**
 * Reads decisions from a byte array, for fuzz targets that take raw bytes: the same target then runs under
 * Jazzer (which mutates the bytes, guided by coverage) and under a plain seeded loop (random bytes) in CI.
 * Once the bytes run out every decision is the smallest choice, so any input is a valid program.
 */
public final class Choices {

    private final byte[] bytes;
    private int at;

    public Choices(byte[] bytes) {
        this.bytes = bytes;
    }

    /** A number in {@code [min, max]}. */
    public int in(int min, int max) {
        if (max <= min) {
            return min;
        }
        long span = (long) max - min + 1;
        long raw = 0;
        for (int i = 0; i < 4; i++) {
            raw = raw << 8 | (at < bytes.length ? bytes[at++] & 0xff : 0);
        }
        return (int) (min + Math.floorMod(raw, span));
    }

    public boolean flip() {
        return in(0, 1) == 1;
    }

    /** Up to {@code max} raw bytes. */
    public byte[] bytes(int max) {
        int n = Math.min(in(0, max), bytes.length - at);
        byte[] out = Arrays.copyOfRange(bytes, at, at + Math.max(0, n));
        at += Math.max(0, n);
        return out;
    }

    /** A word of 1 to {@code max} characters from {@code alphabet}. */
    public String word(String alphabet, int max) {
        int n = in(1, max);
        StringBuilder sb = new StringBuilder(n);
        for (int i = 0; i < n; i++) {
            sb.append(alphabet.charAt(in(0, alphabet.length() - 1)));
        }
        return sb.toString();
    }

    /** Everything not consumed yet. */
    public byte[] rest() {
        byte[] out = Arrays.copyOfRange(bytes, Math.min(at, bytes.length), bytes.length);
        at = bytes.length;
        return out;
    }
}
