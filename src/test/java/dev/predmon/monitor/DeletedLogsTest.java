package dev.predmon.monitor;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.live.Board;
import dev.predmon.live.RobotNames;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.support.HandRuns;
import dev.predmon.watch.ExitRule;
import dev.predmon.watch.WatchSession;
import dev.predmon.watch.WatchSettings;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.lang.ref.WeakReference;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A fleet whose logs come and go keeps no monitor for a log deleted long ago: with many logs of a watched directory
 * deleted, once the time kept has passed (shortened here) their monitors, tiles and series are gone, counted as the
 * monitors still reachable on the heap, not timed; each one's summary was printed as it left and its verdict still
 * counts in the exit code; the log left in the directory is watched on, and a file written again at a forgotten path
 * is a new log.
 */
class DeletedLogsTest {

    private static final Abstraction ABSTRACTION = AbstractionFiles.defaults();
    private static final int GONE = 60;

    @TempDir
    Path dir;

    @Test
    @Timeout(120)
    void deletedLogsLeaveWithTheirMonitorsTilesAndSeriesAndTheirVerdictsStay() throws Exception {
        ModelSet models = ModelStore.read(Path.of("models"), ABSTRACTION);
        Path robots = Files.createDirectories(dir.resolve("robots"));
        String run = HandRuns.depleted().text();
        for (int i = 0; i < GONE; i++) {
            Files.writeString(robots.resolve("gone-" + i + ".log"), run);
        }
        Path kept = Files.writeString(robots.resolve("kept.log"), run);
        Board board = new Board(models, ABSTRACTION, Duration.ofMinutes(10), RobotNames.byFile());
        StringWriter out = new StringWriter();
        WatchSession session = new WatchSession(new PrintWriter(out, true), new PrintWriter(new StringWriter()),
                WatchSettings.of(true, false, true, false), null, board, ABSTRACTION, p -> true);
        Fleet fleet = new Fleet(models, ABSTRACTION, 0, ABSTRACTION.confirm(), session);
        // a deleted file let go 0.2 s after it last grew; a log gone for 0.5 s forgotten, looked for every 0.1 s
        fleet.limits(Duration.ofMillis(200), Integer.MAX_VALUE);
        fleet.forgetDeleted(Duration.ofMillis(500), Duration.ofMillis(100));
        AtomicReference<Throwable> failed = new AtomicReference<>();
        Thread following = new Thread(() -> {
            try {
                fleet.follow(new LogSources(List.of(robots)), TimeUnit.MILLISECONDS.toNanos(2), false);
            } catch (Throwable t) {
                failed.set(t);
            }
        }, "deleted-logs-fleet");
        List<WeakReference<Object>> gone = new ArrayList<>();
        int code;
        try (fleet; session) {
            following.start();
            await(() -> board.status(null).get("logs").size() == GONE + 1, "every log found", 60);
            long records = HandRuns.depleted().list().size();
            // (every log is added now: the fleet's list changes no more until a log is forgotten)
            await(() -> fleet.logs().stream().allMatch(l -> l.monitor().records() == records), "every log read", 60);
            for (WatchedLog log : fleet.logs()) { // nothing is added or forgotten now: no file changes
                if (!log.path().equals(kept)) {
                    gone.add(new WeakReference<>(log));
                    gone.add(new WeakReference<>(log.monitor()));
                }
            }
            int expected = ExitRule.ofMonitor(fleet.logs().get(0).monitor());
            for (int i = 0; i < GONE; i++) {
                Files.delete(robots.resolve("gone-" + i + ".log"));
            }
            await(() -> board.status(null).get("logs").size() == 1, "the deleted logs' tiles leave", 60);
            await(() -> out.toString().lines().filter(l -> l.contains("\"stop\":\"deleted\"")).count() == GONE,
                    "each deleted log's summary as it leaves", 30);

            Files.writeString(robots.resolve("gone-0.log"), run); // a new log at a forgotten path
            await(() -> board.status(null).get("logs").size() == 2, "a log written again is a new log", 30);
            following.interrupt();
            following.join(10_000);
            assertEquals(null, failed.get());
            assertEquals(List.of(kept, robots.resolve("gone-0.log")), fleet.logs().stream().map(WatchedLog::path)
                    .toList(), "the live monitors: the kept log's and the new one's");
            code = session.finish(fleet, "interrupted");
            assertEquals(expected, code, "the forgotten logs' verdicts count with the others'");
        } finally {
            following.interrupt();
        }
        assertEquals(0, reachable(gone), "no forgotten log or monitor is held: " + reachable(gone) + " of "
                + gone.size() + " still reachable");
        assertTrue(out.toString().lines().anyMatch(l -> l.contains("\"stop\":\"interrupted\"")
                && l.contains("kept.log")), "the kept log's summary at the end");
    }

    /** How many of {@code refs} still reach their object after the collector has had its chance. */
    private static long reachable(List<WeakReference<Object>> refs) throws InterruptedException {
        for (int i = 0; i < 20 && refs.stream().anyMatch(r -> r.get() != null); i++) {
            System.gc();
            Thread.sleep(50);
        }
        return refs.stream().filter(r -> r.get() != null).count();
    }

    private static void await(BooleanSupplier condition, String what, int seconds) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("not within " + seconds + " s: " + what);
            }
            Thread.sleep(20);
        }
    }
}
