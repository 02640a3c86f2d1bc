package dev.predmon.parse;

import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.BufferedWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Large logs are parsed on a second thread; what the caller sees must not change, nor must failures get lost. */
class ParallelReaderTest {

    /** The scenarios the logs take in turn, named rather than taken by their place in the enum. */
    private static final List<Scenario> SCENARIOS = List.of(Scenario.DIRECT, Scenario.RECHARGE, Scenario.DEPLETED);

    @TempDir
    Path tmp;

    /** A log over the parallel threshold: simulated runs in several layouts, with broken records in between. */
    private Path bigMixedLog() throws Exception {
        Path log = tmp.resolve("big.log");
        SimOptions plain = SimOptions.defaults();
        try (BufferedWriter w = Files.newBufferedWriter(log, StandardCharsets.UTF_8)) {
            for (int seed = 0; Files.size(log) < LogReader.PARALLEL_FROM_BYTES + (1 << 20); seed++) {
                Scenario s = SCENARIOS.get(seed % SCENARIOS.size());
                SimOptions o = seed % 2 == 0 ? plain : plain.withRawLines(true).withLateReplies(0.3);
                w.write(LogWriter.toText(Simulator.run(s, seed, o), o));
                w.write("12.0\tDEBUG\tCommand intercepted:\n  From : /x\n  Protocol : P\n"); // broken: To missing
                w.write("abc\tDEBUG\tReply intercepted:\n");                              // broken: time
                w.flush();
            }
        }
        return log;
    }

    @Test
    void parallelAndSequentialGiveTheSameRecordsAndProblemsInOrder() throws Exception {
        Path log = bigMixedLog();
        List<Object> here = new ArrayList<>();
        long[] lines = new long[2];
        long n1 = LogReader.readHere(log, here::add, here::add, n -> lines[0] = n);
        List<Object> alongside = new ArrayList<>();
        long n2 = LogReader.readAlongside(log, alongside::add, alongside::add, n -> lines[1] = n);
        assertEquals(n1, n2);
        assertEquals(Files.readString(log).lines().count(), lines[0], "every line counted");
        assertEquals(lines[0], lines[1]);
        assertEquals(here, alongside);
        assertTrue(here.stream().anyMatch(o -> o instanceof ParseProblem), "the fixture has problems");
        List<Object> viaRead = new ArrayList<>();
        LogReader.read(log, viaRead::add, viaRead::add);
        assertEquals(here, viaRead);
    }

    @Test
    void aFailingConsumerStopsTheParserAndIsRethrown() throws Exception {
        Path log = bigMixedLog();
        IllegalStateException boom = new IllegalStateException("consumer failed");
        int[] seen = {0};
        IllegalStateException thrown = assertThrows(IllegalStateException.class, () -> LogReader.readAlongside(log, r -> {
            if (++seen[0] == 5000) {
                throw boom;
            }
        }, p -> { }, n -> { }));
        assertSame(boom, thrown);
        long deadline = System.currentTimeMillis() + 5000;
        while (parserThreadAlive() && System.currentTimeMillis() < deadline) {
            Thread.sleep(20);
        }
        assertFalse(parserThreadAlive(), "the parser thread stopped");
    }

    private static boolean parserThreadAlive() {
        return Thread.getAllStackTraces().keySet().stream().anyMatch(t -> t.getName().equals("predmon-parse") && t.isAlive());
    }
}
