package dev.predmon;

/**
 * Text for a terminal made of what a log or a file name holds. Log values and file names are anyone's bytes: an ESC
 * starts a control sequence that can erase or rewrite the line above (the WARNING), a BEL rings, a NUL or a carriage
 * return hides what came before it, and a newline in a file name forges a line of predmon's own. Every line predmon
 * prints from such text goes through {@link #line}, which writes each of those characters as a visible escape. JSON
 * output needs none of this: its strings escape control characters already.
 */
public final class Terminal {

    private static final char[] HEX = "0123456789abcdef".toCharArray();

    private Terminal() {
    }

    /**
     * {@code text} as one line that does nothing to a terminal but show itself: C0 and C1 control characters and DEL
     * as {@code \n}, {@code \r}, {@code \t} or {@code \xNN}, and the invisible characters that reorder or hide text
     * (bidirectional overrides, zero-width marks, line and paragraph separators) as {@code \}{@code uNNNN}. Anything
     * else, backslashes included, is left as it is.
     */
    public static String line(String text) {
        if (text == null) {
            return null;
        }
        int i = 0;
        while (i < text.length() && !unsafe(text.charAt(i))) {
            i++;
        }
        if (i == text.length()) {
            return text; // the common case: nothing to escape, no copy
        }
        StringBuilder b = new StringBuilder(text.length() + 16).append(text, 0, i);
        for (; i < text.length(); i++) {
            char c = text.charAt(i);
            if (!unsafe(c)) {
                b.append(c);
            } else if (c == '\n') {
                b.append("\\n");
            } else if (c == '\r') {
                b.append("\\r");
            } else if (c == '\t') {
                b.append("\\t");
            } else if (c < 0x100) {
                b.append("\\x").append(HEX[c >> 4]).append(HEX[c & 0xf]);
            } else {
                b.append("\\u").append(HEX[c >> 12]).append(HEX[(c >> 8) & 0xf]).append(HEX[(c >> 4) & 0xf])
                        .append(HEX[c & 0xf]);
            }
        }
        return b.toString();
    }

    /** Whether {@code c} would act on a terminal, or hide or reorder text, rather than show as itself. */
    private static boolean unsafe(char c) {
        if (c < 0x20 || (c >= 0x7f && c < 0xa0)) {
            return true;
        }
        return c >= 0x200b && (c <= 0x200f // zero-width space, joiners, direction marks
                || (c >= 0x2028 && c <= 0x202e) // line and paragraph separators, bidirectional embeddings, overrides
                || (c >= 0x2066 && c <= 0x2069) // bidirectional isolates
                || c == 0xfeff); // zero-width no-break space
    }
}
