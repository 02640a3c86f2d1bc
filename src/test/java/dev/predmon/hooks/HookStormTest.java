package dev.predmon.hooks;

import dev.predmon.event.LogEvent;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.parse.Clock;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * A robot whose battery reading flaps at the floor (19.9, 20.1, 19.9, ...) gives a warning, a violation and a
 * recovery at every crossing: its hooks must not drown another robot's warning, nor run three commands a crossing.
 * And a command past its timeout is killed however it was started and whatever it does with its input.
 */
class HookStormTest {

    /** The commands run for {@code log}, in the order they ran. */
    private List<String> of(String log) throws Exception {
        return lines("calls").stream().filter(l -> l.contains(" " + log + " ")).toList();
    }

    private static final String BATTERY = "battery";

    @TempDir
    Path dir;

    private final List<String> reports = Collections.synchronizedList(new ArrayList<>());

    @BeforeAll
    static void unix() {
        assumeTrue(Files.isExecutable(Path.of("/bin/sh")), "hook commands run with /bin/sh, which this system lacks");
    }

    private static LogEvent warning(String log, long line) {
        return LogEvent.of(log, new MonitorEvent.Warning(line / 10.0, line, List.of("depleted"), 20.1, line,
                Clock.SECONDS, 0, dev.predmon.monitor.WarningRule.FORECAST, null, "P(violation) 0.9",
                MonitorEvent.Clause.FORECAST, "depleted", BATTERY));
    }

    private static LogEvent violation(String log, long line) {
        return LogEvent.of(log, new MonitorEvent.Violation(line / 10.0, line, BATTERY, 19.9, 20.1, Clock.SECONDS, 0));
    }

    private static LogEvent recovered(String log, long line) {
        return LogEvent.of(log, new MonitorEvent.Recovered(line / 10.0, line, "property", 20.1, "holds again",
                Clock.SECONDS, 0, BATTERY));
    }

    /** The flapping robot's events: warning, violation, recovery at each of {@code crossings} crossings. */
    private static void flap(CommandHooks h, String log, int crossings) {
        for (int i = 0; i < crossings; i++) {
            h.event(warning(log, 100 + 3L * i));
            h.event(violation(log, 101 + 3L * i));
            h.event(recovered(log, 102 + 3L * i));
        }
    }

    private String calls(String name) {
        Path f = dir.resolve(name);
        return "echo $PREDMON_EVENT $PREDMON_LOG $PREDMON_LINE >> '" + f + "'";
    }

    private List<String> lines(String name) throws Exception {
        Path f = dir.resolve(name);
        return Files.exists(f) ? Files.readAllLines(f) : List.of();
    }

    /**
     * With no hold at all, 130 crossings of one robot (390 events, a second's command each) fill only its own queue:
     * the other robot's warning that comes after them runs its command, within a round of the turns.
     */
    @Test
    @Timeout(30)
    void oneRobotsStormNeverDropsAnotherRobotsFirstWarning() throws Exception {
        String slow = calls("calls") + "; sleep 1";
        try (CommandHooks h = new CommandHooks(slow, slow, slow, Duration.ofSeconds(5), Duration.ZERO, 20.0,
                reports::add)) {
            flap(h, "flapping.log", 130);
            h.event(warning("calm.log", 7127));
            long until = System.nanoTime() + 10_000_000_000L;
            while (!lines("calls").contains("warning calm.log 7127") && System.nanoTime() < until) {
                Thread.sleep(50);
            }
            assertTrue(lines("calls").contains("warning calm.log 7127"), "the calm robot's warning ran: " + reports);
            assertTrue(reports.stream().noneMatch(r -> r.contains("calm.log")), reports.toString());
            assertTrue(reports.stream().anyMatch(r -> r.endsWith(
                    "not run, " + CommandHooks.PER_LOG + " commands of flapping.log are already waiting")),
                    "the storm's surplus is its own: " + reports.subList(0, Math.min(3, reports.size())));
        }
    }

