package dev.predmon.live;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The robot's name on a log's tile: one name for a single log ({@code --name}), or a pattern filled in from each log's
 * path ({@code --name-pattern}): {@code {file}} is the file's name without {@code .log}/{@code .txt}, {@code {dir}} the
 * name of the directory it is in. The default, {@code {file}}, names {@code logs/r1.log} {@code r1};
 * {@code {dir}} names {@code robots/r1/monitor.log} {@code r1}.
 */
public final class RobotNames {

    /** The default pattern. */
    public static final String DEFAULT = "{file}";

    private static final Pattern PLACEHOLDER = Pattern.compile("\\{([^}]*)}");

    /** Names at most this long are shown whole: only longer ones lose the part every log's name shares. */
    static final int SHORT = 12;

    private final String fixed;
    private final String pattern;
    private final boolean shortens;

    private RobotNames(String fixed, String pattern, boolean shortens) {
        this.fixed = fixed;
        this.pattern = pattern;
        this.shortens = shortens;
    }

    /** Every log's robot is {@code name}. */
    public static RobotNames fixed(String name) {
        if (name.isBlank()) {
            throw new IllegalArgumentException("a robot's name must not be blank");
        }
        return new RobotNames(name.strip(), null, false);
    }

    /**
     * Names filled in from a pattern.
     *
     * @throws IllegalArgumentException for a placeholder other than {@code {file}} and {@code {dir}}, or none at all
     */
    public static RobotNames pattern(String pattern) {
        Matcher m = PLACEHOLDER.matcher(pattern);
        boolean any = false;
        while (m.find()) {
            if (!m.group(1).equals("file") && !m.group(1).equals("dir")) {
                throw new IllegalArgumentException("unknown placeholder " + m.group() + " in '" + pattern
                        + "': use {file} (the file's name without .log/.txt) and {dir} (its directory's name)");
            }
            any = true;
        }
        if (!any) {
            throw new IllegalArgumentException("'" + pattern + "' has no {file} or {dir}: every log would get the "
                    + "same name (use --name for a single log)");
        }
        return new RobotNames(null, pattern, false);
    }

    /**
     * The default: each log by its file's name, shown without the part all the logs' names share
     * ({@code monitor2022-10-11T15_17+02_00} and {@code monitor2022-10-11T16_02+02_00} are {@code 15_17} and
     * {@code 16_02}; see {@link #shown}).
     */
    public static RobotNames byFile() {
        return new RobotNames(null, DEFAULT, true);
    }

    /**
     * The names as shown, in the same order: as they are, or for the default pattern, when two or more are longer
     * than {@value #SHORT} characters, without the beginning and the end they all share (cut where a word or number
     * begins or ends, so that no number is cut in two). Names stay whole where nothing would be left.
     */
    public List<String> shown(List<String> names) {
        if (!shortens || names.size() < 2 || names.stream().allMatch(n -> n.length() <= SHORT)) {
            return names;
        }
        String first = names.get(0);
        int prefix = first.length();
        int suffix = first.length();
        for (String n : names) {
            prefix = Math.min(prefix, common(first, n, true));
            suffix = Math.min(suffix, common(first, n, false));
        }
        while (prefix > 0 && !boundary(first, prefix)) {
            prefix--;
        }
        while (suffix > 0 && !boundary(first, first.length() - suffix)) {
            suffix--;
        }
        List<String> shown = new ArrayList<>();
        for (String n : names) {
            int end = Math.max(prefix, n.length() - suffix);
            String s = trim(n.substring(prefix, end));
            if (s.isEmpty()) {
                return names;
            }
            shown.add(s);
        }
        return shown;
    }

    /** The length of the beginning ({@code front}) or end that {@code a} and {@code b} share. */
    private static int common(String a, String b, boolean front) {
        int n = Math.min(a.length(), b.length());
        int i = 0;
        while (i < n && (front ? a.charAt(i) == b.charAt(i)
                : a.charAt(a.length() - 1 - i) == b.charAt(b.length() - 1 - i))) {
            i++;
        }
        return i;
    }

    /** Whether a name may be cut before position {@code i}: not inside a word or a number. */
    private static boolean boundary(String s, int i) {
        if (i <= 0 || i >= s.length()) {
            return true;
        }
        char a = s.charAt(i - 1);
        char b = s.charAt(i);
        return !Character.isLetterOrDigit(a) || !Character.isLetterOrDigit(b)
                || Character.isDigit(a) != Character.isDigit(b);
    }

    /** Without separators at either end. */
    private static String trim(String s) {
        int from = 0;
        int to = s.length();
        while (from < to && !Character.isLetterOrDigit(s.charAt(from))) {
            from++;
        }
        while (to > from && !Character.isLetterOrDigit(s.charAt(to - 1))) {
            to--;
        }
        return s.substring(from, to);
    }

    /** The robot's name for {@code log} (a path as watched). */
    public String of(String log) {
        if (fixed != null) {
            return fixed;
        }
        Path path;
        try {
            path = Path.of(log);
        } catch (InvalidPathException e) {
            return log;
        }
        Path name = path.getFileName();
        String file = name == null ? log : name.toString().replaceFirst("\\.(log|txt)$", "");
        Path parent = path.toAbsolutePath().normalize().getParent();
        String dir = parent == null || parent.getFileName() == null ? "" : parent.getFileName().toString();
        return pattern.replace("{file}", file).replace("{dir}", dir);
    }
}
