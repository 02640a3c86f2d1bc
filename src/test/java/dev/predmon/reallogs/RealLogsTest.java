package dev.predmon.reallogs;

import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.parse.Clock;
import dev.predmon.parse.LogReader;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;
import dev.predmon.parse.RecordKind;
import dev.predmon.property.Bound;
import dev.predmon.support.RealLogs;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

import java.io.IOException;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Every recording of the real monitor is read with exactly the counts of its README's table (commands, replies,
 * ticks; a record cut off at the end of the file is reported, not counted), and the built-in safety monitor finds
 * exactly the table's violation: the first {@code level} reply below 20.0 on {@code /BatteryComponent} to
 * {@code /BatteryReaderBatteryLevelClient}, at the table's tick.
 */
class RealLogsTest {

    private static final class Seen {
        final Map<RecordKind, Long> kinds = new EnumMap<>(RecordKind.class);
        final List<ParseProblem> problems = new ArrayList<>();
        Double first;
        double lowest = Double.POSITIVE_INFINITY;
        LogRecord violation;
        boolean allTicks = true;
    }

    @Test
    void everyRecordingHasItsTablesCountsAndViolation() throws IOException {
        Bound safety = AbstractionFiles.defaults().safety().orElseThrow();
        List<Executable> checks = new ArrayList<>();
        for (RealLogs.Row row : RealLogs.rows()) {
            Seen seen = new Seen();
            long records = LogReader.read(row.path(), r -> {
                seen.kinds.merge(r.kind(), 1L, Long::sum);
                seen.allTicks &= r.clock() == Clock.TICKS;
                double v = safety.valueOf(r);
                if (!Double.isNaN(v)) {
                    seen.first = seen.first == null ? v : seen.first;
                    seen.lowest = Math.min(seen.lowest, v);
                    if (seen.violation == null && safety.violatedBy(v)) {
                        seen.violation = r;
                    }
                }
            }, seen.problems::add);
            checks.add(() -> {
                String f = row.file();
                assertEquals(row.commands(), seen.kinds.getOrDefault(RecordKind.COMMAND, 0L), f + ": commands");
                assertEquals(row.replies(), seen.kinds.getOrDefault(RecordKind.REPLY, 0L), f + ": replies");
                assertEquals(row.ticks(), seen.kinds.getOrDefault(RecordKind.TICK, 0L), f + ": ticks");
                assertEquals(row.commands() + row.replies() + row.ticks(), records, f + ": records");
                assertTrue(seen.allTicks, f + ": a console capture has no time stamps, its clock is the tick");
                assertEquals(row.firstLevel(), seen.first, 0.05, f + ": first level");
                assertEquals(row.lowestLevel(), seen.lowest, 0.05, f + ": lowest level");
                // Nothing but a record cut off by the end of the capture may be reported.
                assertTrue(seen.problems.stream().allMatch(p -> p.severity() == ParseProblem.Severity.WARNING
                        && p.message().startsWith("log ends in the middle of a record")), f + ": " + seen.problems);
                if (row.violationTick().isPresent()) {
                    assertNotNull(seen.violation, f + ": violation");
                    assertEquals(row.violationTick().getAsInt(), seen.violation.time(), f + ": tick of the violation");
                    assertTrue(seen.violation.line() > 0, f + ": line of the violation");
                } else {
                    assertNull(seen.violation, f + ": no violation");
                }
            });
        }
        assertAll(checks);
    }
}
