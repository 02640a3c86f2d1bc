package dev.predmon.learn;

import dev.predmon.pipeline.RunLabel;

import java.nio.file.Path;
import java.util.List;

/**
 * One scenario of a log directory: {@code <logs>/<name>/scenario.json} and its {@code *.log} files.
 *
 * @param name        the directory name
 * @param faulty      whether runs of this scenario violate the safety property
 * @param description free text from scenario.json
 * @param logs        the scenario's logs, sorted by file name
 * @param runs        which runs of its logs belong to the scenario: all of them, or in a folder of recordings
 *                    labelled by the safety monitor, the violating or the safe ones
 */
public record ScenarioSpec(String name, boolean faulty, String description, List<Path> logs, RunLabel runs) {

    /** A scenario directory's scenario: every run of its logs. */
    public ScenarioSpec(String name, boolean faulty, String description, List<Path> logs) {
        this(name, faulty, description, logs, RunLabel.ALL);
    }
}
