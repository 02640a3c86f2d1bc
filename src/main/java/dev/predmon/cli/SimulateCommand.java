package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.files.AtomicFiles;
import dev.predmon.simulate.Day;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.PropertyLimits;
import dev.predmon.simulate.RealtimeWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.SimRun;
import dev.predmon.simulate.Simulator;
import dev.predmon.simulate.TruthWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

/**
 * {@code predmon simulate}: writes YARP monitor logs of the case study, one run per seed, for learning
 * ({@code --runs N --out-dir DIR}), for evaluation ({@code --out FILE} plus its {@code .truth.json}) or for a
 * live monitor to tail ({@code --realtime}). {@link NoveltyOptions} add what a real robot does and default runs never
 * show; {@code --runs-per-log K} puts several runs in each log.
 */
@Command(name = "simulate", mixinStandardHelpOptions = true,
        description = {"Simulate the robot case study (behaviour tree, skills, battery and navigation components) "
                + "and write the YARP monitor log of a run of the chosen scenario.",
                "Scenarios: direct (nominal), recharge (nominal, recharges on the way), depleted (faulty: "
                        + "the battery falls below 20%% before the charging station).",
                "Novelties a real robot shows and default runs do not (blocked paths that abort, a navigation that "
                        + "never arrives, a grasp that keeps failing, a late turn to the charger, a slower robot, "
                        + "another tick rate, a new place, several runs per log without Tick records) keep each "
                        + "run's scenario and are told in the truth sidecar, which also says which properties each "
                        + "run violated and where; docs/simulate.md describes them."})
