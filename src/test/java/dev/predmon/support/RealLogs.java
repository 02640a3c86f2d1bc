package dev.predmon.support;

import org.junit.jupiter.api.Assumptions;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.OptionalInt;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The public recordings of the real monitor in {@code ../shared/real-logs} and the table of its README, which
 * says for every file what an independent reader counted. They are never copied into this repository: tests that
 * use them are skipped, with a message, where the folder is absent.
 */
public final class RealLogs {

    /** {@code ../shared/real-logs}, or where {@code -Dpredmon.real-logs=DIR} says (from a worktree elsewhere). */
    public static final Path DIR = Path.of(System.getProperty("predmon.real-logs", "../shared/real-logs"));

    /**
     * One row of the README's table.
     *
     * @param file           the file, relative to {@link #DIR}
     * @param violationTick  the tick of the first level reading below 20, if there is one
     */
    public record Row(String file, long commands, long replies, long ticks, double firstLevel, double lowestLevel,
               OptionalInt violationTick) {

        public Path path() {
            return DIR.resolve(file);
        }
    }

    private static final Pattern ROW = Pattern.compile(
            "\\|\\s*(\\S+\\.txt)\\s*\\|\\s*(\\d+)\\s*\\|\\s*(\\d+)\\s*\\|\\s*(\\d+)\\s*\\|\\s*([\\d.]+)\\s*\\|\\s*([\\d.]+)\\s*\\|"
                    + "\\s*(no|yes, first reading below 20 after (\\d+) ticks)\\s*\\|");

    private RealLogs() {
    }

    /** The table's rows; skips the calling test where the recordings are absent. */
    public static List<Row> rows() throws IOException {
        Path readme = DIR.resolve("README.md");
        Assumptions.assumeTrue(Files.isRegularFile(readme),
                "skipped: no real recordings at " + DIR.toAbsolutePath().normalize() + " (they are not part of this repository)");
        List<Row> rows = new ArrayList<>();
        for (String line : Files.readAllLines(readme)) {
            Matcher m = ROW.matcher(line);
            if (m.find()) {
                rows.add(new Row(m.group(1), Long.parseLong(m.group(2)), Long.parseLong(m.group(3)),
                        Long.parseLong(m.group(4)), Double.parseDouble(m.group(5)), Double.parseDouble(m.group(6)),
                        m.group(8) == null ? OptionalInt.empty() : OptionalInt.of(Integer.parseInt(m.group(8)))));
            }
        }
        Assumptions.assumeFalse(rows.isEmpty(), "skipped: the README at " + readme + " has no table of files");
        return rows;
    }
}