    /**
     * The hold time (5 s by default): 40 crossings within a second run the warning's and the violation's command
     * once each, say once that the re-raised alarm runs none, and the recovery's command runs once, after the last
     * crossing. The other robot's warning runs too.
     */
    @Test
    @Timeout(30)
    void aFlappingReadingRunsItsAlarmOnceAndItsRecoveryOnceItStaysOver() throws Exception {
        try (CommandHooks h = new CommandHooks(calls("calls"), calls("calls"), calls("calls"), Duration.ofSeconds(5),
                Duration.ofMillis(1500), 20.0, reports::add)) {
            flap(h, "flapping.log", 40);
            h.event(warning("calm.log", 7127));
            Thread.sleep(800);
            // one robot's commands run in order; two robots' commands interleave as the runners take them in turn
            assertEquals(List.of("warning flapping.log 100", "violation flapping.log 101"), of("flapping.log"),
                    "within the hold: the alarm once, no recovery yet");
            assertEquals(List.of("warning calm.log 7127"), of("calm.log"), "the other robot's warning ran");
            Thread.sleep(1700);
            assertEquals(List.of("warning flapping.log 100", "violation flapping.log 101",
                    "recovered flapping.log " + (102 + 3 * 39)), of("flapping.log"),
                    "the last recovery ran once the reading stayed over for the hold");
            assertEquals(List.of("warning calm.log 7127"), of("calm.log"), "the other robot's warning ran once");
        }
        assertEquals(1, reports.stream().filter(r -> r.contains("the robot's alarm is still up")).count(),
                reports.toString());
        assertTrue(reports.get(0).startsWith("--on-warning: warning of flapping.log line 103: not run, the alarm it "
                + "raises again recovered less than 1.5 s before"), reports.toString());
    }

    /** A violation after a recovered warning says more than the robot heard: it runs within the hold. */
    @Test
    @Timeout(30)
    void aViolationAfterARecoveredWarningRunsWithinTheHold() throws Exception {
        try (CommandHooks h = new CommandHooks(calls("calls"), calls("calls"), calls("calls"), Duration.ofSeconds(5),
                Duration.ofSeconds(5), 20.0, reports::add)) {
            h.event(warning("a.log", 10));
            h.event(recovered("a.log", 11));
            h.event(warning("a.log", 12));
            h.event(violation("a.log", 13));
        }
        assertEquals(List.of("warning a.log 10", "violation a.log 13"), lines("calls"),
                "the recovery at 11 never reached the robot; the warning at 12 told it nothing new");
    }

    /** Watch ends within the hold: the held recovery runs, so the robot's alarm does not stay up for ever. */
    @Test
    @Timeout(30)
    void aHeldRecoveryRunsWhenWatchEnds() throws Exception {
        try (CommandHooks h = new CommandHooks(calls("calls"), calls("calls"), calls("calls"), Duration.ofSeconds(5),
                Duration.ofSeconds(60), 20.0, reports::add)) {
            h.event(warning("a.log", 10));
            h.event(recovered("a.log", 11));
        }
        assertEquals(List.of("warning a.log 10", "recovered a.log 11"), lines("calls"));
        assertEquals(List.of(), reports);
    }

    /**
     * An event whose JSON is larger than a pipe holds (64 KiB), for a command that never reads its input: the timeout
     * still kills it.
     */
    @Test
    @Timeout(30)
    void theTimeoutHoldsWhenTheCommandDoesNotReadALargeEvent() throws Exception {
        List<String> scenarios = new ArrayList<>();
        for (int i = 0; i < 3000; i++) {
            scenarios.add("scenario-with-a-long-name-number-" + i);
        }
        LogEvent big = LogEvent.of("a.log", new MonitorEvent.Warning(1, 7127, scenarios, 30.0, 5, Clock.SECONDS, 0));
        assertTrue(big.line().length() > 100_000, "larger than a pipe: " + big.line().length());
        Path pid = dir.resolve("pid");
        long start = System.nanoTime();
        try (CommandHooks h = new CommandHooks("echo $$ > '" + pid + "'; exec sleep 30", null, null,
                Duration.ofMillis(500), 20.0, reports::add)) {
            h.event(big);
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        assertEquals(List.of("--on-warning: warning of a.log line 7127: timed out after 0.5 s, killed"), reports);
        assertTrue(seconds < 5, "killed at the timeout, not at watch's end: " + seconds + " s");
        assertGone(Long.parseLong(Files.readString(pid).strip()));
    }

    /**
     * A command that started a detached child ({@code (sleep 30 &)}: its parent, a subshell, is gone, so it is no
     * descendant any more) and then outlived its timeout: the child is killed too.
     */
    @Test
    @Timeout(30)
    void aTimedOutCommandsDetachedChildrenAreKilled() throws Exception {
        assumeTrue(Files.isExecutable(Path.of("/usr/bin/setsid")) || Files.isExecutable(Path.of("/bin/setsid")),
                "a command's process group is made with setsid, which this system lacks");
        Path child = dir.resolve("child");
        try (CommandHooks h = new CommandHooks("(sleep 30 & echo $! > '" + child + "'); sleep 30", null, null,
                Duration.ofMillis(700), 20.0, reports::add)) {
            h.event(warning("a.log", 10));
        }
        assertEquals(List.of("--on-warning: warning of a.log line 10: timed out after 0.7 s, killed"), reports);
        long pid = Long.parseLong(Files.readString(child).strip());
        assertGone(pid);
    }

    private static void assertGone(long pid) throws InterruptedException {
        long deadline = System.nanoTime() + 5_000_000_000L;
        while (ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false) && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        assertFalse(ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false), "process " + pid + " is gone");
    }
}
