package dev.predmon.hooks;

import dev.predmon.event.LogEvent;
import dev.predmon.forecast.Forecast;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.WarningRule;
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
    private static final LogEvent SENT = LogEvent.of("robot-1.log", WARNING);

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
            h.event(SENT);
        }
        assertEquals(SENT.line() + "\n", Files.readString(dir.resolve("in.json")), "the event as watch --json gives it");
        assertTrue(SENT.line().startsWith("{\"event\":\"warning\",\"log\":\"robot-1.log\",\"time\":29.581942,"),
                SENT.line());
        assertEquals(Map.of("PREDMON_EVENT", "warning", "PREDMON_LOG", "robot-1.log", "PREDMON_RUN", "1",
                "PREDMON_TIME", "29.581942", "PREDMON_UNIT", "s", "PREDMON_LINE", "7127", "PREDMON_PROPERTY", "",
                "PREDMON_VALUE", "27.83", "PREDMON_BATTERY", "27.83", "PREDMON_SCENARIO", "depleted"),
                Map.copyOf(without(env("env"), "PREDMON_SCENARIOS", "PREDMON_PROBABILITY",
                        "PREDMON_TIME_TO_VIOLATION", "PREDMON_PROPERTY_NAME", "PREDMON_WHAT", "PREDMON_ACTION", "PREDMON_VENV")));
        // the event in words; a property the hooks were not told of has no name and no action
        assertEquals("the run can only be faulty scenario depleted, late (every nominal model eliminated)",
                env("env").get("PREDMON_WHAT"));
        assertEquals("", env("env").get("PREDMON_PROPERTY_NAME"));
        assertEquals("", env("env").get("PREDMON_ACTION"));
        assertEquals("depleted,late", env("env").get("PREDMON_SCENARIOS"));
        assertEquals("", env("env").get("PREDMON_PROBABILITY"), "a warning of the match rule has no forecast");
        assertEquals(List.of(), reports);
    }

    /**
     * A forecast warning on a run no faulty machine still matches: the property's name, the probability and the time
     * left, values rounded as the page shows them, and the faulty scenario the run matched longest.
     */
    @Test
    void aForecastWarningGivesItsPropertyProbabilityTimeAndScenarioRounded() throws Exception {
        Forecast f = new Forecast(0.96223, 4.98123, 4.78, 5.45, Forecast.Basis.RESYNCHRONISED, 4000L, 10, 10,
                29.635000000003867, -2.43, "s");
        MonitorEvent.Warning w = new MonitorEvent.Warning(27.906633, 6763, List.of(), 29.635000000003867, 12,
                Clock.SECONDS, 0, WarningRule.FORECAST, f, "P(violation) 0.96 reaches the warning threshold",
                MonitorEvent.Clause.FORECAST, "depleted", "battery level >= 20%");
        MonitorEvent.Violation v = new MonitorEvent.Violation(34.6, 8219, "battery level >= 20%", 19.996, 20.004,
                Clock.SECONDS, 0);
        try (CommandHooks h = new CommandHooks("env > '" + dir.resolve("warning") + "'",
                "env > '" + dir.resolve("violation") + "'", Duration.ofSeconds(10), 20.0, reports::add)) {
            h.event(LogEvent.of("robot-1.log", w));
            Thread.sleep(300);
            h.event(LogEvent.of("robot-1.log", v));
        }
        Map<String, String> warning = env("warning");
        assertEquals("battery level >= 20%", warning.get("PREDMON_PROPERTY"));
        assertEquals("0.96", warning.get("PREDMON_PROBABILITY"));
        assertEquals("4.98", warning.get("PREDMON_TIME_TO_VIOLATION"));
        assertEquals("29.64", warning.get("PREDMON_VALUE"));
        assertEquals("29.64", warning.get("PREDMON_BATTERY"), "the older name stays");
        assertEquals("depleted", warning.get("PREDMON_SCENARIO"));
        assertEquals("", warning.get("PREDMON_SCENARIOS"), "no faulty machine still matches");
        Map<String, String> violation = env("violation");
        assertEquals("19.99", violation.get("PREDMON_VALUE"), "a violating value never reads as the bound");
        assertEquals("20.00", violation.get("PREDMON_BEFORE"));
        assertEquals("battery level >= 20%", violation.get("PREDMON_PROPERTY"));
        assertEquals(List.of(), reports);
    }

    /** The PREDMON_* variables a command wrote with {@code env > NAME}. */
    private Map<String, String> env(String name) throws Exception {
        Map<String, String> env = new HashMap<>();
        for (String line : Files.readAllLines(dir.resolve(name))) {
            int eq = line.indexOf('=');
            if (line.startsWith("PREDMON_") && eq > 0) {
                env.put(line.substring(0, eq), line.substring(eq + 1));
            }
        }
        return env;
    }

    private static Map<String, String> without(Map<String, String> env, String... keys) {
        Map<String, String> rest = new HashMap<>(env);
        for (String k : keys) {
            rest.remove(k);
        }
        return rest;
    }

    @Test
    void eachKindRunsItsOwnCommandAndOtherEventsRunNone() throws Exception {
        Path calls = dir.resolve("calls");
        try (CommandHooks h = hooks("echo warning $PREDMON_LINE >> '" + calls + "'",
                "echo violation $PREDMON_LINE $PREDMON_BEFORE $PREDMON_PROPERTY >> '" + calls + "'",
                Duration.ofSeconds(10))) {
            h.event(LogEvent.of("a.log", new MonitorEvent.Eliminated(1, 2, "direct", "direct", false, "why", Clock.SECONDS, 0)));
            h.event(LogEvent.of("a.log", new MonitorEvent.NoMatch(1, 2, Clock.SECONDS, 0)));
            h.event(LogEvent.of("a.log", WARNING));
            Thread.sleep(300); // the violation comes later, as in a run
            h.event(LogEvent.of("a.log", VIOLATION));
        }
        assertEquals(List.of("warning 7127", "violation 8219 20.85 battery level >= 20%"), Files.readAllLines(calls));
    }

    @Test
    void theMonitorIsNotHeldUpWhileTheCommandRuns() throws Exception {
        Path marker = dir.resolve("done");
        try (CommandHooks h = hooks("sleep 1; touch '" + marker + "'", null, Duration.ofSeconds(10))) {
            h.event(LogEvent.of("a.log", WARNING));
            assertFalse(Files.exists(marker), "event() returned before the command ended");
        }
        assertTrue(Files.exists(marker), "close() let the command finish");
    }

    @Test
    void aFailingCommandIsReportedWithItsExitCode() {
        // The shell's "not found" message goes to /dev/null: the exit code (127) is what is checked, not the log noise.
        try (CommandHooks h = hooks("exit 3", "no-such-command-predmon 2>/dev/null", Duration.ofSeconds(10))) {
            h.event(LogEvent.of("robot-1.log", WARNING));
            h.event(LogEvent.of("robot-1.log", VIOLATION));
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
            h.event(LogEvent.of("robot-1.log", WARNING));
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
        int events = CommandHooks.THREADS + CommandHooks.PER_LOG + 2;
        try (CommandHooks h = hooks("echo $PREDMON_LINE >> '" + calls + "'; sleep 5", null, Duration.ofSeconds(1))) {
            for (int i = 0; i < events; i++) {
                h.event(LogEvent.of("a.log", new MonitorEvent.Warning(i, i, List.of("depleted"), null, i, Clock.SECONDS, 0)));
            }
        }
        long rejected = reports.stream().filter(r -> r.endsWith("commands of a.log are already waiting")).count();
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
