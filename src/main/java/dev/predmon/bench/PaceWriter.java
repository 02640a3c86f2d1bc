package dev.predmon.bench;

import java.io.BufferedReader;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.locks.LockSupport;

/**
 * The robots of {@link RobotPace}, in a process of their own as robots are: one thread appends the records of a run
 * file to {@code logs} log files, each held open, at {@code rate} records per second per log, one write per record,
 * the logs taken in turn so that the writes are spread evenly over time (log {@code i}'s records fall {@code i/logs}
 * of a record's time after log 0's). Its descriptors and CPU are not the monitor's.
 *
 * <p>Arguments: the run file (records separated by a line holding a single {@code \u0000}), the directory, the number
 * of logs ({@code robot-0.log} ...), records per second per log. It prints {@code ready} once every log is open,
 * starts at a {@code go} line on its input, stops at the input's end, and prints {@code wrote RECORDS NANOS CPU}:
 * the records written, the time it wrote for and its own CPU time.
 */
public final class PaceWriter {

    /** Separates two records in the run file. */
    static final String SEPARATOR = "\u0000\n";

    private PaceWriter() {
    }

    public static void main(String[] args) throws Exception {
        List<byte[]> run = new ArrayList<>();
        for (String r : Files.readString(Path.of(args[0]), StandardCharsets.UTF_8).split(SEPARATOR, -1)) {
            if (!r.isEmpty()) {
                run.add(r.getBytes(StandardCharsets.UTF_8));
            }
        }
        Path dir = Path.of(args[1]);
        int logs = Integer.parseInt(args[2]);
        double rate = Double.parseDouble(args[3]);
        FileOutputStream[] out = new FileOutputStream[logs];
        int[] cursor = new int[logs];
        for (int i = 0; i < logs; i++) {
            out[i] = new FileOutputStream(dir.resolve("robot-" + i + ".log").toFile(), true);
            cursor[i] = (int) ((long) i * run.size() / logs); // robots do not start together
        }
        PrintStream stdout = new PrintStream(System.out, true, StandardCharsets.UTF_8);
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        stdout.println("ready");
        if (!"go".equals(in.readLine())) {
            return;
        }
        AtomicBoolean stop = new AtomicBoolean();
        Thread stopper = new Thread(() -> {
            try {
                while (in.readLine() != null) {
                    // the parent closes the input to stop
                }
            } catch (IOException ignored) {
                // the parent is gone: stop as well
            }
            stop.set(true);
        });
        stopper.setDaemon(true);
        stopper.start();
        long start = System.nanoTime();
        long written = 0;
        double perNano = rate * logs / 1e9;
        while (!stop.get()) {
            long due = (long) ((System.nanoTime() - start) * perNano);
            for (; written < due; written++) {
                int i = (int) (written % logs);
                out[i].write(run.get(cursor[i]));
                cursor[i] = (cursor[i] + 1) % run.size();
            }
            LockSupport.parkNanos(1_000_000L);
        }
        long nanos = System.nanoTime() - start;
        for (FileOutputStream o : out) {
            o.close();
        }
        stdout.println("wrote " + written + " " + nanos + " "
                + ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime());
    }
}
