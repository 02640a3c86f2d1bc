package dev.predmon.learn;

import dev.predmon.BadInputException;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * The layout of a log directory: one subdirectory per scenario, holding its {@code *.log} files and a
 * {@code scenario.json}, {@code {"faulty": true|false, "description": "..."}} ({@link ScenarioFile}).
 */
public final class ScenarioLayout {

    /** Scenario names become file names and symbols in reports: keep them plain. */
    private static final Pattern NAME = Pattern.compile("[A-Za-z0-9_][A-Za-z0-9_.-]*");

    private ScenarioLayout() {
    }

    /** Reads every scenario under {@code logsDir}, sorted by name. */
    public static List<ScenarioSpec> scan(Path logsDir) throws BadInputException {
        if (!Files.isDirectory(logsDir)) {
            throw new BadInputException(logsDir + ": not a directory (expected one subdirectory per scenario)");
        }
        List<Path> dirs;
        try (Stream<Path> s = Files.list(logsDir)) {
            dirs = s.filter(Files::isDirectory).sorted().toList();
        } catch (IOException e) {
            throw new BadInputException(logsDir + ": cannot list: " + BadInputException.reason(e), e);
        }
        List<ScenarioSpec> specs = new ArrayList<>();
        for (Path dir : dirs) {
            specs.add(read(dir));
        }
        if (specs.isEmpty()) {
            throw new BadInputException(logsDir + ": no scenario directories (expected <scenario>/scenario.json and *.log)");
        }
        return specs;
    }

    /** Reads one scenario directory. */
    public static ScenarioSpec read(Path dir) throws BadInputException {
        String name = dir.getFileName().toString();
        if (!NAME.matcher(name).matches()) {
            throw new BadInputException(dir + ": scenario names may hold only letters, digits, '_', '-' and '.'");
        }
        ScenarioFile file = ScenarioFile.read(dir.resolve(ScenarioFile.NAME));
        List<Path> logs;
        try (Stream<Path> s = Files.list(dir)) {
            logs = s.filter(p -> p.getFileName().toString().endsWith(".log") && Files.isRegularFile(p)).sorted().toList();
        } catch (IOException e) {
            throw new BadInputException(dir + ": cannot list: " + BadInputException.reason(e), e);
        }
        if (logs.isEmpty()) {
            throw new BadInputException(dir + ": no *.log files for scenario '" + name + "'");
        }
        return new ScenarioSpec(name, file.faulty(), file.description(), logs);
    }
}
