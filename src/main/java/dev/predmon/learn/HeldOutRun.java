package dev.predmon.learn;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.RunOutcome;
import dev.predmon.monitor.WarningRule;
import dev.predmon.pipeline.RunLabel;
import dev.predmon.replay.LogReplay;
import dev.predmon.replay.ReplayedLog;
import dev.predmon.replay.ReplayedRun;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * One held-out run as {@code watch} forecasts it with a fold's models: every forecast before the property's violation,
 * with its time, and when the rule warned it before that violation; and every obligation of a bounded response with
 * its deadline forecasts. Made by replaying the log through the one replay
 * ({@link LogReplay}), so that the thresholds and the calibrations are chosen on the forecasts {@code watch} makes.
 *
 * @param violated      whether the forecast property was violated in the run
 * @param probabilities the raw probability of each forecast before the violation, in order
 * @param times         the time of each
 * @param warnedAt      the time of the run's first warning when it came before the violation, NaN otherwise
 * @param violationTime the time of the violation, NaN for a run that held
 * @param obligations   every obligation of a bounded response that the monitor forecast and that ended in the run,
 *                      with its deadline forecasts ({@link ReplayedRun#obligations})
 */
public record HeldOutRun(boolean violated, List<Double> probabilities, List<Double> times, double warnedAt,
                         double violationTime, List<ReplayedRun.Obligation> obligations) {

    public HeldOutRun {
        probabilities = List.copyOf(probabilities);
        times = List.copyOf(times);
        obligations = List.copyOf(obligations);
    }

    /** A threshold no probability reaches: a replay with it warns only by the rule's other clauses. */
    public static final double NEVER = 2;

    /** The highest probability before the violation (0 without a forecast). */
    public double peak() {
        return probabilities.stream().mapToDouble(p -> p).max().orElse(0);
    }

    /**
     * The runs of one replay, as the forecast's property and as each bound property with a forecast of its own in
     * {@code models} saw them.
     *
     * @param safety the runs as the forecast's property saw them
     * @param bounds by bound property id, the runs as it saw them: its own violation, forecasts and warning
     */
    public record Judged(List<HeldOutRun> safety, Map<String, List<HeldOutRun>> bounds) {
    }

    /**
     * The runs of {@code log} that {@code label} selects and that have a pair, replayed once against {@code models}
     * (which carry a forecast) by {@code rule} with exact matching, as {@code watch} replays them: as the forecast's
     * property and every bound property saw them.
     */
    public static Judged replayAll(Path log, RunLabel label, ModelSet models, Abstraction abstraction, int confirm,
                                   WarningRule rule) throws IOException {
        ReplayedLog replayed = LogReplay.replay(log, models, abstraction, 0, confirm, rule, (r, run, judged) -> { });
        Map<String, List<HeldOutRun>> bounds = new TreeMap<>();
        for (String id : models.forecast().bounds().keySet()) {
            List<HeldOutRun> runs = new ArrayList<>();
            for (ReplayedRun r : replayed.runs()) {
                if (!r.pairs().isEmpty() && label.selects(r.violated())) {
                    runs.add(ofProperty(r, id));
                }
            }
            bounds.put(id, runs);
        }
        return new Judged(of(replayed, label), bounds);
    }

    /** Run {@code r} as bound property {@code id} saw it; the obligations go with the forecast property's run. */
    private static HeldOutRun ofProperty(ReplayedRun r, String id) {
        MonitorEvent.Violation v = null;
        MonitorEvent.Warning w = null;
        for (MonitorEvent e : r.events()) {
            if (e instanceof MonitorEvent.Violation x && id.equals(x.property()) && v == null) {
                v = x;
            } else if (e instanceof MonitorEvent.Warning x && id.equals(x.property()) && v == null && w == null) {
                w = x;
            }
        }
        List<ReplayedRun.Timed> f = r.boundBeforeViolation(id);
        return new HeldOutRun(v != null, f.stream().map(t -> t.forecast().probability()).toList(),
                f.stream().map(ReplayedRun.Timed::time).toList(), w == null ? Double.NaN : w.time(),
                v == null ? Double.NaN : v.time(), List.of());
    }

    private static List<HeldOutRun> of(ReplayedLog replayed, RunLabel label) {
        List<HeldOutRun> out = new ArrayList<>();
        for (ReplayedRun r : replayed.runs()) {
            if (r.pairs().isEmpty() || !label.selects(r.violated())) {
                continue;
            }
            RunOutcome o = r.outcome();
            MonitorEvent.Warning w = o.warning();
            MonitorEvent.Violation v = o.violation();
            boolean before = w != null && (v == null || w.line() < v.line());
            out.add(new HeldOutRun(r.violated(),
                    r.beforeViolation().stream().map(t -> t.forecast().probability()).toList(),
                    r.beforeViolation().stream().map(ReplayedRun.Timed::time).toList(),
                    before ? w.time() : Double.NaN, v == null ? Double.NaN : v.time(), r.obligations()));
        }
        return out;
    }
}
