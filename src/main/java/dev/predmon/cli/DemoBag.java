package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.Learning;
import dev.predmon.rosbag.BagMessage;
import dev.predmon.rosbag.McapWriter;
import dev.predmon.simulate.Nav2Recording;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.SimRun;
import dev.predmon.simulate.Simulator;
import dev.predmon.simulate.TruthWriter;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The demo on ROS 2 recordings ({@code demo --format mcap}): its runs recorded as a robot on nav2 records them, an
 * MCAP file that grows chunk by chunk as {@code ros2 bag record} writes it, watched with models of the built-in
 * {@code nav2} abstraction.
 */
final class DemoBag {

    /** The models {@code demo --format mcap} uses when {@code --models} is not given. */
    static final Path MODELS = Path.of("models-nav2");
    /** Training runs per scenario when there are no recordings to learn from. */
    private static final int TRAINING_RUNS = 4;

    private DemoBag() {
    }

    /** The built-in {@code nav2}. */
    static Abstraction nav2() {
        return AbstractionFiles.builtin("nav2").orElseThrow();
    }

    /**
     * Learns {@code models} with {@code nav2}: from {@code logs} when given, else from runs of every scenario simulated
     * and recorded as MCAP files into {@code work/training}.
     */
    static void learn(PrintWriter out, Path models, Path logs, Path work) throws IOException, BadInputException {
        Path from = logs;
        if (from == null) {
            from = work.resolve("training");
            for (Scenario s : Scenario.values()) {
                Path dir = Files.createDirectories(from.resolve(s.id()));
                for (long seed = 1; seed <= TRAINING_RUNS; seed++) {
                    SimRun run = Simulator.run(s, seed, SimOptions.defaults());
                    SimulatedBags.write(dir.resolve(s.id() + "-" + seed + ".mcap"), List.of(run),
                            SimulatedBags.Form.MCAP, TruthWriter.toJson(run.truth()) + "\n");
                }
                TruthWriter.writeScenario(s, dir);
            }
            out.println("no models in " + models + ": learning them with nav2 from " + TRAINING_RUNS
                    + " simulated runs of each scenario, recorded as MCAP files in " + from);
        } else {
            out.println("no models in " + models + ": learning them with nav2 from " + from);
        }
        out.flush();
        Learning.learnAndWrite(from, models, nav2(), l -> { });
    }

    /**
     * Records {@code run} into {@code file} as nav2 would, {@code speed} times faster than it happened: each message
     * written when it is due, and the chunk ended (written to the file) whenever the recorder then has to wait.
     */
    static void record(SimRun run, Path file, double speed) {
        List<BagMessage> messages = Nav2Recording.of(run);
        try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(file));
             McapWriter w = new McapWriter(out, McapWriter.Compression.ZSTD, 1 << 20)) {
            Map<String, Integer> channels = new HashMap<>();
            long first = messages.isEmpty() ? 0 : messages.get(0).logTimeNanos();
            long start = System.nanoTime();
            for (int i = 0; i < messages.size(); i++) {
                BagMessage m = messages.get(i);
                int c = channels.computeIfAbsent(m.topic(), t -> w.channel(t, m.type()));
                w.write(c, m.logTimeNanos(), m.fields());
                if (i + 1 < messages.size() && messages.get(i + 1).logTimeNanos() > m.logTimeNanos()) {
                    w.flush();
                    long due = start + (long) ((messages.get(i + 1).logTimeNanos() - first) / speed);
                    long left;
                    while ((left = due - System.nanoTime()) > 0) {
                        Thread.sleep(left / 1_000_000, (int) (left % 1_000_000));
                    }
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt(); // the recording stops here, as a recorder that is stopped does
        }
    }
}
