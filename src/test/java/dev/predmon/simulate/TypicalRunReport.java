package dev.predmon.simulate;

import org.junit.jupiter.api.Test;

import java.util.DoubleSummaryStatistics;
import java.util.IntSummaryStatistics;

/**
 * Prints what typical runs look like over seeds 1..200 (records, duration, sampling attempts, levels), for the
 * documentation; it asserts nothing that the other tests do not.
 */
class TypicalRunReport {

    @Test
    void printTypicalRuns() {
        for (Scenario s : Scenario.values()) {
            IntSummaryStatistics records = new IntSummaryStatistics();
            IntSummaryStatistics attempts = new IntSummaryStatistics();
            DoubleSummaryStatistics duration = new DoubleSummaryStatistics();
            DoubleSummaryStatistics turn = new DoubleSummaryStatistics();
            DoubleSummaryStatistics station = new DoubleSummaryStatistics();
            DoubleSummaryStatistics min = new DoubleSummaryStatistics();
            for (SimRun run : Runs.of(s)) {
                Truth t = run.truth();
                records.accept(run.events().size());
                attempts.accept(t.parameters().attempt() + 1);
                duration.accept(t.endTime() - run.events().get(0).time());
                if (t.turnLevel() != null) {
                    turn.accept(t.turnLevel());
                }
                if (t.stationLevel() != null) {
                    station.accept(t.stationLevel());
                }
                min.accept(t.batteryTimeline().stream().mapToDouble(p -> p[1]).min().orElse(Double.NaN));
            }
            System.out.printf("%-9s records %d..%d (mean %.0f), duration %.0f..%.0f s (mean %.0f), attempts mean %.2f"
                            + " max %d, turn level %s, station level %s, min level %.1f..%.1f%n",
                    s.id(), records.getMin(), records.getMax(), records.getAverage(), duration.getMin(),
                    duration.getMax(), duration.getAverage(), attempts.getAverage(), attempts.getMax(),
                    range(turn), range(station), min.getMin(), min.getMax());
        }
    }

    private static String range(DoubleSummaryStatistics d) {
        return d.getCount() == 0 ? "-" : String.format("%.1f..%.1f", d.getMin(), d.getMax());
    }
}
