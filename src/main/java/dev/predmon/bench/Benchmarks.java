package dev.predmon.bench;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.WarningRule;
import dev.predmon.property.Property;
import dev.predmon.property.Response;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;

/**
 * Runs predmon's benchmarks and describes each figure in one line. Not timed unit tests: each benchmark warms
 * up, repeats, and reports what it measured, whether the target is met or not.
 */
public final class Benchmarks {

    /** The benchmarks, as named on the command line. */
    public enum Kind { BATCH, LATENCY, CPU, MEMORY, LEARN, FLEET, BAG }

    /**
     * Sizes.
     *
     * @param batchMegabytes  size of the generated log for the batch benchmark
     * @param latencyRuns     appends measured
     * @param pollMicros      the watcher's pause when nothing was appended
     * @param memoryRecords   records pushed through the monitor
     * @param cpuRecords      records a following watch takes while its CPU time is measured
     * @param learnRuns       runs per scenario, one learning per value
     * @param modelRuns       runs per scenario the monitored models are learned from
     * @param tempDir         where generated logs go
     * @param fleetLogs       fleet sizes: logs watched at once in the fleet benchmark, one measurement each
     * @param fleetSamples    append-to-warning latencies measured per fleet size (at least one per log)
     * @param fleetSeconds    how long the fleet benchmark runs at robot pace, and idle, per fleet size
     * @param fleetPolling    the fleet polls every log ({@code watch --polling}) instead of waiting for notifications
     * @param fleetIdleLogs   logs of the idle fleet whose cost is measured apart (0: none)
     * @param bagMessages     messages in the ROS 2 bag of the bag benchmark
     * @param fleetDir        where the fleet benchmark's logs go
     */
    public record Options(long batchMegabytes, int latencyRuns, long pollMicros, long memoryRecords,
                          long cpuRecords, List<Integer> learnRuns, int modelRuns, Path tempDir, List<Integer> fleetLogs,
                          int fleetSamples, double fleetSeconds, boolean fleetPolling, int fleetIdleLogs,
                          long bagMessages, Path fleetDir) {
    }

    /** What is said of {@code early} logs that warned before the warning's record was appended, if any. */
    static String early(int early) {
        return early == 0 ? "" : f("; %d more warned before the record that raises the warning was appended, so "
                + "gave no sample", early);
    }

    /** {@code dir} and the type of its file system ({@code /dev/shm (tmpfs)}). */
    static String fileSystem(Path dir) {
        try {
            return dir + " (" + Files.getFileStore(dir).type() + ")";
        } catch (IOException e) {
            return dir.toString();
        }
    }

    private Benchmarks() {
    }

