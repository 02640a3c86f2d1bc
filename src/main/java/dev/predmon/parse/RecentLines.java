package dev.predmon.parse;

import java.util.Arrays;

/**
 * The last three lines seen, kept because a yarplogger save file shows its nature only at its first start marker
 * (or a version line), and an entry's time stamps and level are the three lines before its marker.
 */
final class RecentLines {

    private final String[] text = new String[3];

    void push(String line) {
        text[0] = text[1];
        text[1] = text[2];
        text[2] = line;
    }

    /** The k-th of the three lines (0 oldest), trimmed, or null when there is none. */
    String trimmed(int k) {
        return text[k] == null ? null : text[k].trim();
    }

    void clear() {
        Arrays.fill(text, null);
    }
}
