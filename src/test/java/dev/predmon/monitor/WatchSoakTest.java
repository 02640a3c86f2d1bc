package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.LearnedModels;
import dev.predmon.parse.ParseProblem;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Soak: {@link LogWatcher} follows a log that a writer thread appends to in pieces cut anywhere, while it is
 * rotated 100 times (by rename and new file, by copytruncate, by delete and recreate), and the watcher is
 * started before the file exists. Every record carries a sequence number; at the end each must have reached
 * the monitor exactly once. Prints the counts.
 */
class WatchSoakTest {

    private static final int ROTATIONS = 100;
    private static final Abstraction ABSTRACTION = AbstractionFiles.defaults();

    @TempDir
    Path dir;

    @Test
    void hundredRotationsWhileWritingLoseAndRepeatNoRecord() throws Exception {
        Path log = dir.resolve("robot.log");
        AtomicLong written = new AtomicLong();
        AtomicLong seenCount = new AtomicLong();
        ConcurrentLinkedQueue<Throwable> writerFailure = new ConcurrentLinkedQueue<>();
        Map<Long, Integer> seen = new TreeMap<>();
        List<ParseProblem> problems = new ArrayList<>();
        PredictiveMonitor monitor = new PredictiveMonitor(LearnedModels.modelSet(List.of(), ABSTRACTION),
                ABSTRACTION, 0, e -> { });

        Thread writer = new Thread(() -> {
            try {
                write(log, written, seenCount);
            } catch (Throwable t) {
                writerFailure.add(t);
            }
        }, "soak-writer");

        long start = System.nanoTime();
        try (LogWatcher watcher = new LogWatcher(log, monitor, problems::add, r -> {
            seen.merge(Long.parseLong(r.arguments()), 1, Integer::sum);
            seenCount.incrementAndGet();
        }, Duration.ZERO)) { // a replaced file finished as soon as it is read: rotations here race the reads, not a writer
            // that goes on writing the renamed file (that wait is LogFollowerTest's)
            writer.start();
            long deadline = System.nanoTime() + 60_000_000_000L;
            long quietSince = System.nanoTime();
            // Until the writer is done and, after it, nothing new came for half a second (or all was seen).
            while (System.nanoTime() < deadline && (writer.isAlive() || (seenCount.get() < written.get()
                    && System.nanoTime() - quietSince < 500_000_000L))) {
                if (watcher.poll()) {
                    quietSince = System.nanoTime();
                } else {
                    Thread.sleep(1);
                }
            }
            writer.join(1000);
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        assertTrue(writerFailure.isEmpty(), () -> "writer failed: " + writerFailure);
        long duplicates = seen.values().stream().filter(n -> n > 1).mapToLong(n -> n - 1).sum();
        long lost = 0;
        for (long k = 0; k < written.get(); k++) {
            if (!seen.containsKey(k)) {
                lost++;
            }
        }
        System.out.printf(Locale.ROOT, "soak: %d rotations, %d records written, %d processed, %d duplicates, "
                + "%d lost, %d parse problems, %.1f s%n", ROTATIONS, written.get(), seenCount.get(), duplicates, lost,
                problems.size(), seconds);
        assertEquals(List.of(), problems.stream().map(p -> p.format(log.toString())).toList());
        assertEquals(0, duplicates, "records processed twice");
        assertEquals(0, lost, "records skipped");
        assertEquals(written.get(), seenCount.get());
    }

    /**
     * Writes records in random pieces, rotating every few records; the watcher polls meanwhile. Two waits
     * (bounded; a timeout shows as lost records) keep out what no follower of a path can see, {@code tail -F}
     * included: a file renamed or deleted before the watcher ever looked at the path, and what a logger writes
     * between the watcher's last read and a copytruncate (it exists only in the copy). Everything else races:
     * appends cut anywhere, the truncation and the rewrite after it, the new file after a rename or delete.
     */
    static void write(Path log, AtomicLong written, AtomicLong seenCount) throws Exception {
        write(log, written, seenCount, ROTATIONS);
    }

    /** As above, rotating {@code rotations} times. */
    static void write(Path log, AtomicLong written, AtomicLong seenCount, int rotations) throws Exception {
        Random random = new Random(2024);
        Thread.sleep(20); // the watcher starts first and must wait for the file to appear
        long seq = 0;
        for (int rotation = 0; rotation <= rotations; rotation++) {
            int records = 1 + random.nextInt(40);
            try (FileChannel out = FileChannel.open(log, StandardOpenOption.CREATE, StandardOpenOption.WRITE,
                    StandardOpenOption.APPEND)) {
                StringBuilder text = new StringBuilder();
                for (int i = 0; i < records; i++) {
                    text.append(record(seq + i, random.nextBoolean() ? "\n" : "\r\n"));
                }
                byte[] bytes = text.toString().getBytes(StandardCharsets.UTF_8);
                for (int at = 0; at < bytes.length; ) {
                    int n = Math.min(bytes.length - at, 1 + random.nextInt(300));
                    out.write(ByteBuffer.wrap(bytes, at, n));
                    at += n;
                    if (random.nextInt(4) == 0) {
                        Thread.sleep(0, 200_000);
                    }
                }
                seq += records;
                written.set(seq);
            }
            if (rotation == rotations) {
                break;
            }
            boolean copyTruncate = rotation % 3 == 1;
            // A file must be at its path when the watcher looks at least once (it is then held open and
            // drained after a rename or delete); a copytruncate must come after the watcher read the file.
            long needed = copyTruncate ? seq : seq - records + 1;
            long deadline = System.nanoTime() + 2_000_000_000L;
            while (seenCount.get() < needed && System.nanoTime() < deadline) {
                Thread.sleep(1);
            }
            switch (rotation % 3) {
                case 0 -> Files.move(log, log.resolveSibling("robot.log.1"), StandardCopyOption.REPLACE_EXISTING);
                case 1 -> {
                    Files.copy(log, log.resolveSibling("robot.log.1"), StandardCopyOption.REPLACE_EXISTING);
                    try (FileChannel truncate = FileChannel.open(log, StandardOpenOption.WRITE)) {
                        truncate.truncate(0);
                    }
                }
                default -> Files.delete(log);
            }
        }
    }

    static String record(long seq, String eol) {
        String time = String.format(Locale.ROOT, "%.6f", seq * 0.01);
        return time + "\tDEBUG\tCommand intercepted:" + eol
                + "  From      : /Soak/client" + eol
                + "  To        : /SoakComponent" + eol
                + "  Protocol  : Soak" + eol
                + "  Command   : step" + eol
                + "  Arguments : " + seq + eol
                + "  Reply     : " + eol;
    }
}
