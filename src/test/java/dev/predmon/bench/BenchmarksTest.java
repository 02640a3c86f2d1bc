package dev.predmon.bench;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * What {@code bench} says it measured: which properties were on, and a following watch's CPU per record over the
 * records it took. Figures are not judged here (a shared machine's speed is no test), only that they were measured.
 */
class BenchmarksTest {

    @Test
    void everyBuiltInPropertyIsOnAndNamedAndACpuFigurePerRecordIsPrinted(@TempDir Path dir) throws Exception {
        List<String> lines = new ArrayList<>();
        Benchmarks.run(List.of(Benchmarks.Kind.CPU), new Benchmarks.Options(1, 1, 1000, 1, 20_000, List.of(), 20, dir,
                List.of(), 1, 1, false, 0, 1000, dir), lines::add);
        assertEquals("properties on in every benchmark: 5 of abstraction thesis-tables-4.1-4.2-bands-5.2: battery "
                + "(forecast), charger-in-time, no-abort, navigation-in-time (deadline forecast), grasp-in-time",
                lines.get(1));
        String cpu = lines.get(lines.size() - 1);
        assertTrue(cpu.startsWith("watch cpu per record: a following watch (poll pause 1000 us) took "), cpu);
        long records = Long.parseLong(cpu.replaceAll(".* took (\\d+) records.*", "$1"));
        assertTrue(records >= 20_000 && records < 30_000, "the records asked for, to the end of a run: " + cpu);
        double nanos = Double.parseDouble(cpu.replaceAll(".* s: (\\d+) ns of its thread's CPU time.*", "$1"));
        assertTrue(nanos > 0, cpu);
    }

    @Test
    void theBagBenchmarkReadsEveryMessageAndPrintsItsFiguresBesideYarps(@TempDir Path dir) throws Exception {
        List<String> lines = new ArrayList<>();
        Benchmarks.run(List.of(Benchmarks.Kind.BAG), new Benchmarks.Options(1, 1, 1000, 1, 1, List.of(), 1, dir,
                List.of(), 1, 1, false, 0, 3000, dir), lines::add);
        String bag = lines.stream().filter(l -> l.startsWith("bag: read+decode")).findFirst().orElseThrow();
        assertTrue(bag.contains(" 3000 messages ") && bag.contains("messages/s"), bag);
        assertTrue(lines.stream().anyMatch(l -> l.startsWith("bag: beside it, the YARP parser")), lines.toString());
        assertTrue(lines.stream().anyMatch(l -> l.contains("(counted 3000)") || l.contains("could not be run")),
                lines.toString());
    }
}
