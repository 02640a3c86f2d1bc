package dev.predmon.learn;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelIndex;
import dev.predmon.pipeline.RunLabel;
import dev.predmon.property.Property;
import dev.predmon.ros2.Recordings;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * The layout of a log directory: one subdirectory per scenario, holding its {@code *.log} files and a
 * {@code scenario.json}, {@code {"faulty": true|false, "description": "...", "violates": "<property id>"}}
 * ({@link ScenarioFile}).
 */
public final class ScenarioLayout {

    /** Scenario names become file names and symbols in reports: keep them plain (reading models checks the same). */
    private static final Pattern NAME = ModelIndex.SCENARIO_NAME;

    private ScenarioLayout() {
    }

    /**
     * Reads every scenario under {@code logsDir}, sorted by name. A directory with {@code <scenario>/scenario.json}
     * subdirectories is read as such; any other directory holding {@code *.log} or {@code *.txt} files (in
     * subfolders too) is a {@link RecordingFolder}, whose runs the abstraction's safety monitor labels.
     */
    public static List<ScenarioSpec> scan(Path logsDir, Abstraction abstraction) throws BadInputException {
        if (!Files.isDirectory(logsDir)) {
            throw new BadInputException(logsDir + ": not a directory (expected one subdirectory per scenario with its "
                    + "scenario.json, or a folder of *.log/*.txt recordings)");
        }
        List<Path> dirs;
        try (Stream<Path> s = Files.list(logsDir)) {
            dirs = s.filter(Files::isDirectory).sorted().toList();
        } catch (IOException e) {
            throw new BadInputException(logsDir + ": cannot list: " + BadInputException.reason(e), e);
        }
        if (dirs.stream().noneMatch(d -> Files.isRegularFile(d.resolve("scenario.json")))) {
            List<ScenarioSpec> labelled = RecordingFolder.scenarios(logsDir, abstraction);
            if (labelled.isEmpty()) {
                throw new BadInputException(logsDir + ": no scenario directories (<scenario>/scenario.json and *.log) "
                        + "and no *.log or *.txt recordings");
            }
            return labelled;
        }
        List<ScenarioSpec> specs = new ArrayList<>();
        List<String> properties = abstraction.properties().stream().map(Property::id).toList();
        for (Path dir : dirs) {
            specs.add(read(dir, properties));
        }
        return specs;
    }

    /** Reads one scenario directory, whatever property its {@code scenario.json} names. */
    public static ScenarioSpec read(Path dir) throws BadInputException {
        return read(dir, null);
    }

    /**
     * Reads one scenario directory; the property its {@code scenario.json} says its runs violate must be one of
     * {@code properties} (ids; null to accept any).
     */
    static ScenarioSpec read(Path dir, List<String> properties) throws BadInputException {
        String name = dir.getFileName().toString();
        if (!NAME.matcher(name).matches()) {
            throw new BadInputException(dir + ": scenario names may hold only letters, digits, '_', '-' and '.'");
        }
        ScenarioFile file = ScenarioFile.read(dir.resolve(ScenarioFile.NAME), properties);
        List<Path> logs;
        try (Stream<Path> s = Files.list(dir)) {
            logs = s.filter(p -> (p.getFileName().toString().endsWith(".log") && Files.isRegularFile(p))
                    || Recordings.isRecording(p)).sorted().toList();
        } catch (IOException e) {
            throw new BadInputException(dir + ": cannot list: " + BadInputException.reason(e), e);
        }
        if (logs.isEmpty()) {
            throw new BadInputException(dir + ": no *.log files or ROS 2 recordings for scenario '" + name + "'");
        }
        return new ScenarioSpec(name, file.faulty(), file.description(), logs, RunLabel.ALL, file.violates());
    }
}
