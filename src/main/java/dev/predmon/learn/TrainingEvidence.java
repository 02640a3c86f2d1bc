package dev.predmon.learn;

import dev.predmon.BadInputException;
import dev.predmon.parse.LogFormat;
import dev.predmon.parse.RecordSink;
import dev.predmon.parse.RecordSource;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.property.Property;
import dev.predmon.property.UnseenNames;
import dev.predmon.property.Vocabulary;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * What the training logs say of each property: the names of it that no log holds (a misspelt command or port,
 * {@link UnseenNames}), and in how many training runs it was violated, and in how many nothing it speaks of occurred
 * (no evidence). A property with no evidence in any training run cannot be forecast from them.
 *
 * @param unseen the names no training log holds, in the file's order
 * @param runs   per property, in the file's order, what the training runs did to it
 */
public record TrainingEvidence(List<UnseenNames.Problem> unseen, List<PropertyRuns> runs) {

    public TrainingEvidence {
        unseen = List.copyOf(unseen);
        runs = List.copyOf(runs);
    }

    /**
     * One property over the training runs.
     *
     * @param property   its id
     * @param runs       the training runs
     * @param violated   of those, the runs that violated it
     * @param unobserved of those, the runs in which nothing it speaks of occurred
     */
    public record PropertyRuns(String property, int runs, int violated, int unobserved) {

        /** {@code grasp-in-time: violated in 10 of 43 runs}, with the runs that gave no evidence for it. */
        public String line() {
            if (runs > 0 && unobserved == runs) {
                return property + ": no evidence in any of the " + runs + " training runs (nothing it speaks of "
                        + "occurred): it cannot be forecast, and reads \"no evidence\" on runs like them";
            }
            return property + ": violated in " + violated + " of " + runs + " runs"
                    + (unobserved > 0 ? ", no evidence in " + unobserved : "");
        }
    }

    /** The evidence of {@code specs}' training runs, their logs read into {@code traces}, for {@code properties}. */
    static TrainingEvidence of(List<ScenarioSpec> specs, Map<Path, LogTrace> traces, List<Property> properties,
                               LogFormat format) throws BadInputException {
        Set<Path> logs = new LinkedHashSet<>();
        specs.forEach(s -> logs.addAll(s.logs()));
        // a log of a labelled folder is in both scenarios, each taking its own runs: count each run once
        Map<Path, Set<Integer>> counted = new HashMap<>();
        List<LogTrace.Run> runs = new ArrayList<>();
        for (ScenarioSpec s : specs) {
            for (Path log : s.logs()) {
                LogTrace trace = traces.get(log);
                if (trace == null) {
                    continue;
                }
                for (LogTrace.Run r : trace.runs()) {
                    if (!r.pairs().isEmpty() && s.runs().selects(r.violated())
                            && counted.computeIfAbsent(log, k -> new HashSet<>()).add(r.index())) {
                        runs.add(r);
                    }
                }
            }
        }
        List<PropertyRuns> tally = new ArrayList<>();
        for (Property p : properties) {
            int violated = (int) runs.stream().filter(r -> r.violated(p.id())).count();
            int unobserved = (int) runs.stream().filter(r -> !r.timing().observed(p.id())).count();
            tally.add(new PropertyRuns(p.id(), runs.size(), violated, unobserved));
        }
        return new TrainingEvidence(UnseenNames.check(properties, vocabulary(logs, format)), tally);
    }

    /**
     * The names {@code logs} hold: every record of each, read once more in {@code format} (the abstraction's: a ROS 2
     * recording's records are those its topic rules map), without the pipeline.
     */
    public static Vocabulary vocabulary(Collection<Path> logs, LogFormat format) throws BadInputException {
        Vocabulary seen = new Vocabulary();
        for (Path log : logs) {
            try (RecordSource source = format.read(log, RecordSink.of(seen::accept, p -> { }))) {
                source.drain();
            } catch (IOException e) {
                throw BadInputException.cannotRead(log, e);
            }
        }
        return seen;
    }
}
