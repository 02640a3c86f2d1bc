package dev.predmon.bench;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.learn.LearnedModels;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.mealy.MealyAlphabet;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.parse.LogFormat;
import dev.predmon.parse.RecordSink;
import dev.predmon.parse.RecordSource;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

/**
 * Batch throughput of the whole offline path on one large generated log: parse, abstract, compact and match
 * (a {@link PredictiveMonitor} with the learned models, restarted at each run boundary as a rotated log would
 * restart it, so the models keep matching instead of being eliminated once for the whole file). Compared with
 * {@code grep -c intercepted} on the same file, the floor of any line-by-line reader.
 *
 * <p>Then the user's view, side by side on the same file: {@code predmon classify} as a whole process (a child JVM
 * started with this JVM's binary and class path and no JVM flags) against {@code grep -c}, with the child's wall
 * time and peak resident memory ({@code VmHWM} of {@code /proc/<pid>/status}, polled every few milliseconds while
 * it runs; the high-water mark only grows, so at most the last poll interval is missed).
 */
final class BatchBench {

    /**
     * @param bytes        the file's size
     * @param records      records parsed
     * @param seconds      in-process times of the measured passes, sorted
     * @param grepSeconds  times of {@code grep -c intercepted}, sorted; empty if grep could not be run
     * @param grepCount    what grep counted (as a check: it equals {@code records})
     * @param classifySeconds whole-process {@code classify} wall times, sorted
     * @param classifyPeakKb  peak resident memory of each {@code classify} child, kB, sorted; -1 if unknown
     */
    // Arrays: sorted samples for percentiles; a result is printed, never compared or hashed.
    @SuppressWarnings("ArrayRecordComponent")
    record Result(long bytes, long records, double[] seconds, double[] grepSeconds, long grepCount,
                  double[] classifySeconds, long[] classifyPeakKb) {
        double mbPerSecond(double s) {
            return bytes / 1e6 / s;
        }

        double median() {
            return BatchBench.median(seconds);
        }

        double recordsPerSecond() {
            return records / median();
        }
    }

    private BatchBench() {
    }

    static double median(double[] sorted) {
        int n = sorted.length;
        return n == 0 ? Double.NaN : n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }

    static Result run(Abstraction abstraction, List<LearnedScenario> learned, long megabytes, int repeats, Path dir)
            throws Exception {
        ModelSet models = LearnedModels.modelSet(learned, abstraction);
        Path file = Files.createTempFile(dir, "predmon-batch", ".log");
        Path modelDir = Files.createTempDirectory(dir, "predmon-batch-models");
        try {
            BenchData.bigLog(file, megabytes * 1_000_000L);
            ModelStore.write(modelDir, LearnedModels.index(learned, abstraction),
                    LearnedModels.dots(learned, MealyAlphabet.inputs(abstraction)), abstraction.canonicalJson());
            long size = Files.size(file);
            double[] seconds = new double[repeats];
            long records = 0;
            for (int i = 0; i < repeats + 1; i++) { // the first pass warms the JIT and the page cache up
                long start = System.nanoTime();
                records = once(file, abstraction, models);
                double s = (System.nanoTime() - start) / 1e9;
                if (i > 0) {
                    seconds[i - 1] = s;
                }
            }
            Arrays.sort(seconds);
            List<Double> grep = new ArrayList<>();
            List<Double> classify = new ArrayList<>();
            List<Long> peaks = new ArrayList<>();
            long grepCount = -1;
            String java = ProcessHandle.current().info().command().orElse("java");
            for (int i = 0; i < repeats; i++) { // alternated, so that both see the same load
                long start = System.nanoTime();
                Process p = new ProcessBuilder("grep", "-c", "intercepted", file.toString()).redirectErrorStream(true).start();
                String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.US_ASCII).trim();
                if (p.waitFor(60, TimeUnit.SECONDS) && p.exitValue() == 0) {
                    grep.add((System.nanoTime() - start) / 1e9);
                    grepCount = Long.parseLong(out);
                }
                start = System.nanoTime();
                Process c = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), "dev.predmon.cli.Main",
                        "classify", "--log", file.toString(), "--models", modelDir.toString())
                        .redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectError(ProcessBuilder.Redirect.DISCARD)
                        .start();
                long peak = -1;
                while (!c.waitFor(5, TimeUnit.MILLISECONDS)) {
                    peak = Math.max(peak, peakKb(c.pid()));
                }
                classify.add((System.nanoTime() - start) / 1e9);
                peaks.add(peak);
            }
            return new Result(size, records, seconds, sorted(grep), grepCount, sorted(classify),
                    peaks.stream().mapToLong(Long::longValue).sorted().toArray());
        } finally {
            Files.deleteIfExists(file);
            try (Stream<Path> files = Files.list(modelDir)) {
                for (Path f : files.toList()) {
                    Files.deleteIfExists(f);
                }
            }
            Files.deleteIfExists(modelDir);
        }
    }

    private static double[] sorted(List<Double> values) {
        return values.stream().mapToDouble(Double::doubleValue).sorted().toArray();
    }

    /** {@code VmHWM} of a running process in kB, or -1 (not Linux, or the process is gone). */
    private static long peakKb(long pid) {
        try {
            for (String line : Files.readAllLines(Path.of("/proc", Long.toString(pid), "status"))) {
                if (line.startsWith("VmHWM:")) {
                    return Long.parseLong(line.replaceAll("[^0-9]", ""));
                }
            }
        } catch (IOException | RuntimeException e) {
            return -1; // the child exited between two polls: its earlier readings stand
        }
        return -1;
    }

    private static long once(Path file, Abstraction abstraction, ModelSet models) throws IOException {
        PredictiveMonitor monitor = new PredictiveMonitor(models, abstraction, 0, e -> {
        });
        double[] last = {Double.NEGATIVE_INFINITY};
        long[] records = {0};
        try (RecordSource source = LogFormat.yarp().read(file, RecordSink.of(r -> {
            if (r.time() < last[0]) {
                monitor.restart("next run");
            }
            last[0] = r.time();
            records[0]++;
            monitor.accept(r);
        }, p -> { }))) {
            source.drain();
        }
        monitor.endOfInput();
        return records[0];
    }
}