    /** Runs {@code kinds} in order, handing each figure's line to {@code out} as soon as it is measured. */
    public static void run(List<Kind> kinds, Options o, Consumer<String> out) throws Exception {
        Abstraction abstraction = AbstractionFiles.defaults();
        ModelSet models = null;
        List<LearnedScenario> learned = null;
        if (kinds.stream().anyMatch(k -> k != Kind.LEARN && k != Kind.BAG)) {
            learned = BenchData.learned(abstraction, o.modelRuns());
            models = BenchData.models(abstraction, learned, o.modelRuns());
            out.accept(f("models: %d machines learned from %d runs per scenario, with their forecast (rule %s)",
                    models.models().size(), o.modelRuns(), PredictiveMonitor.defaultRule(models).id()));
            out.accept(properties(abstraction, models));
        }
        out.accept(f("machine: %d cores, Java %s, max heap %.0f MB", Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.version"), Runtime.getRuntime().maxMemory() / 1e6));
        for (Kind k : kinds) {
            switch (k) {
                case BATCH -> {
                    BatchBench.Result r = BatchBench.run(abstraction, learned, models, o.batchMegabytes(), 5,
                            o.tempDir());
                    double[] t = r.seconds();
                    double mb = r.mbPerSecond(r.median());
                    out.accept(f("batch: parse+abstract+compact+match of %.1f MB (%d records): median %.3f s, %.1f MB/s "
                                    + "(%.1f-%.1f over %d passes after a warm-up pass), %.0f records/s; "
                                    + "target >= 250 MB/s median: %s",
                            r.bytes() / 1e6, r.records(), r.median(), mb, r.mbPerSecond(t[t.length - 1]),
                            r.mbPerSecond(t[0]), t.length, r.recordsPerSecond(), mb >= 250 ? "met" : "MISSED"));
                    double grep = BatchBench.median(r.grepSeconds());
                    double classify = BatchBench.median(r.classifySeconds());
                    out.accept(Double.isNaN(grep) ? "batch: grep could not be run"
                            : f("batch: grep -c intercepted on the same file: median %.3f s, %.1f MB/s (counted %d)",
                            grep, r.mbPerSecond(grep), r.grepCount()));
                    out.accept(f("batch: whole-process 'predmon classify' on the same file, default JVM flags: median "
                                    + "%.3f s wall (%.3f-%.3f), %.1f x grep -c; target within 10x: %s",
                            classify, r.classifySeconds()[0], r.classifySeconds()[r.classifySeconds().length - 1],
                            classify / grep, classify <= 10 * grep ? "met" : "MISSED"));
                    long[] peak = r.classifyPeakKb();
                    double peakMib = peak[peak.length - 1] / 1024.0;
                    out.accept(f("batch: peak RSS of 'predmon classify' (VmHWM): max %.0f MiB over %d runs (min %.0f); "
                                    + "target < 200 MiB: %s", peakMib, peak.length, peak[0] / 1024.0,
                            peak[0] < 0 ? "unknown" : peakMib < 200 ? "met" : "MISSED"));
                }
                case LATENCY -> {
                    ModelSet without = new ModelSet(models.dir(), models.index(), models.models());
                    List<LatencyBench.Result> r = LatencyBench.compare(abstraction, List.of(models, without),
                            o.latencyRuns(), o.pollMicros(), o.tempDir());
                    for (int i = 0; i < r.size(); i++) {
                        LatencyBench.Result x = r.get(i);
                        out.accept(f("latency%s: append of the warning's record -> warning event, %d runs, poll pause "
                                        + "%d us: median %.3f ms, p99 %.3f ms, max %.3f ms (of which the poll that read "
                                        + "it: median %.3f ms, p99 %.3f ms); target p99 < 20 ms: %s",
                                i == 0 ? "" : " without the forecast (thesis's rule, same machines, alternated)",
                                x.millis().length, x.pollMicros(), x.median(), x.p99(), x.max(),
                                LatencyBench.Result.percentile(x.processing(), 0.5),
                                LatencyBench.Result.percentile(x.processing(), 0.99), x.p99() < 20 ? "met" : "MISSED"));
                    }
                    out.accept(f("latency: p99 with the forecast / without: %.2fx; target within 1.5x: %s",
                            r.get(0).p99() / r.get(1).p99(), r.get(0).p99() <= 1.5 * r.get(1).p99() ? "met"
                                    : "MISSED"));
                }
                case CPU -> {
                    WatchCpuBench.Result r = WatchCpuBench.run(abstraction, models, o.cpuRecords(), o.pollMicros(),
                            o.tempDir());
                    out.accept(f("watch cpu per record: a following watch (poll pause %d us) took %d records appended "
                                    + "run by run in %.1f s: %.0f ns of its thread's CPU time per record (%.0f ns of "
                                    + "the whole process's); load average %.1f", o.pollMicros(), r.records(),
                            r.seconds(), r.threadNanos(), r.processNanos(),
                            ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage()));
                }
                case MEMORY -> {
                    MemoryBench.Result r = MemoryBench.run(abstraction, models, o.memoryRecords(), 10);
                    List<String> cpu = new ArrayList<>();
                    List<String> heap = new ArrayList<>();
                    for (int i = 0; i < r.records().length; i++) {
                        cpu.add(f("%.0f", r.cpuNanos()[i]));
                        heap.add(f("%.1f", r.heapMb()[i]));
                    }
                    out.accept(f("watch cpu: ns of CPU per record, per tenth of %d records: %s", o.memoryRecords(),
                            String.join(" ", cpu)));
                    out.accept(f("watch heap: MB in use after GC, per tenth: %s (max heap %.0f MB); after %d records: "
                                    + "%.1f MB", String.join(" ", heap), r.maxHeapMb(),
                            r.records()[r.records().length - 1], r.heapMb()[r.heapMb().length - 1]));
                }
                case FLEET -> {
                    String how = o.fleetPolling() ? f("polling every %d us", o.pollMicros())
                            : "woken by file-change notification";
                    for (FleetBench.Result r : FleetBench.run(abstraction, models, o.fleetLogs(), o.fleetSamples(),
                            o.pollMicros(), o.fleetPolling(), o.fleetSeconds(), o.fleetDir())) {
                        RobotPace.Load p = r.pace();
                        double paceP99 = FleetBench.Result.percentile(p.millis(), 0.99);
                        boolean atPace = p.writtenRate() >= 0.95 * r.paceRate();
                        String pace = atPace
                                ? f("at robot pace (%.0f records/s per log: %.1f written, %.1f read; the writer "
                                + "process %.0f%% of a core)", r.paceRate(), p.writtenRate(), p.readRate(),
                                100 * p.writerCore())
                                : f("NOT at robot pace: the writer fell behind (%.1f of %.0f records/s per log written, "
                                + "%.1f read; the writer process %.0f%% of a core)", p.writtenRate(), r.paceRate(),
                                p.readRate(), 100 * p.writerCore());
                        out.accept(f("fleet: %d log%s in one process, %s: catch-up %.0f ns CPU/record; idle %.1f%% of "
                                        + "a core (following thread %.1f%%); %s %.1f%% of a core, %.0f ns CPU/record, "
                                        + "append->warning median %.3f ms, p99 %.3f ms (%d samples%s); quiet append->warning "
                                        + "median %.3f ms, p99 %.3f ms, max %.3f ms (%d samples%s); logs on %s; load average "
                                        + "%.1f%s", r.logs(),
                                r.logs() == 1 ? "" : "s", how, r.catchUpNanos(), 100 * r.idleCore(),
                                100 * r.idleLoopCore(), pace, 100 * p.core(),
                                p.nanosPerRecord(), FleetBench.Result.percentile(p.millis(), 0.5), paceP99,
                                p.millis().length, early(p.early()), r.percentile(0.5), r.percentile(0.99),
                                r.percentile(1), r.millis().length, early(r.early()), fileSystem(o.fleetDir()),
                                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(),
                                r.logs() < 1000 ? "" : r.logs() < 10_000
                                        ? f("; target idle < 5%% of a core and p99 < 20 ms: %s",
                                        r.idleCore() < 0.05 && r.percentile(0.99) < 20 ? "met" : "MISSED")
                                        : f("; target robot pace within one core and p99 < 20 ms: %s%s",
                                        atPace && p.core() < 1 && paceP99 < 20 ? "met" : "MISSED",
                                        atPace ? "" : " (not measured at robot pace)")));
                    }
                    if (o.fleetIdleLogs() > 0) {
                        IdleFleetBench r = IdleFleetBench.run(new FleetSetup(abstraction, models,
                                o.pollMicros() * 1000, o.fleetPolling(), o.fleetDir()), o.fleetIdleLogs(),
                                o.fleetSeconds());
                        out.accept(f("fleet idle: %d logs of 12 records in one process, %s: %.1f%% of a core "
                                        + "(following thread %.1f%%); heap after GC %.0f MB (%.0f before the fleet, %.1f "
                                        + "KB per log); %d descriptors open (%d before the fleet, limit %d); load "
                                        + "average %.1f", r.logs(), how, 100 * r.core(), 100 * r.loopCore(), r.heapMb(),
                                r.baseHeapMb(), r.kbPerLog(), r.descriptors(), r.baseFds(), r.maxFds(),
                                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage()));
                    }
                }
                case BAG -> {
                    BagBench.Result r = BagBench.run(o.bagMessages(), 3, o.tempDir());
                    double s = BatchBench.median(r.seconds());
                    double y = BatchBench.median(r.yarpSeconds());
                    out.accept(f("bag: read+decode of an MCAP file in zstd chunks, %d messages (battery, action "
                                    + "status, rosout), %.1f MB: median %.3f s over %d passes, %.0f messages/s, %.1f "
                                    + "MB/s", r.messages(), r.bytes() / 1e6, s, r.seconds().length, r.messages() / s,
                            r.bytes() / 1e6 / s));
                    out.accept(f("bag: beside it, the YARP parser on a log of the same size (%d records): median %.3f "
                                    + "s, %.0f records/s, %.1f MB/s", r.yarpRecords(), y, r.yarpRecords() / y,
                            r.bytes() / 1e6 / y));
                    double p = BatchBench.median(r.pythonSeconds());
                    out.accept(Double.isNaN(p) ? "bag: Python's mcap could not be run (no virtual environment with "
                            + "mcap and mcap-ros2-support; .ci/run creates one)"
                            : f("bag: Python mcap + mcap-ros2-support decoding the same file: median %.3f s, %.0f "
                                    + "messages/s, %.1f MB/s (counted %d); predmon is %.1fx faster", p,
                            r.pythonMessages() / p, r.bytes() / 1e6 / p, r.pythonMessages(), p / s));
                }
                case LEARN -> {
                    for (int n : o.learnRuns()) {
                        LearnBench.Result r = LearnBench.run(abstraction, n);
                        out.accept(f("learn: %d runs per scenario (3 scenarios): %.3f s, peak heap %.1f MB, %d machines, "
                                        + "%d states (samples prepared in %.1f s, not counted)", r.runs(), r.seconds(),
                                r.peakMb(), r.machines(), r.states(), r.prepareSeconds()));
                    }
                    int most = o.learnRuns().stream().mapToInt(Integer::intValue).max().orElse(0);
                    if (most > 0) {
                        LearnBench.Speedup r = LearnBench.speedup(abstraction, most, o.tempDir());
                        out.accept(f("learn reading: %d logs (%d runs per scenario, %.1f MB), parse+abstract+compact, "
                                        + "median of %d alternated rounds: 1 thread %.2f s, %d threads %.2f s: speed-up "
                                        + "%.2fx; models byte-identical: %s (logs written in %.1f s, not counted)",
                                r.logs(), most, r.bytes() / 1e6, LearnBench.ROUNDS, r.oneSeconds(), r.threads(),
                                r.allSeconds(), r.factor(), r.identical() ? "yes" : "NO", r.prepareSeconds()));
                    }
                }
            }
        }
    }

    /**
     * Which properties every benchmark checks on every record (each mode but {@code learn} monitors with {@code
     * models}, and learning reads every log through the same property checker): those of the abstraction, with the
     * forecast's and the deadline forecasts.
     */
    static String properties(Abstraction abstraction, ModelSet models) {
        List<String> on = new ArrayList<>();
        boolean warns = PredictiveMonitor.defaultRule(models) == WarningRule.FORECAST;
        for (Property p : abstraction.properties()) {
            boolean forecast = abstraction.safety().map(b -> b.id().equals(p.id())).orElse(false);
            boolean deadline = warns && p instanceof Response
                    && models.forecast().obligations().containsKey(p.id())
                    && models.forecast().obligations().get(p.id()).size() > 0;
            on.add(p.id() + (forecast ? " (forecast)" : deadline ? " (deadline forecast)" : ""));
        }
        return f("properties on in every benchmark: %d of abstraction %s: %s", on.size(), abstraction.name(),
                String.join(", ", on));
    }

    private static String f(String format, Object... args) {
        return String.format(Locale.ROOT, format, args);
    }
}
