package dev.predmon.live;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
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

    private final String fixed;
    private final String pattern;

    private RobotNames(String fixed, String pattern) {
        this.fixed = fixed;
        this.pattern = pattern;
    }

    /** Every log's robot is {@code name}. */
    public static RobotNames fixed(String name) {
        if (name.isBlank()) {
            throw new IllegalArgumentException("a robot's name must not be blank");
        }
        return new RobotNames(name.strip(), null);
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
        return new RobotNames(null, pattern);
    }

    /** The default: each log by its file's name. */
    public static RobotNames byFile() {
        return pattern(DEFAULT);
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
