package dev.predmon.bench;

import dev.predmon.parse.LogFormat;
import dev.predmon.parse.RecordSink;
import dev.predmon.parse.RecordSource;
import dev.predmon.rosbag.BagMessage;
import dev.predmon.rosbag.BagSink;
import dev.predmon.rosbag.Bags;
import dev.predmon.rosbag.McapWriter;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * Reading throughput of a ROS 2 recording: an MCAP file in zstd chunks (rosbag2's default) of nav2-like traffic
 * (battery states, action status arrays, /rosout lines), read and decoded from CDR by {@code Bags.read}, beside the
 * YARP parser on a log of the same size in bytes (parse only: the bag figure has no monitor either), and beside
 * Python's {@code mcap} with {@code mcap-ros2-support} decoding the same file, where its virtual environment is
 * there.
 */
final class BagBench {

    /**
     * @param messages     messages in the bag
     * @param bytes        the bag's size
     * @param seconds      predmon's passes over the bag, sorted
     * @param yarpRecords  records of the YARP log
     * @param yarpSeconds  the YARP parser's passes, sorted
     * @param pythonSeconds Python's passes, sorted; empty when there is no Python environment
     * @param pythonMessages what Python counted (as a check: equals {@code messages})
     */
    @SuppressWarnings("ArrayRecordComponent") // sorted samples, printed only
    record Result(long messages, long bytes, double[] seconds, long yarpRecords, double[] yarpSeconds,
                  double[] pythonSeconds, long pythonMessages) {
    }

    private static final String PYTHON = """
            import sys, time
            from mcap.reader import NonSeekingReader
            from mcap_ros2.decoder import DecoderFactory
            n = 0
            t = time.perf_counter()
            with open(sys.argv[1], 'rb') as f:
                for _ in NonSeekingReader(f, decoder_factories=[DecoderFactory()]).iter_decoded_messages():
                    n += 1
            print(n, time.perf_counter() - t)
            """;

    private BagBench() {
    }

    static Result run(long messages, int repeats, Path dir) throws Exception {
        Path bag = Files.createTempFile(dir, "predmon-bag", ".mcap");
        Path log = Files.createTempFile(dir, "predmon-bag-yarp", ".log");
        try {
            write(bag, messages);
            long bytes = Files.size(bag);
            double[] seconds = new double[repeats];
            long read = 0;
            for (int i = 0; i <= repeats; i++) { // the first pass warms up
                long start = System.nanoTime();
                read = read(bag);
                if (i > 0) {
                    seconds[i - 1] = (System.nanoTime() - start) / 1e9;
                }
            }
            BenchData.bigLog(log, bytes);
            double[] yarp = new double[repeats];
            long records = 0;
            for (int i = 0; i <= repeats; i++) {
                long start = System.nanoTime();
                records = parse(log);
                if (i > 0) {
                    yarp[i - 1] = (System.nanoTime() - start) / 1e9;
                }
            }
            List<Double> python = new ArrayList<>();
            long pythonCount = -1;
            Path py = python();
            for (int i = 0; py != null && i < repeats; i++) {
                Process p = new ProcessBuilder(py.toString(), "-c", PYTHON, bag.toString())
                        .redirectError(ProcessBuilder.Redirect.DISCARD).start();
                String[] out = new String(p.getInputStream().readAllBytes(), StandardCharsets.US_ASCII).trim()
                        .split("\\s+", -1);
                if (!p.waitFor(600, TimeUnit.SECONDS) || p.exitValue() != 0 || out.length != 2) {
                    break;
                }
                pythonCount = Long.parseLong(out[0]);
                python.add(Double.parseDouble(out[1]));
            }
            Arrays.sort(seconds);
            Arrays.sort(yarp);
            if (read != messages) {
                throw new IllegalStateException("read " + read + " of the " + messages + " messages written");
            }
            return new Result(messages, bytes, seconds, records, yarp,
                    python.stream().mapToDouble(Double::doubleValue).sorted().toArray(), pythonCount);
        } finally {
            Files.deleteIfExists(bag);
            Files.deleteIfExists(log);
        }
    }

    private static void write(Path bag, long messages) throws IOException {
        try (OutputStream out = Files.newOutputStream(bag);
             McapWriter w = new McapWriter(out, McapWriter.Compression.ZSTD, 1 << 20)) {
            int battery = w.channel("/battery_state", "sensor_msgs/msg/BatteryState");
            int status = w.channel("/navigate_to_pose/_action/status", "action_msgs/msg/GoalStatusArray");
            int rosout = w.channel("/rosout", "rcl_interfaces/msg/Log");
            long t = 1_700_000_000_000_000_000L;
            for (long i = 0; i < messages; i++) {
                t += 10_000_000L;
                Map<String, Object> stamp = Map.of("sec", t / 1_000_000_000L, "nanosec", t % 1_000_000_000L);
                switch ((int) (i % 3)) {
                    case 0 -> w.write(battery, t, Map.of("header", Map.of("stamp", stamp, "frame_id", "base_link"),
                            "voltage", 24.0, "percentage", 1.0 - (i % 1000) / 1000.0, "present", true,
                            "location", "slot0"));
                    case 1 -> w.write(status, t, Map.of("status_list", List.of(Map.of("goal_info",
                            Map.of("stamp", stamp), "status", (int) (i % 7)))));
                    default -> w.write(rosout, t, Map.of("stamp", stamp, "level", 20, "name", "bt_navigator",
                            "msg", "Begin navigating from current location to (1.00, 2.00)", "file",
                            "bt_navigator.cpp", "function", "onGoalReceived", "line", 123));
                }
            }
        }
    }

    private static long read(Path bag) throws IOException {
        long[] n = {0};
        Bags.read(bag, new BagSink() {
            @Override
            public void message(BagMessage message) {
                n[0]++;
            }

            @Override
            public void problem(String line) {
                throw new IllegalStateException(line);
            }
        });
        return n[0];
    }

    private static long parse(Path log) throws IOException {
        long[] n = {0};
        try (RecordSource source = LogFormat.yarp().read(log, RecordSink.of(r -> n[0]++, p -> { }))) {
            source.drain();
        }
        return n[0];
    }

    /** The Python of the virtual environment {@code .ci/run} creates, or null. */
    private static Path python() {
        List<Path> candidates = new ArrayList<>();
        String env = System.getenv("PREDMON_VENV");
        if (env != null && !env.isBlank()) {
            candidates.add(Path.of(env, "bin", "python"));
        }
        candidates.add(Path.of("target", "venv", "bin", "python"));
        candidates.add(Path.of(System.getProperty("user.home"), ".cache", "predmon-venv", "bin", "python"));
        return candidates.stream().filter(Files::isExecutable).findFirst().orElse(null);
    }
}
