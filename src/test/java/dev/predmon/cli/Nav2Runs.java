package dev.predmon.cli;

import dev.predmon.rosbag.BagMessage;
import dev.predmon.rosbag.McapWriter;
import dev.predmon.simulate.Nav2Recording;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.SimRun;
import dev.predmon.simulate.Simulator;

import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

/**
 * Simulated runs as nav2 records them: MCAP files written with predmon's writer, and nav2 models learned from a few
 * runs per scenario once per test JVM (deleted when it exits).
 */
final class Nav2Runs {

    private static Path models;

    private Nav2Runs() {
    }

    /** The messages of one simulated run. */
    static List<BagMessage> messages(Scenario scenario, long seed) {
        SimRun run = Simulator.run(scenario, seed, SimOptions.defaults());
        return Nav2Recording.of(run);
    }

    /** Writes {@code messages} to {@code file} as an MCAP recording. */
    static void write(Path file, List<BagMessage> messages) throws IOException {
        try (OutputStream out = Files.newOutputStream(file);
             McapWriter w = new McapWriter(out, McapWriter.Compression.NONE, 64 * 1024)) {
            Map<String, Integer> channels = new HashMap<>();
            for (BagMessage m : messages) {
                int c = channels.computeIfAbsent(m.topic(), t -> w.channel(t, m.type()));
                w.write(c, m.logTimeNanos(), m.fields());
            }
        }
    }

    /** nav2 models learned from seeds 1..4 of every scenario. */
    static synchronized Path models() {
        if (models == null) {
            try {
                Path tmp = Files.createTempDirectory("predmon-nav2-models-");
                Runtime.getRuntime().addShutdownHook(new Thread(() -> delete(tmp)));
                Path logs = tmp.resolve("bags");
                for (Scenario s : Scenario.values()) {
                    Path dir = Files.createDirectories(logs.resolve(s.id()));
                    Files.writeString(dir.resolve("scenario.json"), "{\"faulty\": " + s.faulty()
                            + ", \"description\": \"" + s.id() + "\"}", StandardCharsets.UTF_8);
                    for (long seed = 1; seed <= 4; seed++) {
                        write(dir.resolve(s.id() + "-" + seed + ".mcap"), messages(s, seed));
                    }
                }
                Path m = tmp.resolve("models");
                Cli r = Cli.run("learn", "--abstraction", "nav2", "--logs", logs.toString(), "--models", m.toString());
                if (r.code() != 0) {
                    throw new IllegalStateException("learn exited " + r.code() + ": " + r.err());
                }
                models = m;
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return models;
    }

    private static void delete(Path tree) {
        try (Stream<Path> files = Files.walk(tree)) {
            for (Path f : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(f);
            }
        } catch (IOException e) {
            // a temporary directory is left behind
        }
    }
}
