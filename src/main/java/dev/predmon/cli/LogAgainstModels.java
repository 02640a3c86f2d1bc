package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.parse.LogReader;
import dev.predmon.parse.ParseProblem;
import dev.predmon.pipeline.Evidence;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.Traces;
import dev.predmon.replay.LogReplay;
import dev.predmon.replay.RecordTaken;
import dev.predmon.replay.ReplayedLog;
import dev.predmon.ros2.Recordings;
import picocli.CommandLine.MissingParameterException;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * The options of a command that judges one log against the learned models ({@code watch}, {@code verify},
 * {@code classify}, {@code explain}): {@code --log}, {@code --json}, {@code --models}, {@code --abstraction},
 * {@code --tolerance}, and the checks they share, so that one situation gets one message from all four.
 */
final class LogAgainstModels {

    @Spec(Spec.Target.MIXEE)
    CommandSpec spec;

    @Option(names = "--log", paramLabel = "FILE",
            description = "The log. watch takes several: repeat it, or name a directory (its *.log and *.txt files, "
                    + "also those that appear later) or a quoted glob ('logs/robot-*.log').")
    List<Path> logs;

    @Option(names = "--json", description = "Print the result as JSON on stdout (watch: one object per event).")
    boolean json;

    @Option(names = "--models", paramLabel = "DIR", defaultValue = "models",
            description = "Model directory written by 'learn' (default: ${DEFAULT-VALUE}).")
    Path modelsDir;

    @Mixin
    AbstractionOption abstractionOption;

    @Mixin
    ToleranceOption tolerance;

    private Abstraction abstraction;
    private ModelSet models;

    /**
     * The abstraction to read the log with: {@code --abstraction} when given, else the one the models were learned
     * with ({@code models/abstraction.json}), else the default.
     */
    Abstraction abstraction() throws BadInputException {
        if (abstraction == null) {
            abstraction = abstractionOption.loadFor(ModelStore.storedAbstraction(modelsDir));
        }
        return abstraction;
    }

    /** The models, checked against {@link #abstraction()}. */
    ModelSet models() throws BadInputException {
        if (models == null) {
            models = ModelStore.read(modelsDir, abstraction());
        }
        return models;
    }

    /**
     * {@link #abstraction()} as the models were learned with it: with the hysteresis {@code learn} estimated from the
     * training runs' sensor noise, so that the log abstracts as the training logs did.
     */
    Abstraction tuned() throws BadInputException {
        return models().tune(abstraction());
    }

    /**
     * What a command that judges one log starts from: the models, the abstraction tuned for them, and the log read
     * through it.
     */
    record Opened(ModelSet models, Abstraction abstraction, LogTrace trace) {
    }

    /** The models, {@link #tuned()} and the log it reads ({@link #readLog}), parse problems printed to {@code err}. */
    Opened open(PrintWriter err) throws BadInputException, IOException {
        ModelSet set = models();
        Abstraction abstraction = tuned();
        return new Opened(set, abstraction, readLog(abstraction, err));
    }

    /**
     * Checks {@code --log}, reads it with {@code abstraction} through the shared pipeline, refuses a log that gives
     * no evidence (no monitor record, nothing the abstraction maps, a fragment amid other bytes) and prints its parse
     * problems to {@code err}; refuses, after its unmapped messages, a log the abstraction does not fit.
     */
    LogTrace readLog(Abstraction abstraction, PrintWriter err) throws BadInputException, IOException {
        checkLog();
        Path log = log();
        LogTrace trace = Traces.read(log, abstraction);
        Evidence evidence = Evidence.of(trace, abstraction);
        String missing = evidence.missing().or(evidence::fragment).orElse(null);
        if (missing != null) {
            throw new BadInputException(missing);
        }
        Problems.print(err, log, trace);
        String misfit = evidence.misfit().orElse(null);
        if (misfit != null) { // after the unmapped messages by command, which show why
            throw new BadInputException(misfit);
        }
        return trace;
    }

