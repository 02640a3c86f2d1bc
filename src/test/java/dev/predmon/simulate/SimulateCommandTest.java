package dev.predmon.simulate;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.cli.SimulateCommand;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The {@code simulate} command run in-process, and the realtime writer it uses. */
class SimulateCommandTest {

    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    private int run(String... args) {
        CommandLine cl = new CommandLine(new SimulateCommand());
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(err));
        return cl.execute(args);
    }

    @Test
    void printsTheLogToStandardOutput() {
        assertEquals(0, run("--scenario", "direct", "--seed", "9", "--vocab"));
        SimOptions o = SimOptions.defaults().withVocab(true);
        assertEquals(LogWriter.toText(Simulator.run(Scenario.DIRECT, 9, o), o), out.toString());
    }

    @Test
    void writesTheLogAndItsTruth(@TempDir Path dir) throws IOException {
        Path log = dir.resolve("run.log");
        assertEquals(0, run("--scenario", "DEPLETED", "--seed", "4", "--out", log.toString(), "--crlf"));
        SimOptions o = SimOptions.defaults().withCrlf(true);
        SimRun expected = Simulator.run(Scenario.DEPLETED, 4, o);
        assertEquals(LogWriter.toText(expected, o), Files.readString(log));
        JsonNode truth = new ObjectMapper().readTree(dir.resolve("run.log.truth.json").toFile());
        assertEquals("depleted", truth.get("scenario").asText());
        assertTrue(truth.get("faulty").asBoolean());
        assertEquals(4, truth.get("seed").asLong());
        assertEquals(expected.truth().violationTime(), truth.get("violationTime").asDouble());
        assertTrue(truth.get("parameters").has("tickPeriod"));
        JsonNode first = truth.get("batteryTimeline").get(0);
        assertEquals(2, first.size());
        assertEquals(expected.truth().batteryTimeline().size(), truth.get("batteryTimeline").size());
    }

    @Test
    void writesABatchAndItsScenario(@TempDir Path dir) throws IOException {
        assertEquals(0, run("--scenario", "recharge", "--seed", "10", "--runs", "3", "--out-dir", dir.toString()));
        for (long seed = 10; seed <= 12; seed++) {
            assertEquals(LogWriter.toText(Simulator.run(Scenario.RECHARGE, seed, SimOptions.defaults()),
                    SimOptions.defaults()), Files.readString(dir.resolve("recharge-" + seed + ".log")));
        }
        assertFalse(Files.exists(dir.resolve("recharge-13.log")));
        JsonNode scenario = new ObjectMapper().readTree(dir.resolve("scenario.json").toFile());
        assertFalse(scenario.get("faulty").asBoolean());
        assertTrue(scenario.get("description").asText().startsWith("Recharge: "));
    }

    @Test
    void rejectsBadArguments() {
        assertEquals(2, run("--seed", "1"));
        assertEquals(2, run("--scenario", "crash"));
        assertEquals(2, run("--scenario", "direct", "--runs", "2"));
        assertEquals(2, run("--scenario", "direct", "--late-replies", "1.5"));
        assertTrue(err.toString().contains("--runs needs --out-dir"), err.toString());
    }

    @Test
    void realtimeWritesTheSameRecordsPaced(@TempDir Path dir) throws IOException {
        Path log = dir.resolve("live.log");
        SimRun run = Simulator.run(Scenario.DIRECT, 11, SimOptions.defaults());
        double duration = run.truth().endTime() - run.events().get(0).time();
        double speed = duration / 0.3;
        long t0 = System.nanoTime();
        assertEquals(0, run("--scenario", "direct", "--seed", "11", "--out", log.toString(), "--realtime",
                "--speed", Double.toString(speed)));
        double wall = (System.nanoTime() - t0) / 1e9;
        assertTrue(wall >= 0.28, "finished too fast: " + wall + " s");
        assertEquals(LogWriter.toText(run, SimOptions.defaults()), Files.readString(log));
    }

    @Test
    void realtimeWriterStopsWhenInterrupted() throws InterruptedException {
        SimRun run = Simulator.run(Scenario.DEPLETED, 3, SimOptions.defaults());
        StringWriter sink = new StringWriter();
        Thread t = new Thread(new RealtimeWriter(run, SimOptions.defaults(), sink, 1.0));
        t.start();
        Thread.sleep(200);
        t.interrupt();
        t.join(2000);
        assertFalse(t.isAlive());
        int written = Runs.read(sink.toString()).size();
        assertTrue(written > 0 && written < run.events().size(), "written " + written);
    }
}
