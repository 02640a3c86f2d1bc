package dev.predmon.cli;

import dev.predmon.bench.Benchmarks;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

/** {@code predmon bench}: the performance figures of the README, measured on this machine. */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = {"Measure predmon on this machine with simulated logs: batch throughput (vs grep), "
                + "append-to-warning latency of watch, a following watch's CPU per record, its CPU per record and "
                + "heap as the log grows, "
                + "learning time and peak heap, a fleet of logs watched in one process against one log, and the reading "
                + "of a ROS 2 bag (MCAP) beside the YARP parser and Python's mcap.",
                "For the heap figure run: java -Xmx64m -jar predmon.jar bench --only memory"})
final class BenchCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--only", split = ",", paramLabel = "batch|latency|cpu|memory|learn|fleet",
            description = "Run only these benchmarks (default: all, in this order).")
    List<String> only;

    @Option(names = "--batch-mb", defaultValue = "200", description = "Size of the batch log in MB (default: ${DEFAULT-VALUE}).")
    long batchMb;

    @Option(names = "--latency-runs", defaultValue = "1000",
            description = "Appends measured, after a fifth as many not measured (default: ${DEFAULT-VALUE}).")
    int latencyRuns;

    @Option(names = "--poll-us", defaultValue = "1000",
            description = "Watcher pause when nothing was appended, microseconds (watch --poll-ms; default: ${DEFAULT-VALUE}).")
    long pollMicros;

    @Option(names = "--memory-records", defaultValue = "10000000",
            description = "Records pushed through the monitor (default: ${DEFAULT-VALUE}).")
    long memoryRecords;

    @Option(names = "--cpu-records", defaultValue = "500000",
            description = "Records a following watch takes while its CPU time is measured, after half as many "
                    + "not measured (default: ${DEFAULT-VALUE}).")
    long cpuRecords;

    @Option(names = "--learn-runs", split = ",", defaultValue = "10,100,1000",
            description = "Runs per scenario to learn from, one measurement each (default: ${DEFAULT-VALUE}).")
    List<Integer> learnRuns;

    @Option(names = "--model-runs", defaultValue = "20",
            description = "Runs per scenario the monitored models are learned from (default: ${DEFAULT-VALUE}).")
    int modelRuns;

    @Option(names = "--tmp", paramLabel = "DIR", description = "Directory for generated logs (default: the system's).")
    Path tmp;

    @Option(names = "--fleet-tmp", paramLabel = "DIR",
            description = "Directory for the fleet benchmark's logs (default: /dev/shm where it is a writable "
                    + "directory, a RAM file system on which 270,000 appends a second cost the writer a fraction of a "
                    + "core, else --tmp).")
    Path fleetTmp;

    @Option(names = "--fleet-logs", split = ",", defaultValue = "1,1000,10000",
            description = "Fleet sizes: logs watched at once by the fleet benchmark, one measurement each (default: "
                    + "${DEFAULT-VALUE}).")
    List<Integer> fleetLogs;

    @Option(names = "--fleet-samples", defaultValue = "200",
            description = "Append-to-warning latencies measured per fleet size, at least one per log (default: "
                    + "${DEFAULT-VALUE}).")
    int fleetSamples;

    @Option(names = "--fleet-seconds", defaultValue = "5",
            description = "Seconds the fleet benchmark appends at robot pace, and stays idle, per fleet size "
                    + "(default: ${DEFAULT-VALUE}).")
    double fleetSeconds;

    @Option(names = "--fleet-polling", description = "The fleet polls every log every --poll-us, as watch --polling "
            + "does, instead of waiting for the operating system's file-change notification.")
    boolean fleetPolling;

    @Option(names = "--fleet-idle-logs", defaultValue = "10000",
            description = "Logs of the idle fleet whose CPU, heap and descriptors the fleet benchmark measures apart "
                    + "(0: none; default: ${DEFAULT-VALUE}).")
    int fleetIdleLogs;

    @Option(names = "--bag-messages", defaultValue = "300000",
            description = "Messages in the ROS 2 bag (MCAP, zstd) the bag benchmark reads (default: ${DEFAULT-VALUE}).")
    long bagMessages;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        List<Benchmarks.Kind> kinds = only == null || only.isEmpty() ? Arrays.asList(Benchmarks.Kind.values())
                : only.stream().map(this::kind).toList();
        Path dir = tmp != null ? tmp : Path.of(System.getProperty("java.io.tmpdir"));
        Path shm = Path.of("/dev/shm");
        Path fleetDir = fleetTmp != null ? fleetTmp
                : tmp == null && Files.isDirectory(shm) && Files.isWritable(shm) ? shm : dir;
        Benchmarks.run(kinds, new Benchmarks.Options(batchMb, latencyRuns, pollMicros, memoryRecords, cpuRecords, learnRuns,
                modelRuns, dir, fleetLogs, fleetSamples, fleetSeconds, fleetPolling, fleetIdleLogs, bagMessages, fleetDir), line -> {
            out.println(line);
            out.flush();
        });
        return ExitCodes.OK;
    }

    private Benchmarks.Kind kind(String name) {
        try {
            return Benchmarks.Kind.valueOf(name.trim().toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(),
                    "--only: unknown benchmark '" + name + "' (expected batch, latency, cpu, memory, learn, fleet or bag)");
        }
    }
}
