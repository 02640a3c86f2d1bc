package dev.predmon.learn;

import java.nio.file.Path;
import java.util.List;

/**
 * One scenario of a log directory: {@code <logs>/<name>/scenario.json} and its {@code *.log} files.
 *
 * @param name        the directory name
 * @param faulty      whether runs of this scenario violate the safety property
 * @param description free text from scenario.json
 * @param logs        the scenario's logs, sorted by file name
 */
public record ScenarioSpec(String name, boolean faulty, String description, List<Path> logs) {
}
