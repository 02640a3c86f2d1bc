package dev.predmon.parse;

/** Names matched by a pattern in which {@code *} stands for any characters (ports, topics): one matcher for all. */
public final class Glob {

    private Glob() {
    }

    /** Whether {@code text} matches {@code pattern} whole; {@code *} matches any run of characters, even none. */
    public static boolean matches(String pattern, String text) {
        // Classic wildcard matching with backtracking over the last star: linear but for the star's retries.
        int p = 0;
        int t = 0;
        int star = -1;
        int mark = 0;
        while (t < text.length()) {
            if (p < pattern.length() && pattern.charAt(p) == '*') {
                star = p++;
                mark = t;
            } else if (p < pattern.length() && pattern.charAt(p) == text.charAt(t)) {
                p++;
                t++;
            } else if (star >= 0) {
                p = star + 1;
                t = ++mark;
            } else {
                return false;
            }
        }
        while (p < pattern.length() && pattern.charAt(p) == '*') {
            p++;
        }
        return p == pattern.length();
    }
}
