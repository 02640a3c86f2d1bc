package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.support.HandRuns;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Stopping {@code watch} the way people and service managers do, on a real child process: Ctrl-C (SIGINT),
 * SIGTERM and SIGHUP, before and after a warning. Each ends with the end summary (JSON with {@code --json}) and the exit code
 * of the table (it used to be 130 or 143 and no summary).
 */
class WatchSignalTest {

    @TempDir
    Path tmp;
    Path models;

    @BeforeEach
    void learn() throws Exception {
        Path logs = tmp.resolve("logs");
        models = tmp.resolve("models");
        CliEndToEndTest.learnHandRuns(logs, models, "recharge");
    }

    /** A child {@code watch} with its stdout collected line by line. */
    private record Watch(Process process, List<String> out) {

        static Watch start(String... args) throws IOException {
            Process p = new ProcessBuilder(Child.command(args)).redirectError(ProcessBuilder.Redirect.DISCARD).start();
            List<String> out = Child.stdoutLines(p);
            return new Watch(p, out);
        }

        void awaitLine(String part) throws InterruptedException {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            while (out.stream().noneMatch(l -> l.contains(part))) {
                assertTrue(process.isAlive() && System.nanoTime() < deadline, "waiting for '" + part + "': " + out);
                Thread.sleep(10);
            }
        }

        /** Sends the signal to this process (by its pid) and returns its exit code. */
        int signal(String name) throws Exception {
            Process kill = new ProcessBuilder("kill", "-" + name, Long.toString(process.pid())).start();
            assertEquals(0, kill.waitFor(), "kill -" + name);
            assertTrue(process.waitFor(20, TimeUnit.SECONDS), "stops on SIG" + name);
            Thread.sleep(50); // the last lines
            return process.exitValue();
        }
    }

    /** SIGINT is ignored by processes started from a background job of a script; then it cannot be tested. */
    private static void assumeSigintReachesChildren() throws IOException {
        for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
            if (line.startsWith("SigIgn:")) {
                long ignored = Long.parseUnsignedLong(line.substring(7).strip(), 16);
                Assumptions.assumeTrue((ignored & (1L << 1)) == 0, "SIGINT is ignored in this test run");
            }
        }
    }

    /** Before any warning: a nominal run, followed until the faulty model drops out. */
    private void beforeAWarning(String signal) throws Exception {
        Path log = Files.writeString(tmp.resolve("nominal.log"), HandRuns.recharge().text());
        Watch w = Watch.start("watch", "--log", log.toString(), "--models", models.toString(), "--eliminations");
        w.awaitLine("model depleted (faulty) eliminated");
        assertEquals(ExitCodes.OK, w.signal(signal), "SIG" + signal + " before a warning: " + w.out());
        // the end line, then the run's last forecast
        String end = w.out().stream().filter(l -> l.startsWith("end of ")).reduce((a, b) -> b).orElse("");
        assertTrue(w.out().get(w.out().size() - 1).startsWith("last forecast of battery: "), w.out().toString());
        assertTrue(end.startsWith("end of " + log + " (stopped: SIG" + signal + "): ")
                && end.contains("; no warning; ") && end.endsWith(" hold"), end);
    }

    /** After a warning, with --json: the last line is the end event. */
    private void afterAWarning(String signal) throws Exception {
        Path log = Files.writeString(tmp.resolve("faulty.log"), HandRuns.depleted().text());
        Watch w = Watch.start("watch", "--log", log.toString(), "--models", models.toString(), "--json");
        w.awaitLine("\"event\":\"violation\"");
        assertEquals(ExitCodes.WARNING, w.signal(signal), "SIG" + signal + " after a warning: " + w.out());
        JsonNode end = new ObjectMapper().readTree(w.out().get(w.out().size() - 1));
        assertEquals("end", end.get("event").asText());
        assertEquals("SIG" + signal, end.get("stop").asText());
        assertTrue(end.get("warning").asBoolean() && end.get("violation").asBoolean(), end.toString());
        assertEquals(HandRuns.depleted().list().size(), end.get("records").asInt());
    }

    @Test
    @Timeout(60)
    void sigtermBeforeAWarning() throws Exception {
        beforeAWarning("TERM");
    }

    @Test
    @Timeout(60)
    void sigtermAfterAWarning() throws Exception {
        afterAWarning("TERM");
    }

    /** A closed terminal or SSH session sends SIGHUP: a stop like SIGTERM, not a death without the summary (129). */
    @Test
    @Timeout(60)
    void sighupAfterAWarningIsAStopWithTheSummary() throws Exception {
        afterAWarning("HUP");
    }

    @Test
    @Timeout(60)
    void sigintBeforeAWarning() throws Exception {
        assumeSigintReachesChildren();
        beforeAWarning("INT");
    }

    @Test
    @Timeout(60)
    void sigintAfterAWarning() throws Exception {
        assumeSigintReachesChildren();
        afterAWarning("INT");
    }
}
