package dev.predmon.learn;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunLabel;
import dev.predmon.pipeline.Traces;
import dev.predmon.property.Bound;
import dev.predmon.ros2.Recordings;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * A folder of recordings not sorted into scenarios (named by date, say): every {@code *.log} and {@code *.txt}
 * file under it, in subfolders too, is one run, labelled by the abstraction's safety monitor. Runs that violate
 * the property form the faulty scenario {@value #VIOLATING}, the others the nominal scenario {@value #SAFE}; the
 * learner then splits each into conflict-free groups as for any scenario.
 */
public final class RecordingFolder {

    /** The faulty scenario of a labelled folder: runs the safety monitor saw violate the property. */
    public static final String VIOLATING = "violating";
    /** The nominal scenario of a labelled folder: runs in which the property held to the end. */
    public static final String SAFE = "safe";

    private RecordingFolder() {
    }

    /** Whether {@code name} is a log file of a recording folder. */
    static boolean isLog(Path file) {
        String name = file.getFileName().toString();
        return (name.endsWith(".log") || name.endsWith(".txt")) && Files.isRegularFile(file);
    }

    /** The recordings under {@code dir}, sorted by path; a rosbag2 folder is one, the files in it none. */
    public static List<Path> logs(Path dir) throws BadInputException {
        try (Stream<Path> s = Files.walk(dir)) {
            List<Path> found = s.filter(p -> !p.equals(dir) && (isLog(p) || Recordings.isRecording(p))).sorted()
                    .toList();
            List<Path> bagFolders = found.stream().filter(Files::isDirectory).toList();
            return found.stream().filter(p -> bagFolders.stream().noneMatch(b -> !b.equals(p) && p.startsWith(b)))
                    .toList();
        } catch (IOException e) {
            throw new BadInputException(dir + ": cannot list: " + e.getMessage());
        }
    }

    /**
     * The two scenarios of a recording folder, labelled run by run by the safety monitor (a log holding a safe run
     * and a violating one is in both, each taking its own runs); a scenario without runs is left out.
     */
    static List<ScenarioSpec> scenarios(Path dir, Abstraction abstraction) throws BadInputException {
        Bound rule = abstraction.safety().orElseThrow(() -> new BadInputException(dir
                + ": a folder of recordings is labelled by the safety monitor, and abstraction '" + abstraction.name()
                + "' has none; give it a \"safety\" property or sort the logs into <scenario>/scenario.json folders"));
        List<Path> violating = new ArrayList<>();
        List<Path> safe = new ArrayList<>();
        for (Path log : logs(dir)) {
            LogTrace trace;
            try {
                trace = Traces.read(log, abstraction);
            } catch (IOException e) {
                throw BadInputException.cannotRead(log, e);
            }
            if (trace.runs().stream().anyMatch(LogTrace.Run::violated)) {
                violating.add(log);
            }
            if (trace.runs().stream().anyMatch(r -> !r.violated())) {
                safe.add(log);
            }
        }
        List<ScenarioSpec> specs = new ArrayList<>();
        if (!safe.isEmpty()) {
            specs.add(new ScenarioSpec(SAFE, false, "runs in which '" + rule.name()
                    + "' held to the end (labelled by the safety monitor)", List.copyOf(safe), RunLabel.SAFE));
        }
        if (!violating.isEmpty()) {
            specs.add(new ScenarioSpec(VIOLATING, true, "runs that violated '" + rule.name()
                    + "' (labelled by the safety monitor)", List.copyOf(violating), RunLabel.VIOLATING));
        }
        return specs;
    }
}
