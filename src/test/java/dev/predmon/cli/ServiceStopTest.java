package dev.predmon.cli;

import dev.predmon.simulate.Scenario;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The service of {@code docs/predmon-watch.service}, stopped the way systemd stops it: its {@code ExecStart} (this
 * build's JVM and classes in place of {@code java -jar}, the example {@code docs/predmon-watch.conf} with a test's
 * log, models, port and hook), in a real child process; then its {@code KillSignal} to the main process alone, as
 * {@code KillMode=mixed} sends it. watch must print its end summary, exit with a status the unit counts as success,
 * within {@code TimeoutStopSec}, and leave no process behind for the SIGKILL that follows, after letting the hook
 * command it was running deliver its warning.
 */
class ServiceStopTest {

    private static final Path UNIT = Path.of("docs/predmon-watch.service");
    private static final Path EXAMPLE = Path.of("docs/predmon-watch.conf");

    @TempDir
    Path dir;

    /** The {@code [Service]} section's settings (the last of each, as systemd takes them). */
    static Map<String, String> service(Path unit) throws IOException {
        Map<String, String> settings = new LinkedHashMap<>();
        String section = "";
        for (String line : Files.readAllLines(unit)) {
            String l = line.strip();
            if (l.startsWith("[")) {
                section = l;
            } else if (section.equals("[Service]") && !l.isEmpty() && !l.startsWith("#") && l.contains("=")) {
                settings.put(l.substring(0, l.indexOf('=')).strip(), l.substring(l.indexOf('=') + 1).strip());
            }
        }
        return settings;
    }

    /** The example settings file, with the values of {@code replaced} instead of its own. */
    private Path config(Map<String, String> replaced) throws IOException {
        List<String> lines = new ArrayList<>();
        Set<String> seen = new HashSet<>();
        for (String line : Files.readAllLines(EXAMPLE)) {
            int eq = line.indexOf('=');
            String name = eq < 0 || line.startsWith("#") ? null : line.substring(0, eq).strip();
            if (name != null && replaced.containsKey(name)) {
                seen.add(name);
                lines.add(name + " = " + replaced.get(name));
            } else {
                lines.add(line);
            }
        }
        assertEquals(replaced.keySet(), seen, "the example sets what the test replaces");
        return Files.write(dir.resolve("watch.conf"), lines);
    }

    @Test
    @Timeout(120)
    void sigtermToTheMainProcessEndsWithTheSummaryAndASuccessStatus() throws Exception {
        Map<String, String> unit = service(UNIT);
        assertEquals("mixed", unit.get("KillMode"), "SIGTERM to watch alone; its hooks are left to it");
        String signal = unit.getOrDefault("KillSignal", "SIGTERM");
        long timeout = Long.parseLong(unit.get("TimeoutStopSec"));
        Set<Integer> success = new HashSet<>(List.of(0));
        Arrays.stream(unit.getOrDefault("SuccessExitStatus", "").split("\\s+", -1)).filter(s -> !s.isEmpty())
                .forEach(s -> success.add(Integer.parseInt(s)));

        List<String> exec = List.of(unit.get("ExecStart").split("\\s+", -1));
        int watch = exec.indexOf("watch");
        assertTrue(watch > 0 && exec.get(watch + 1).equals("--config"), "ExecStart runs watch --config: " + exec);
        Path log = Files.writeString(dir.resolve("monitor.log"), ""); // the run comes once the service is up
        Path delivered = dir.resolve("delivered.txt");
        Path conf = config(Map.of("log", log.toString(), "models", Path.of("models").toAbsolutePath().toString(),
                "http", "0", "on-warning", "sleep 1; echo \"$PREDMON_EVENT\" > " + delivered));
        List<String> args = new ArrayList<>(exec.subList(watch, exec.size()));
        args.set(2, conf.toString());

        Process p = new ProcessBuilder(Child.command(args.toArray(String[]::new))).directory(dir.toFile())
                .redirectError(dir.resolve("stderr.txt").toFile()).start();
        List<String> out = Child.stdoutLines(p);
        try {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            // A hook is for what happens while watch runs, not for what the log held at its start: the run comes once
            // watch says it follows the log, which it says once the log's history is read.
            while (!Files.readString(dir.resolve("stderr.txt")).contains("predmon: following " + log)) {
                assertTrue(p.isAlive() && System.nanoTime() < deadline, "waiting for the start: "
                        + Files.readString(dir.resolve("stderr.txt")));
                Thread.sleep(10);
            }
            Files.writeString(log, FleetWatchTest.run(Scenario.DEPLETED, 9001));
            while (out.stream().noneMatch(l -> l.contains("WARNING: "))) {
                assertTrue(p.isAlive() && System.nanoTime() < deadline, "waiting for the warning: " + out + " "
                        + Files.readString(dir.resolve("stderr.txt")));
                Thread.sleep(10);
            }

            long stopAt = System.nanoTime();
            Process kill = new ProcessBuilder("kill", "-" + signal.replaceFirst("^SIG", ""), Long.toString(p.pid()))
                    .start();
            assertEquals(0, kill.waitFor(), "kill");
            List<ProcessHandle> left = new ArrayList<>(p.descendants().toList());
            assertTrue(p.waitFor(timeout, TimeUnit.SECONDS), "stopped within TimeoutStopSec=" + timeout);
            double took = (System.nanoTime() - stopAt) / 1e9;
            Thread.sleep(50); // the last lines

            int code = p.exitValue();
            assertTrue(success.contains(code), "exit status " + code + " is one the unit counts as success "
                    + success + "; stderr: " + Files.readString(dir.resolve("stderr.txt")));
            assertEquals(ExitCodes.WARNING, code, "the run warned");
            assertTrue(out.stream().anyMatch(l -> l.startsWith("end of " + log + " (stopped: " + signal + "): ")
                    && (l.contains("battery warned") || l.contains("battery VIOLATED, warned"))), "the end summary: " + out);
            assertEquals("warning", Files.readString(delivered).strip(), "the hook under way delivered its warning");
            assertTrue(left.stream().noneMatch(ProcessHandle::isAlive), "nothing left for the SIGKILL: " + left);
            assertTrue(took < timeout, "stopped in " + took + " s");
        } finally {
            p.destroyForcibly();
        }
    }
}
