package dev.predmon.bench;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.parse.LogReader;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * Batch throughput of the whole offline path on one large generated log: parse, abstract, compact and match
 * (a {@link PredictiveMonitor} with the learned models, restarted at each run boundary as a rotated log would
 * restart it, so the models keep matching instead of being eliminated once for the whole file). Compared with
 * {@code grep -c intercepted} on the same file, the floor of any line-by-line reader.
 */
final class BatchBench {

    /**
     * @param bytes      the file's size
     * @param records    records parsed
     * @param seconds    best time over the repetitions
     * @param grepSeconds best time of {@code grep -c intercepted}, or NaN if grep could not be run
     * @param grepCount  what grep counted (as a check: it equals {@code records})
     */
    record Result(long bytes, long records, double seconds, double grepSeconds, long grepCount) {
        double mbPerSecond() {
            return bytes / 1e6 / seconds;
        }

        double recordsPerSecond() {
            return records / seconds;
        }
    }

    private BatchBench() {
    }

    static Result run(Abstraction abstraction, ModelSet models, long megabytes, int repeats, Path dir) throws Exception {
        Path file = Files.createTempFile(dir, "predmon-batch", ".log");
        try {
            BenchData.bigLog(file, megabytes * 1_000_000L);
            long size = Files.size(file);
            double best = Double.MAX_VALUE;
            long records = 0;
            for (int i = 0; i < repeats + 1; i++) { // the first pass warms the JIT and the page cache up
                long start = System.nanoTime();
                records = once(file, abstraction, models);
                double s = (System.nanoTime() - start) / 1e9;
                if (i > 0) {
                    best = Math.min(best, s);
                }
            }
            double grepBest = Double.NaN;
            long grepCount = -1;
            for (int i = 0; i < repeats; i++) {
                long start = System.nanoTime();
                Process p = new ProcessBuilder("grep", "-c", "intercepted", file.toString()).redirectErrorStream(true).start();
                String out = new String(p.getInputStream().readAllBytes()).trim();
                if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0) {
                    break;
                }
                double s = (System.nanoTime() - start) / 1e9;
                grepBest = Double.isNaN(grepBest) ? s : Math.min(grepBest, s);
                grepCount = Long.parseLong(out);
            }
            return new Result(size, records, best, grepBest, grepCount);
        } finally {
            Files.deleteIfExists(file);
        }
    }

    private static long once(Path file, Abstraction abstraction, ModelSet models) throws IOException {
        PredictiveMonitor monitor = new PredictiveMonitor(models, abstraction, 0, e -> {
        });
        double[] last = {Double.NEGATIVE_INFINITY};
        long[] records = {0};
        LogReader.read(file, r -> {
            if (r.time() < last[0]) {
                monitor.restart("next run");
            }
            last[0] = r.time();
            records[0]++;
            monitor.accept(r);
        }, p -> {
        });
        monitor.endOfInput();
        return records[0];
    }
}