public final class SimulateCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--scenario", required = true, paramLabel = "direct|recharge|depleted[,...]",
            description = "The story to simulate. With --out and --runs (or --runs-per-log), a comma-separated list: "
                    + "the log holds the runs one after another, the list taken in turn (a robot's day: "
                    + "'direct,depleted').")
    String scenario;

    @Option(names = "--seed", defaultValue = "1", description = "Seed of the run (first seed with --runs); "
            + "the same seed gives the same log byte for byte. Default: ${DEFAULT-VALUE}.")
    long seed;

    @Option(names = "--out", paramLabel = "FILE",
            description = "Write the log here (and FILE.truth.json beside it) instead of to standard output.")
    Path out;

    @Option(names = "--runs", paramLabel = "N", description = "Simulate N runs, seeds seed..seed+N-1: with --out-dir "
            + "one log each; with --out one log holding them one after another (its tick counter starting again "
            + "with every run, as the real monitor's does).")
    Integer runs;

    @Option(names = "--out-dir", paramLabel = "DIR",
            description = "Write DIR/<scenario>-<seed>.log for each run and DIR/scenario.json.")
    Path outDir;

    @Option(names = "--realtime", description = "Append records at the pace of the simulated clock, flushing "
            + "after each, so a live monitor can tail the log.")
    boolean realtime;

    @Option(names = "--speed", defaultValue = "1", paramLabel = "X",
            description = "With --realtime: simulated seconds per wall-clock second. Default: ${DEFAULT-VALUE}.")
    double speed;

    @Option(names = "--early-warning", defaultValue = "50", paramLabel = "PERCENT",
            description = "Battery level at or below which the robot goes to charge. Default: ${DEFAULT-VALUE}.")
    double earlyWarning;

    @Option(names = "--epoch", description = "Unix epoch time stamps instead of seconds since the start.")
    boolean epoch;

    @Option(names = "--raw-lines", description = "Print the INFO raw-bottle line before each record.")
    boolean rawLines;

    @Option(names = "--late-replies", defaultValue = "0", paramLabel = "P",
            description = "Probability that a reply is printed after later records of other connections.")
    double lateReplies;

    @Option(names = "--vocab", description = "Print isAtLocation replies as YARP vocabs 27503/1818845542.")
    boolean vocab;

    @Option(names = "--spaces", description = "Separate the columns by spaces instead of a tab.")
    boolean spaces;

    @Option(names = "--crlf", description = "End lines with CR LF.")
    boolean crlf;

    @Option(names = "--runs-per-log", paramLabel = "K", description = "Each log holds K runs one after another "
            + "(seeds in turn): with --out the log FILE, with --out-dir N logs (--runs N) named after their first "
            + "seed, each with its FILE.truth.json. See --gap and --no-ticks.")
    Integer runsPerLog;

    @Option(names = "--format", defaultValue = "yarp", paramLabel = "yarp|mcap|sqlite3",
            description = "yarp: the YARP monitor's log. mcap, sqlite3: the runs as a robot on ROS 2 navigation (nav2)"
                    + " records them, as an .mcap or a .db3 file (read them with --abstraction nav2); needs --out or"
                    + " --out-dir. Default: ${DEFAULT-VALUE}.")
    String format;

    @Mixin
    NoveltyOptions novelty = new NoveltyOptions();

    @Option(names = "--noise", defaultValue = "0", paramLabel = "SIGMA",
            description = "Gaussian noise of this standard deviation (percentage points) on every battery reading; "
                    + "the tree reacts to the noisy reading, as a real one would. Default: ${DEFAULT-VALUE}.")
    double noise;

    @Option(names = "--navigation-deadline", defaultValue = "400", paramLabel = "TICKS",
            description = "The truth's navigation-in-time: ticks a navigation has to reach its destination. "
                    + "Default: ${DEFAULT-VALUE}.")
    int navigationDeadline;

    @Option(names = "--grasp-attempts", defaultValue = "8", paramLabel = "K",
            description = "The truth's grasp-in-time: closeHand attempts a grasp has to hold. Default: ${DEFAULT-VALUE}.")
    int graspAttempts;

    @Override
    public Integer call() throws IOException, BadInputException {
        Scenario s;
        List<Scenario> day = new ArrayList<>();
        SimOptions options;
        try {
            // Limit 0: a trailing comma is ignored, as it always was; an empty id elsewhere is an error.
            for (String id : scenario.split(",", 0)) {
                day.add(Scenario.fromId(id.strip()));
            }
            s = day.get(0);
            options = new SimOptions(earlyWarning, epoch, rawLines, lateReplies, vocab, spaces, crlf, noise,
                    novelty.novelties(), PropertyLimits.DEFAULT.withNavigationTicks(navigationDeadline)
                    .withGraspAttempts(graspAttempts));
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage(), e);
        }
        checkCombination();
        SimulatedBags.Form form = form();
        boolean dayLog = out != null && (runs != null || runsPerLog != null);
        if (day.size() > 1 && !dayLog) {
            throw new ParameterException(spec.commandLine(),
                    "several scenarios need --out FILE and --runs N (or --runs-per-log K)");
        }
        if (novelty.gap != null && !dayLog && !(outDir != null && runsPerLog != null)) {
            throw new ParameterException(spec.commandLine(),
                    "--gap needs several runs in a log: --runs-per-log K, or --runs N with --out");
        }
        try {
            if (form != SimulatedBags.Form.YARP) {
                SimulatedBags.write(day, options, form, out, outDir, seed,
                        runs != null ? runs : runsPerLog != null ? runsPerLog : 1, spec.commandLine().getErr());
            } else if (dayLog) {
                writeDay(day, options, runs != null ? runs : runsPerLog);
            } else if (outDir != null) {
                writeBatch(s, options);
            } else {
                writeOne(s, options);
            }
        } catch (UncheckedIOException e) {
            throw e.getCause(); // the CLI's error handler reports it: one line, exit 3
        } catch (IllegalStateException e) {
            // No run of this scenario can tell its story with these options (an impossible --early-warning, or
            // novelties that leave a nominal run no way to stay nominal).
            String hint = options.novelties().changesRuns() ? ": with these novelties no run keeps the scenario's "
                    + "outcome; fewer --aborts, a shorter --stuck or --late-turn or a smaller --slowdown or "
                    + "--drain-factor leave room" : "";
            throw new ParameterException(spec.commandLine(), e.getMessage() + hint, e);
        }
        return ExitCodes.OK;
    }

    private SimulatedBags.Form form() {
        SimulatedBags.Form form;
        try {
            form = SimulatedBags.Form.of(format);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage(), e);
        }
        if (form != SimulatedBags.Form.YARP && (realtime || (out == null && outDir == null))) {
            throw new ParameterException(spec.commandLine(), "--format " + format + " needs --out FILE or --out-dir"
                    + " DIR, and cannot be combined with --realtime");
        }
        return form;
    }

    private void checkCombination() {
        if (runs != null && outDir == null && out == null) {
            throw new ParameterException(spec.commandLine(), "--runs needs --out-dir or --out");
        }
        if (runs != null && out != null && realtime) {
            throw new ParameterException(spec.commandLine(), "--runs with --out cannot be combined with --realtime");
        }
        if (runs != null && runs < 1) {
            throw new ParameterException(spec.commandLine(), "--runs must be at least 1, got " + runs);
        }
        if (outDir != null && (out != null || realtime)) {
            throw new ParameterException(spec.commandLine(), "--out-dir cannot be combined with --out or --realtime");
        }
        if (!(speed > 0) || Double.isInfinite(speed)) {
            throw new ParameterException(spec.commandLine(), "--speed must be a positive number, got " + speed);
        }
        if (runsPerLog != null) {
            if (runsPerLog < 1) {
                throw new ParameterException(spec.commandLine(), "--runs-per-log must be at least 1, got " + runsPerLog);
            }
            if (out == null && outDir == null) {
                throw new ParameterException(spec.commandLine(), "--runs-per-log needs --out or --out-dir");
            }
            if (out != null && runs != null) {
                throw new ParameterException(spec.commandLine(), "with --out, --runs already is the number of runs "
                        + "in the log: give --runs or --runs-per-log, not both");
            }
            if (realtime) {
                throw new ParameterException(spec.commandLine(), "--runs-per-log cannot be combined with --realtime");
            }
        }
    }

    private void writeBatch(Scenario s, SimOptions options) throws IOException, BadInputException {
        String other = TruthWriter.otherScenario(s, outDir);
        if (other != null) {
            throw new BadInputException(other);
        }
        Files.createDirectories(outDir);
        int n = runs == null ? 1 : runs;
        int perLog = runsPerLog == null ? 1 : runsPerLog;
        // Evaluation scores novel runs by their truth; a plain batch keeps the files it always had.
        boolean truths = runsPerLog != null || options.novelties().any();
        for (long k = seed; k < seed + (long) n * perLog; k += perLog) {
            Path log = outDir.resolve(s.id() + "-" + k + ".log");
            if (runsPerLog != null) {
                writeDayLog(Day.simulate(List.of(s), k, perLog, options), options, log);
                continue;
            }
            SimRun run = Simulator.run(s, k, options);
            if (truths) {
                writeWithTruth(log, w -> LogWriter.write(run, options, w), TruthWriter.toJson(run.truth()) + "\n");
            } else {
                AtomicFiles.replace(log, w -> LogWriter.write(run, options, w));
            }
        }
        TruthWriter.writeScenario(s, outDir);
        spec.commandLine().getErr().println("simulate: wrote " + n + " " + s.id()
                + (runsPerLog == null ? " runs" : " logs of " + perLog + " runs each") + " to " + outDir);
    }

    /** One log holding {@code count} runs one after another, and a sidecar listing each run's truth. */
    private void writeDay(List<Scenario> scenarios, SimOptions options, int count) throws IOException {
        List<SimRun> day = Day.simulate(scenarios, seed, count, options);
        Path parent = out.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        writeDayLog(day, options, out);
        spec.commandLine().getErr().println("simulate: wrote " + count + " runs one after another to " + out);
    }

    private static void writeDayLog(List<SimRun> day, SimOptions options, Path log) throws IOException {
        StringBuilder truths = new StringBuilder("[");
        for (SimRun run : day) {
            truths.append(truths.length() > 1 ? ",\n" : "\n").append(TruthWriter.toJson(run.truth()));
        }
        writeWithTruth(log, w -> {
            for (SimRun run : day) {
                LogWriter.write(run, options, w);
            }
        }, truths.append("\n]\n").toString());
    }

    /**
     * A log and its truth sidecar, as a pair: both written in full before either replaces its previous file, so a
     * failure leaves both as they were, never a new truth beside the previous log.
     */
    private static void writeWithTruth(Path log, AtomicFiles.Body body, String truth) throws IOException {
        AtomicFiles.replaceBoth(log, body, TruthWriter.sidecarOf(log), w -> w.write(truth));
    }

    private void writeOne(Scenario s, SimOptions options) throws IOException {
        SimRun run = Simulator.run(s, seed, options);
        if (out == null) {
            PrintWriter w = spec.commandLine().getOut();
            emit(run, options, w);
            w.flush();
            return;
        }
        Path parent = out.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        if (!realtime) {
            writeWithTruth(out, w -> LogWriter.write(run, options, w), TruthWriter.toJson(run.truth()) + "\n");
            return;
        }
        // The truth first: the log grows in place while a monitor tails it, and its truth is known from the start.
        TruthWriter.writeTruth(run.truth(), TruthWriter.sidecarOf(out));
        // A live monitor tails this file, so it is written in place as the run goes, not renamed in at the end.
        Writer opened = Files.newBufferedWriter(out, StandardCharsets.UTF_8); // a failure here names the file
        try (Writer w = opened) {
            emit(run, options, w);
        } catch (IOException e) {
            throw AtomicFiles.stoppedInPlace(out, e);
        } catch (UncheckedIOException e) {
            throw AtomicFiles.stoppedInPlace(out, e.getCause());
        }
    }

    private void emit(SimRun run, SimOptions options, Writer w) throws IOException {
        if (realtime) {
            new RealtimeWriter(run, options, w, speed).run();
        } else {
            LogWriter.write(run, options, w);
        }
    }
}
