package dev.predmon.hooks;

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
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/** Hook commands run as real child processes of {@code /bin/sh}. */
class CommandHooksTest {

    private static final MonitorEvent.Warning WARNING = new MonitorEvent.Warning(29.581942, 7127,
            List.of("depleted", "late"), 27.83, 14, Clock.SECONDS, 1);
    private static final MonitorEvent.Violation VIOLATION = new MonitorEvent.Violation(34.6077, 8219,
            "battery level >= 20%", 15.86, 20.85, Clock.SECONDS, 1);
    private static final String JSON = "{\"event\":\"warning\",\"log\":\"robot-1.log\"}";

    @TempDir
    Path dir;

    private final List<String> reports = Collections.synchronizedList(new ArrayList<>());

    @BeforeAll
    static void unix() {
        assumeTrue(Files.isExecutable(Path.of("/bin/sh")), "hook commands run with /bin/sh, which this system lacks");
    }

    private CommandHooks hooks(String onWarning, String onViolation, Duration timeout) {
        return new CommandHooks(onWarning, onViolation, timeout, reports::add);
    }

    @Test
    void theCommandGetsTheJsonOnStdinAndTheMainFieldsInItsEnvironment() throws Exception {
        try (CommandHooks h = hooks("cat > '" + dir.resolve("in.json") + "'; env > '" + dir.resolve("env") + "'",
                null, Duration.ofSeconds(10))) {
            h.event("robot-1.log", WARNING, JSON);
        }
        assertEquals(JSON + "\n", Files.readString(dir.resolve("in.json")));
        Map<String, String> env = new HashMap<>();
        for (String line : Files.readAllLines(dir.resolve("env"))) {
            int eq = line.indexOf('=');
            if (line.startsWith("PREDMON_") && eq > 0) {
                env.put(line.substring(0, eq), line.substring(eq + 1));
            }
        }
        assertEquals(Map.of("PREDMON_EVENT", "warning", "PREDMON_LOG", "robot-1.log", "PREDMON_RUN", "1",
                "PREDMON_TIME", "29.581942", "PREDMON_UNIT", "s", "PREDMON_LINE", "7127", "PREDMON_BATTERY", "27.83",
                "PREDMON_SCENARIO", "depleted", "PREDMON_SCENARIOS", "depleted,late"), env);
        assertEquals(List.of(), reports);
    }

    @Test
    void eachKindRunsItsOwnCommandAndOtherEventsRunNone() throws Exception {
        Path calls = dir.resolve("calls");
        try (CommandHooks h = hooks("echo warning $PREDMON_LINE >> '" + calls + "'",
                "echo violation $PREDMON_LINE $PREDMON_BEFORE $PREDMON_PROPERTY >> '" + calls + "'",
                Duration.ofSeconds(10))) {
            h.event("a.log", new MonitorEvent.Eliminated(1, 2, "direct", "direct", false, "why", Clock.SECONDS, 0), "{}");
            h.event("a.log", new MonitorEvent.NoMatch(1, 2, Clock.SECONDS, 0), "{}");
            h.event("a.log", WARNING, JSON);
            Thread.sleep(300); // the violation comes later, as in a run
            h.event("a.log", VIOLATION, "{}");
        }
        assertEquals(List.of("warning 7127", "violation 8219 20.85 battery level >= 20%"), Files.readAllLines(calls));
    }

    @Test
    void theMonitorIsNotHeldUpWhileTheCommandRuns() throws Exception {
        Path marker = dir.resolve("done");
        try (CommandHooks h = hooks("sleep 1; touch '" + marker + "'", null, Duration.ofSeconds(10))) {
            h.event("a.log", WARNING, JSON);
            assertFalse(Files.exists(marker), "event() returned before the command ended");
        }
        assertTrue(Files.exists(marker), "close() let the command finish");
    }

    @Test
    void aFailingCommandIsReportedWithItsExitCode() {
        // The shell's "not found" message goes to /dev/null: the exit code (127) is what is checked, not the log noise.
        try (CommandHooks h = hooks("exit 3", "no-such-command-predmon 2>/dev/null", Duration.ofSeconds(10))) {
            h.event("robot-1.log", WARNING, JSON);
            h.event("robot-1.log", VIOLATION, JSON);
        }
        assertEquals(2, reports.size(), reports.toString());
        assertTrue(reports.contains("--on-warning: warning of robot-1.log line 7127: failed with exit code 3"),
                reports.toString());
        assertTrue(reports.contains("--on-violation: violation of robot-1.log line 8219: failed with exit code 127"),
                reports.toString());
    }

    @Test
    @Timeout(20)
    void aSlowCommandIsKilledAtTheTimeoutAndReported() throws Exception {
        Path pid = dir.resolve("pid");
        try (CommandHooks h = hooks("echo $$ > '" + pid + "'; sleep 30; echo late", null, Duration.ofMillis(500))) {
            h.event("robot-1.log", WARNING, JSON);
        }
        assertEquals(List.of("--on-warning: warning of robot-1.log line 7127: timed out after 0.5 s, killed"), reports);
        long shell = Long.parseLong(Files.readString(pid).strip());
        long deadline = System.nanoTime() + 5_000_000_000L;
        while (ProcessHandle.of(shell).map(ProcessHandle::isAlive).orElse(false) && System.nanoTime() < deadline) {
            Thread.sleep(20);
        }
        assertFalse(ProcessHandle.of(shell).map(ProcessHandle::isAlive).orElse(false), "the command is gone");
    }

    /** More events than can wait: the surplus is reported, nothing runs twice, and close() still returns. */
    @Test
    @Timeout(30)
    void aFullQueueDropsWithAReportAndNoEventRunsTwice() throws Exception {
        Path calls = dir.resolve("calls");
        int events = CommandHooks.THREADS + CommandHooks.QUEUE + 2;
        try (CommandHooks h = hooks("echo $PREDMON_LINE >> '" + calls + "'; sleep 5", null, Duration.ofSeconds(1))) {
            for (int i = 0; i < events; i++) {
                h.event("a.log", new MonitorEvent.Warning(i, i, List.of("depleted"), null, i, Clock.SECONDS, 0), "{}");
            }
        }
        long rejected = reports.stream().filter(r -> r.endsWith("commands are already waiting")).count();
        assertTrue(rejected >= 2, reports.toString());
        List<String> ran = Files.readAllLines(calls);
        assertEquals(ran.size(), ran.stream().distinct().count(), "no event ran twice: " + ran);
        for (int i = 0; i < events; i++) {
            String line = " line " + i + ":";
            long said = reports.stream().filter(r -> r.contains(line)).count();
            assertEquals(1, said, "each event is reported once (run and killed, or not run): " + reports);
        }
        assertTrue(reports.stream().anyMatch(r -> r.endsWith("not run, watch ended")), reports.toString());
    }
}
