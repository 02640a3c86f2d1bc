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
 * @param values        the property's value at each forecast as the property reads it (NaN before a reading)
 * @param novel         whether the run was novel at each forecast
 * @param matchingAt    when the thesis's matching first warned of the property before its violation, NaN if not
 * @param noveltyAt     when the clause beyond the safe training runs first warned before the violation, NaN if not
 */
public record HeldOutRun(boolean violated, List<Double> probabilities, List<Double> times, double warnedAt,
                         double violationTime, List<ReplayedRun.Obligation> obligations, List<Double> values,
                         List<Boolean> novel, double matchingAt, double noveltyAt) {

    public HeldOutRun {
        probabilities = List.copyOf(probabilities);
        times = List.copyOf(times);
        obligations = List.copyOf(obligations);
        values = List.copyOf(values);
        novel = List.copyOf(novel);
    }

    /** A run whose forecasts' values are not kept, every clause's warning counted as the novelty clause's. */
    public HeldOutRun(boolean violated, List<Double> probabilities, List<Double> times, double warnedAt,
                      double violationTime, List<ReplayedRun.Obligation> obligations) {
        this(violated, probabilities, times, warnedAt, violationTime, obligations, List.of(), List.of(), Double.NaN,
                warnedAt);
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
     * @param bounds by id, every bound property's, absence's and precedence's with a forecast of its own, the runs
     *               as it saw them: its own violation, forecasts and warning
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
        String safety = abstraction.safety().map(b -> b.id()).orElse(null);
        Map<String, List<HeldOutRun>> bounds = new TreeMap<>();
        List<String> own = new ArrayList<>(models.forecast().bounds().keySet());
        models.forecast().events().forEach((id, e) -> {
            if (e.forecasts()) {
                own.add(id);
            }
        });
        for (String id : own) {
            List<HeldOutRun> runs = new ArrayList<>();
            for (ReplayedRun r : replayed.runs()) {
                if (!r.pairs().isEmpty() && label.selects(r.violated())) {
                    runs.add(ofProperty(r, id));
                }
            }
            bounds.put(id, runs);
        }
        return new Judged(of(replayed, label, safety), bounds);
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
        return of(r, r.boundBeforeViolation(id), w == null ? Double.NaN : w.time(), v, id, List.of());
    }

    /**
     * Run {@code r} as the property {@code id} saw it: its forecasts {@code f} before its violation {@code v}, its
     * first warning before it at {@code warnedAt}, and when each of the rule's clauses first warned of it.
     */
    private static HeldOutRun of(ReplayedRun r, List<ReplayedRun.Timed> f, double warnedAt, MonitorEvent.Violation v,
                                 String id, List<ReplayedRun.Obligation> obligations) {
        double matching = Double.NaN;
        double novelty = Double.NaN;
        for (MonitorEvent e : r.events()) {
            if (e instanceof MonitorEvent.Warning x && (x.property() == null || x.property().equals(id))
                    && (v == null || x.line() < v.line())) {
                if (x.clause() == MonitorEvent.Clause.MATCHING && Double.isNaN(matching)) {
                    matching = x.time();
                } else if (x.clause() == MonitorEvent.Clause.NOVELTY && Double.isNaN(novelty)) {
                    novelty = x.time();
                }
            }
        }
        return new HeldOutRun(v != null, f.stream().map(t -> t.forecast().probability()).toList(),
                f.stream().map(ReplayedRun.Timed::time).toList(), warnedAt, v == null ? Double.NaN : v.time(),
                obligations, f.stream().map(t -> t.forecast().value() == null ? Double.NaN : t.forecast().value())
                .toList(), f.stream().map(t -> t.forecast().novel()).toList(), matching, novelty);
    }

    private static List<HeldOutRun> of(ReplayedLog replayed, RunLabel label, String safety) {
        List<HeldOutRun> out = new ArrayList<>();
        for (ReplayedRun r : replayed.runs()) {
            if (r.pairs().isEmpty() || !label.selects(r.violated())) {
                continue;
            }
            RunOutcome o = r.outcome();
            MonitorEvent.Warning w = o.warning();
            MonitorEvent.Violation v = o.violation();
            boolean before = w != null && (v == null || w.line() < v.line());
            out.add(of(r, r.beforeViolation(), before ? w.time() : Double.NaN, v, safety, r.obligations()));
        }
        return out;
    }
}
