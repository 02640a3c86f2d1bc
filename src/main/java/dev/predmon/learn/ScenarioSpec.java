package dev.predmon.learn;

import dev.predmon.pipeline.LogTrace;
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
 * @param violates    the id of the property a faulty scenario's runs violate, null for the property the forecast
 *                    follows (the abstraction's safety property)
 */
public record ScenarioSpec(String name, boolean faulty, String description, List<Path> logs, RunLabel runs,
                           String violates) {

    /** A scenario that violates, when faulty, the property the forecast follows. */
    public ScenarioSpec(String name, boolean faulty, String description, List<Path> logs, RunLabel runs) {
        this(name, faulty, description, logs, runs, null);
    }

    /**
     * Whether {@code run} violated the property this scenario is about: the one its {@code scenario.json} names, else
     * the one the forecast follows. The thesis's rule, a faulty scenario matched, is right about a run that did.
     */
    public boolean violatedBy(LogTrace.Run run) {
        return run.violated(violates);
    }

    /** This scenario with only {@code logs} (a fold's share of them), everything else kept. */
    public ScenarioSpec withLogs(List<Path> logs) {
        return new ScenarioSpec(name, faulty, description, logs, runs, violates);
    }

    /** A scenario directory's scenario: every run of its logs. */
    public ScenarioSpec(String name, boolean faulty, String description, List<Path> logs) {
        this(name, faulty, description, logs, RunLabel.ALL);
    }
}
