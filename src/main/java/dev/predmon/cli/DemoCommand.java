package dev.predmon.cli;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.files.AtomicFiles;
import dev.predmon.learn.Learning;
import dev.predmon.live.Board;
import dev.predmon.live.LiveServer;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.TickSeconds;
import dev.predmon.monitor.WatchedLog;
import dev.predmon.simulate.RealtimeWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.SimRun;
import dev.predmon.simulate.Simulator;
import dev.predmon.watch.Stamp;
import dev.predmon.watch.WatchSession;
import dev.predmon.watch.WatchSettings;
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
import java.time.Instant;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.Stream;

/**
 * {@code predmon demo}: the main job on a fresh machine. A faulty ({@code depleted}) run is simulated live into a
 * log file while the predictive monitor follows it, exactly as {@code watch} does; the warning and then the safety
 * monitor's violation are shown as they happen, with the lead between them. Then a nominal ({@code recharge}) run
 * ends without a warning.
 */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = {"Watch a simulated 'depleted' run live (sped up) and see the warning arrive before the "
                + "safety violation, then a 'recharge' run that ends without a warning. Uses the models in "
                + "--models, learning them from --logs first if there are none.",
                "With --format mcap the runs are recorded as a robot on ROS 2 navigation records them, an MCAP file "
                        + "growing chunk by chunk, and watched with models of the built-in nav2 abstraction "
                        + "(models-nav2, learned from simulated recordings first if there are none).",
                "Exit 0 when both runs behave as expected, 1 otherwise."})
