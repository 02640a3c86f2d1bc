package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.files.AtomicFiles;
import dev.predmon.rosbag.BagMessage;
import dev.predmon.rosbag.Db3Writer;
import dev.predmon.rosbag.McapWriter;
import dev.predmon.simulate.Day;
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
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * {@code simulate --format mcap|sqlite3}: the simulated runs as a robot on nav2 records them ({@link Nav2Recording}),
 * written as an MCAP file (zstd chunks, as {@code ros2 bag record} writes them) or a rosbag2 sqlite3 file, each with
 * its truth sidecar. A file is written whole beside its place and moved there, so it is complete or not there.
 */
final class SimulatedBags {

    /** What {@code --format} names. */
    enum Form {
        YARP(".log"), MCAP(".mcap"), SQLITE3(".db3");

        final String extension;

        Form(String extension) {
            this.extension = extension;
        }

        static Form of(String name) {
            return switch (name.toLowerCase(Locale.ROOT)) {
                case "yarp" -> YARP;
                case "mcap" -> MCAP;
                case "sqlite3", "db3" -> SQLITE3;
                default -> throw new IllegalArgumentException("--format must be yarp, mcap or sqlite3, got '" + name
                        + "'");
            };
        }
    }

    /** Records a chunk holds before it is written: about a minute of the simulated robot's topics. */
    static final int CHUNK_BYTES = 16 * 1024;

    private SimulatedBags() {
    }

    /**
     * The runs as nav2 records them: with {@code out}, one file holding {@code n} runs one after another (the
     * scenarios of {@code day} in turn); else one file per run in {@code outDir}, seeds {@code seed..seed+n-1}.
     */
    static void write(List<Scenario> day, SimOptions options, Form form, Path out, Path outDir, long seed, int n,
                      PrintWriter err) throws IOException, BadInputException {
        if (out != null) {
            Path parent = out.toAbsolutePath().getParent();
            if (parent != null) {
                Files.createDirectories(parent);
            }
            List<SimRun> all = Day.simulate(day, seed, n, options);
            StringBuilder truths = new StringBuilder();
            for (SimRun run : all) {
                truths.append(truths.length() == 0 ? "[\n" : ",\n").append(TruthWriter.toJson(run.truth()));
            }
            write(out, all, form, n == 1 ? TruthWriter.toJson(all.get(0).truth()) + "\n"
                    : truths.append("\n]\n").toString());
            err.println("simulate: wrote " + n + " run" + (n == 1 ? "" : "s") + " to " + out);
            return;
        }
        Scenario s = day.get(0);
        String other = TruthWriter.otherScenario(s, outDir);
        if (other != null) {
            throw new BadInputException(other);
        }
        Files.createDirectories(outDir);
        for (long k = seed; k < seed + n; k++) {
            SimRun run = Simulator.run(s, k, options);
            write(outDir.resolve(s.id() + "-" + k + form.extension), List.of(run), form,
                    TruthWriter.toJson(run.truth()) + "\n");
        }
        TruthWriter.writeScenario(s, outDir);
        err.println("simulate: wrote " + n + " " + s.id() + " runs to " + outDir);
    }

    /** Writes {@code runs}, one after another, to {@code file} in {@code form}, and their truth beside it. */
    static void write(Path file, List<SimRun> runs, Form form, String truth) throws IOException {
        List<BagMessage> messages = Nav2Recording.of(runs);
        Path temporary = file.resolveSibling("." + file.getFileName() + ".part");
        Files.deleteIfExists(temporary);
        try {
            if (form == Form.MCAP) {
                try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(temporary));
                     McapWriter w = new McapWriter(out, McapWriter.Compression.ZSTD, CHUNK_BYTES)) {
                    Map<String, Integer> channels = new HashMap<>();
                    for (BagMessage m : messages) {
                        int c = channels.computeIfAbsent(m.topic(), t -> w.channel(t, m.type()));
                        w.write(c, m.logTimeNanos(), m.fields());
                    }
                }
            } else {
                try (Db3Writer w = new Db3Writer(temporary, false)) {
                    Map<String, Integer> topics = new HashMap<>();
                    for (BagMessage m : messages) {
                        Integer t = topics.get(m.topic());
                        if (t == null) {
                            t = w.topic(m.topic(), m.type());
                            topics.put(m.topic(), t);
                        }
                        w.write(t, m.logTimeNanos(), m.fields());
                    }
                }
            }
            AtomicFiles.replace(TruthWriter.sidecarOf(file), truth);
            Files.move(temporary, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(temporary);
        }
    }
}