    /**
     * Checks {@code --log} and replays it once through {@code watch}'s monitor ({@link LogReplay}) with the models'
     * default rule, {@code confirm} and the abstraction tuned for them; refuses, as {@link #readLog} does, a log that
     * gives no evidence or that the abstraction does not fit, and prints its parse problems to {@code err}.
     *
     * @param taken  gets every record with its run right after the monitor took it
     * @param detail what the replay keeps of each run
     */
    ReplayedLog replay(PrintWriter err, int confirm, RecordTaken taken, LogReplay.Detail detail)
            throws BadInputException, IOException {
        checkLog();
        ModelSet set = models();
        Abstraction abstraction = tuned();
        ReplayedLog replayed = LogReplay.replay(log(), set, abstraction, tolerance(), confirm,
                PredictiveMonitor.defaultRule(set), taken, detail);
        Evidence evidence = replayed.evidence(abstraction);
        String missing = evidence.missing().or(evidence::fragment).orElse(null);
        if (missing != null) {
            throw new BadInputException(missing);
        }
        Problems.print(err, log(), replayed.problems(), replayed.monitor().unmapped());
        String misfit = evidence.misfit().orElse(null);
        if (misfit != null) { // after the unmapped messages by command, which show why
            throw new BadInputException(misfit);
        }
        return replayed;
    }

    int tolerance() {
        return tolerance.value;
    }

    /** The logs named; {@code --log} is required wherever logs are read ({@code watch --rosbridge} reads none). */
    List<Path> logs() {
        if (logs == null) {
            throw new MissingParameterException(spec.commandLine(), spec.findOption("--log"),
                    "Missing required option: '--log=FILE'");
        }
        return logs;
    }

    /** The one log of verify, classify and explain (watch takes several). */
    Path log() throws BadInputException {
        List<Path> logs = logs();
        if (logs.size() != 1) {
            throw new BadInputException("--log is given " + logs.size() + " times; this command judges one log "
                    + "(watch follows several)");
        }
        return logs.get(0);
    }

    /** Checks that {@code --log} is a readable file; one message per situation, the same from every command. */
    void checkLog() throws BadInputException {
        Path log = log();
        if (!Files.exists(log)) {
            throw new BadInputException(log + ": no such file; expected a log file");
        }
        checkLogIfPresent();
    }

    /**
     * As {@link #checkLog()}, and refuses a whole file that holds no monitor record (a README, a config file): in one
     * line, before anything else is printed. The file is read up to its first record only: a log costs nothing.
     */
    void checkLogHoldsRecords(Abstraction abstraction) throws BadInputException, IOException {
        checkLog();
        Path log = log();
        if (Recordings.isRecording(log)) {
            return; // a ROS 2 recording is read by its own format, which says what is wrong with it
        }
        ParseProblem[] first = {null};
        long[] lines = {0};
        try {
            LogReader.read(log, r -> {
                throw new FirstRecord();
            }, p -> first[0] = first[0] == null ? p : first[0], n -> lines[0] = n);
        } catch (FirstRecord found) {
            return;
        }
        String missing = new Evidence(log, () -> lines[0], 0, 0, 0, Map.of(), abstraction, first[0], 0).missing()
                .orElse(null);
        if (missing != null) {
            throw new BadInputException(missing);
        }
    }

    /** Ends a read at its first record. */
    private static final class FirstRecord extends RuntimeException {
        private static final long serialVersionUID = 1L;

        FirstRecord() {
            super(null, null, false, false);
        }
    }

    /** As {@link #checkLog()}, but a file that does not exist yet is fine ({@code watch} waits for it). */
    void checkLogIfPresent() throws BadInputException {
        Path log = log();
        boolean recording = Recordings.isRecording(log);
        if (Files.isDirectory(log) && !recording) {
            throw new BadInputException(log + ": is a directory; expected a log file or a ROS 2 recording");
        }
        if (Files.exists(log) && !Files.isRegularFile(log) && !recording) {
            throw new BadInputException(log + ": not a regular file; expected a log file");
        }
        if (Files.exists(log) && !Files.isReadable(log)) {
            throw new BadInputException(log + ": permission denied; expected a readable log file");
        }
    }
}