final class DemoCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--models", paramLabel = "DIR", description = "Models (default: models; with --format mcap, "
            + "models-nav2).")
    Path models;

    @Option(names = "--logs", paramLabel = "DIR",
            description = "Logs to learn from when --models holds no models (default: sample-logs; with --format "
                    + "mcap, recordings of simulated runs).")
    Path logs;

    @Option(names = "--format", paramLabel = "yarp|mcap", defaultValue = "yarp",
            description = "What the runs are written as: a YARP monitor log, or an MCAP recording of nav2's topics "
                    + "(default: ${DEFAULT-VALUE}).")
    String format;

    @Option(names = "--seconds", paramLabel = "S", defaultValue = "15",
            description = "Wall-clock seconds each run takes; sets the speed-up (default: ${DEFAULT-VALUE}).")
    double seconds;

    @Option(names = "--depleted-seed", defaultValue = "9001", description = "Seed of the faulty run (default: ${DEFAULT-VALUE}).")
    long depletedSeed;

    @Option(names = "--recharge-seed", defaultValue = "9002", description = "Seed of the nominal run (default: ${DEFAULT-VALUE}).")
    long rechargeSeed;

    @Option(names = "--work", paramLabel = "DIR", description = "Where to write the live logs (default: a new temporary directory).")
    Path work;

    @Mixin
    LiveViewOptions liveView;

    @Option(names = "--wait-viewer", paramLabel = "S", defaultValue = "30",
            description = "With --http: wait at most S seconds for a browser to open the page before the first run "
                    + "(default: ${DEFAULT-VALUE}).")
    double waitViewer;

    @Option(names = "--linger", paramLabel = "S", defaultValue = "60",
            description = "With --http: keep the page up S seconds after the runs (default: ${DEFAULT-VALUE}).")
    double linger;

    @Override
    public Integer call() throws Exception {
        if (!(seconds > 0) || Double.isInfinite(seconds)) {
            throw new ParameterException(spec.commandLine(), "--seconds must be a positive number, got " + seconds);
        }
        boolean bags = switch (format) {
            case "yarp" -> false;
            case "mcap" -> true;
            default -> throw new ParameterException(spec.commandLine(), "--format must be yarp or mcap, got '" + format
                    + "'");
        };
        PrintWriter out = spec.commandLine().getOut();
        if (models == null) {
            models = bags ? DemoBag.MODELS : Path.of("models");
        }
        Path dir = work != null ? Files.createDirectories(work) : Files.createTempDirectory("predmon-demo-");
        try {
            return run(out, bags, dir);
        } finally {
            if (work == null) {
                removeTree(dir); // a directory of its own: nothing of it is left behind
            }
        }
    }

    private int run(PrintWriter out, boolean bags, Path dir) throws Exception {
        if (!Files.isRegularFile(models.resolve(ModelStore.INDEX))) {
            if (bags) {
                DemoBag.learn(out, models, logs, dir);
            } else {
                Path from = logs != null ? logs : Path.of("sample-logs");
                out.println("no models in " + models + ": learning them from " + from);
                out.flush();
                Learning.learnAndWrite(from, models, AbstractionFiles.defaults(), l -> { });
            }
        }
        Optional<Path> stored = ModelStore.storedAbstraction(models);
        Abstraction abstraction = stored.isPresent() ? AbstractionFiles.load(stored.get()) : AbstractionFiles.defaults();
        if (bags && abstraction.topicRules().isEmpty()) {
            throw new ParameterException(spec.commandLine(), "--format mcap: the models in " + models + " were learned"
                    + " with '" + abstraction.name() + "', which maps no ROS 2 topic; give --models a directory of "
                    + "models learned with --abstraction nav2 (or one without models, to learn them)");
        }
        ModelSet set = ModelStore.read(models, abstraction);
        out.println("predmon demo: " + set.models().size() + " learned machines in " + models + " ("
                + String.join(", ", set.index().scenarios().stream()
                .map(s -> s.name() + (s.faulty() ? " faulty" : " nominal")).toList()) + ")");
        Board board = liveView.board(set, abstraction, true, List.of("the demo's runs, written into " + dir));
        boolean depletedOk;
        boolean rechargeOk;
        try (LiveServer server = liveView.start(out, board)) {
            if (server != null) {
                LiveDemo.awaitViewer(out, board, server, waitViewer);
            }
            depletedOk = live(out, set, abstraction, dir, Scenario.DEPLETED, depletedSeed, board, bags);
            rechargeOk = live(out, set, abstraction, dir, Scenario.RECHARGE, rechargeSeed, board, bags);
            out.println(depletedOk && rechargeOk
                    ? "demo done: the faulty run was predicted before its violation; the nominal run raised no warning"
                    : "demo done, but not as expected: see above");
            out.flush();
            if (server != null) {
                LiveDemo.linger(out, server, linger);
            }
        }
        return depletedOk && rechargeOk ? ExitCodes.OK : ExitCodes.WARNING;
    }

    /**
     * Simulates one run into a file on a writer thread while a watch session follows it; whether it behaved as
     * expected. With a live view ({@code board} not null) the run's log gets a tile.
     */
    private boolean live(PrintWriter out, ModelSet set, Abstraction abstraction, Path dir, Scenario scenario, long seed,
                         Board board, boolean bags) throws IOException, InterruptedException {
        SimRun run = Simulator.run(scenario, seed, SimOptions.defaults());
        double duration = run.truth().endTime() - run.events().get(0).time();
        double speed = Math.max(1.0, duration / seconds);
        Path log = dir.resolve(scenario.id() + "-" + seed + (bags ? ".mcap" : ".log"));
        Files.deleteIfExists(log);
        out.printf(Locale.ROOT, "%nrun: a '%s' run (%s, seed %d), %.0f s of robot time played at %.1fx into %s%n",
                scenario.id(), scenario.faulty() ? "faulty" : "nominal", seed, duration, speed, log);
        if (bags) {
            out.println("  recorded as nav2 records it: /battery_state and the navigate_to_pose and dock_robot action "
                    + "status, in MCAP chunks");
        }
        out.flush();
        // Followed as watch follows a log, its events printed with the seconds since the run began.
        WatchSettings settings = new WatchSettings(false, true, false, false, Stamp.since(Instant.now()), 0,
                TickSeconds.NONE);
        AtomicReference<Throwable> failed = new AtomicReference<>();
        Thread writer = new Thread(() -> {
            if (bags) {
                DemoBag.record(run, log, speed);
            } else {
                write(run, log, speed);
            }
        }, "predmon-demo-writer");
        writer.setDaemon(true);
        writer.setUncaughtExceptionHandler((t, e) -> failed.set(e)); // rethrown below, not printed by the thread
        try (WatchSession session = new WatchSession(out, spec.commandLine().getErr(), settings, null, board,
                abstraction, p -> false);
             Fleet fleet = new Fleet(set, abstraction, 0, abstraction.confirm(), session)) {
            WatchedLog watched = fleet.add(log);
            writer.start();
            while (writer.isAlive()) {
                if (!fleet.poll()) {
                    Thread.sleep(5);
                }
            }
            writer.join();
            rethrow(failed.get());
            fleet.drain();
            return verdict(out, scenario, watched.monitor());
        }
    }

    /** Writes the run's log in place as it goes (the watcher tails it); a failure names the log. */
    private static void write(SimRun run, Path log, double speed) {
        Writer opened;
        try {
            opened = Files.newBufferedWriter(log, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e); // it names the file, and nothing was written
        }
        try (Writer w = opened) {
            new RealtimeWriter(run, SimOptions.defaults(), w, speed).run();
        } catch (IOException e) {
            throw new UncheckedIOException(AtomicFiles.stoppedInPlace(log, e));
        } catch (UncheckedIOException e) {
            throw new UncheckedIOException(AtomicFiles.stoppedInPlace(log, e.getCause()));
        }
    }

    /** What the writer thread failed with, on the command's thread, so the one error handler reports it. */
    private static void rethrow(Throwable e) throws IOException {
        if (e == null) {
            return;
        }
        if (e instanceof UncheckedIOException u) {
            throw u.getCause();
        }
        if (e instanceof RuntimeException r) {
            throw r;
        }
        if (e instanceof Error err) {
            throw err;
        }
        throw new IllegalStateException("the demo's log writer failed", e);
    }

    /** Deletes the demo's own temporary directory and what it wrote there. */
    private static void removeTree(Path dir) throws IOException {
        try (Stream<Path> files = Files.walk(dir)) {
            for (Path f : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(f);
            }
        }
    }

    private static boolean verdict(PrintWriter out, Scenario scenario, PredictiveMonitor m) {
        MonitorEvent.Warning w = m.warning().orElse(null);
        MonitorEvent.Violation v = m.violation().orElse(null);
        boolean ok;
        if (scenario.faulty()) {
            ok = w != null && v != null && w.time() < v.time();
            out.println(ok ? String.format(Locale.ROOT, "  => predicted %.1f s ahead: warning at %s %.1f%%, "
                    + "violation at %.1f%%", v.time() - w.time(), w.property(), w.value(), v.value())
                    : "  => the warning did not come before the violation");
        } else {
            ok = w == null && v == null;
            out.println(ok ? "  => run ended with no warning and no violation" : "  => unexpected warning or violation");
        }
        out.flush();
        return ok;
    }
}
