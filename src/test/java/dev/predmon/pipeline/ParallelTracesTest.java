package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

/** Reading logs on several threads gives the traces of reading them one after another, in the same order. */
class ParallelTracesTest {

    /** The scenarios the logs take in turn, named rather than taken by their place in the enum. */
    private static final List<Scenario> SCENARIOS = List.of(Scenario.DIRECT, Scenario.RECHARGE, Scenario.DEPLETED);

    @TempDir
    Path dir;

    private List<Path> logs(int n) throws IOException {
        List<Path> logs = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Scenario s = SCENARIOS.get(i % SCENARIOS.size());
            Path log = dir.resolve(s.id() + "-" + i + ".log");
            Files.writeString(log, LogWriter.toText(Simulator.run(s, 100 + i, SimOptions.defaults()), SimOptions.defaults()));
            logs.add(log);
        }
        return logs;
    }

    @Test
    void sameTracesInTheSameOrderWhateverTheThreadCount() throws IOException {
        List<Path> logs = logs(12);
        List<Path> asked = new ArrayList<>(logs);
        asked.add(logs.get(3)); // a log named twice is read once
        Abstraction abstraction = AbstractionFiles.defaults();
        Map<Path, LogTrace> one = Traces.readAll(asked, abstraction, 1);
        Map<Path, LogTrace> four = Traces.readAll(asked, abstraction, 4);
        assertEquals(logs, List.copyOf(one.keySet()));
        assertEquals(logs, List.copyOf(four.keySet()));
        for (Path log : logs) {
            LogTrace a = one.get(log);
            LogTrace b = four.get(log);
            assertEquals(a.pairs(), b.pairs(), log.toString());
            assertEquals(a.runs(), b.runs(), log.toString());
            assertEquals(a.records(), b.records(), log.toString());
            assertEquals(a.problems(), b.problems(), log.toString());
        }
    }

    @Test
    void theFirstUnreadableLogInOrderIsReported() throws IOException {
        List<Path> logs = new ArrayList<>(logs(4));
        logs.add(1, dir.resolve("missing-a.log"));
        logs.add(dir.resolve("missing-b.log"));
        Traces.ReadFailure e = assertThrows(Traces.ReadFailure.class,
                () -> Traces.readAll(logs, AbstractionFiles.defaults(), 3));
        assertEquals(dir.resolve("missing-a.log"), e.log());
    }
}
