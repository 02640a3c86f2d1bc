package dev.predmon.cli;

import dev.predmon.support.RealLogs;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * classify gives the verdict watch reaches at the end of the same log: the same exit code on every shipped sample
 * log, on a log of every simulated novelty, and on the public recordings when they are here.
 */
class ClassifyWatchAgreementTest {

    @TempDir
    Path tmp;

    private static List<String> disagreements(List<Path> logs, String models) {
        List<String> differ = new ArrayList<>();
        for (Path log : logs) {
            int classify = Cli.run("classify", "--log", log.toString(), "--models", models).code();
            int watch = Cli.run("watch", "--no-follow", "--log", log.toString(), "--models", models).code();
            if (classify != watch) {
                differ.add(log + ": classify " + classify + ", watch " + watch);
            }
        }
        return differ;
    }

    private static List<Path> files(Path dir, String suffix) throws IOException {
        try (Stream<Path> s = Files.walk(dir)) {
            return s.filter(p -> p.toString().endsWith(suffix)).sorted().toList();
        }
    }

    @Test
    void onEverySampleLog() throws IOException {
        List<Path> logs = files(Path.of("sample-logs"), ".log");
        assertEquals(30, logs.size());
        assertEquals(List.of(), disagreements(logs, "models"));
    }

    @Test
    void onEverySimulatedNovelty() {
        List<List<String>> novelties = List.of(List.of("--aborts", "1"), List.of("--never-arrives", "450"),
                List.of("--grasp", "--grasp-failures", "12"), List.of("--late-turn", "15"), List.of("--noise", "0.5"),
                List.of("--new-location", "garden"), List.of("--no-ticks"), List.of("--slowdown", "1.5"),
                List.of("--drain-factor", "1.3"), List.of("--runs", "3"),
                List.of("--tick-period", "0.5"), List.of("--stuck", "20", "--aborts", "1"));
        List<Path> logs = new ArrayList<>();
        int n = 0;
        for (List<String> novelty : novelties) {
            for (String scenario : List.of("direct", "recharge", "depleted")) {
                n++;
                Path log = tmp.resolve("n" + n + "-" + scenario + ".log");
                List<String> args = new ArrayList<>(List.of("simulate", "--scenario", scenario, "--seed",
                        Integer.toString(700 + n), "--out", log.toString()));
                args.addAll(novelty);
                Cli r = Cli.run(args.toArray(String[]::new));
                assertEquals(0, r.code(), novelty + " " + scenario + ": " + r.err());
                logs.add(log);
            }
        }
        assertEquals(List.of(), disagreements(logs, "models"));
    }

    @Test
    void onThePublicRecordings() throws IOException {
        Assumptions.assumeTrue(Files.isDirectory(RealLogs.DIR), "the real recordings are not here");
        Path models = tmp.resolve("real-models");
        Cli learned = Cli.run("learn", "--logs", RealLogs.DIR.toString(), "--abstraction", "scope-fetch", "--models",
                models.toString());
        assertEquals(0, learned.code(), learned.err());
        List<Path> logs = files(RealLogs.DIR, ".txt");
        assertTrue(logs.size() >= 40, "the 43 recordings: " + logs.size());
        assertEquals(List.of(), disagreements(logs, models.toString()));
    }
}
