package dev.predmon.watch;

import dev.predmon.Terminal;
import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.event.EventJson;
import dev.predmon.event.ForecastJson;
import dev.predmon.event.OutcomeJson;
import dev.predmon.event.PropertyJson;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.PropertyOutcome;
import dev.predmon.monitor.RunOutcome;
import dev.predmon.monitor.RunsSummary;
import dev.predmon.monitor.WatchedLog;
import dev.predmon.pipeline.UnmappedMessages;

import java.io.PrintWriter;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.DoubleFunction;
import java.util.function.IntFunction;

/**
 * A log's end summary: its records, runs and pairs with the verdict (each run's too when it held several: whether a
 * warning of any property was raised, whether the forecast's property was violated), every property's verdict, the
 * last forecast; as text, or with {@code --json} as the {@code end} event. The interface
 * messages no rule maps go to stderr.
 */
final class Summary {

    private final PrintWriter out;
    private final PrintWriter err;
    private final WatchSettings settings;

    Summary(PrintWriter out, PrintWriter err, WatchSettings settings) {
        this.out = out;
        this.err = err;
        this.settings = settings;
    }

    PrintWriter err() {
        return err;
    }

    /**
     * Prints {@code log}'s end summary and returns the exit code of its verdict ({@link ExitRule#ofMonitor}).
     *
     * @param stop          why the watch ended: {@code end-of-file}, the signal, {@code interrupted}
     * @param judged        whether the log gets a verdict at all
     * @param restartBefore how a run began, when it began where the log was truncated or replaced
     */
    int print(WatchedLog log, String stop, boolean judged, IntFunction<Optional<String>> restartBefore) {
        PredictiveMonitor m = log.monitor();
        Map<UnmappedMessage, Long> unmapped = m.unmapped();
        ProblemLines.unmapped(err, log.path(), unmapped);
        if (settings.json()) {
            json(log, stop);
        } else {
            text(log, stop, judged, restartBefore);
        }
        out.flush();
        return ExitRule.ofMonitor(m);
    }

    private void json(WatchedLog log, String stop) {
        PredictiveMonitor m = log.monitor();
        List<RunOutcome> runs = m.runs();
        RunsSummary all = m.summary();
        RunOutcome first = all.firstWarned().orElse(runs.get(0));
        RunOutcome last = runs.get(runs.size() - 1);
        // the last run's properties with their latest forecasts, the earlier runs' with their verdicts
        List<PropertyJson> latest = PropertyJson.latest(m.properties());
        String forecastId = m.forecastProperty().orElse(null);
        List<List<PropertyOutcome>> outcomes = new ArrayList<>();
        List<RunEnd> perRun = new ArrayList<>();
        for (RunOutcome r : runs) {
            List<PropertyOutcome> o = PropertyOutcome.of(r, forecastId);
            outcomes.add(o);
            perRun.add(new RunEnd(r.run(), r.firstLine(), r.pairs(), r.warning() != null, r.violation() != null,
                    r.lead().orElse(null), r.noMatch(), ForecastJson.of(r.forecast()),
                    r.run() == last.run() ? latest : PropertyJson.of(r.properties()), OutcomeJson.of(o)));
        }
        End end = new End("end", stop, m.records(), all.pairs(), m.warning().isPresent(), m.violation().isPresent(),
                first.lead().orElse(null), m.clock().unit(), all.noMatch(), perRun, all.runs(), all.dropped(),
                UnmappedMessages.texts(m.unmapped()), m.rule().id(), ForecastJson.of(last.forecast()), latest,
                OutcomeJson.of(PropertyOutcome.worstOver(outcomes)));
        out.println(EventJson.line(EventJson.stamped(end, settings.several() ? log.name() : null, Instant.now())));
    }

    private void text(WatchedLog log, String stop, boolean judged, IntFunction<Optional<String>> restartBefore) {
        PredictiveMonitor m = log.monitor();
        List<RunOutcome> runs = m.runs();
        RunsSummary all = m.summary();
        if (all.dropped() > 0) {
            out.println("(the first " + all.dropped() + " of " + all.runs() + " runs are counted, not listed)");
        }
        String forecastId = m.forecastProperty().orElse(null);
        DoubleFunction<String> span = l -> EventPrinter.span(l, m.clock());
        List<List<PropertyOutcome>> outcomes = new ArrayList<>();
        for (RunOutcome r : runs) {
            outcomes.add(PropertyOutcome.of(r, forecastId));
        }
        if (all.runs() > 1) {
            for (int i = 0; i < runs.size(); i++) {
                RunOutcome r = runs.get(i);
                out.println("run " + r.run() + " (from line " + r.firstLine()
                        + restartBefore.apply(r.run()).map(how -> ", after " + MonitorEvent.Restarted.words(how)).orElse("")
                        + "): " + r.pairs() + " compacted pairs; "
                        + PropertyOutcome.sentence(outcomes.get(i), r.warned(), span)
                        + (r.noMatch() ? "; no model matches the run" : "")
                        + (r.forecast() == null ? "" : "; last forecast" + (forecastId == null ? "" : " of "
                        + forecastId) + " " + ForecastWords.line(r.forecast())));
                if (judged) {
                    properties(log, r, outcomes.get(i));
                }
            }
        }
        // every property any run violated or warned, worst first
        String verdict = !judged ? "no verdict"
                : PropertyOutcome.sentence(PropertyOutcome.worstOver(outcomes), all.warned(), span)
                + (all.noMatch() ? "; no model matches the run" : "");
        out.println(settings.stamp().of(Instant.now()) + "end of " + Terminal.line(log.name())
                + (stop.equals("end-of-file") ? "" : " (stopped: " + stop + ")") + ": " + m.records() + " records, "
                + (all.runs() > 1 ? all.runs() + " runs, " : "") + all.pairs() + " compacted pairs; " + verdict);
        if (all.runs() == 1 && judged) {
            properties(log, runs.get(0), outcomes.get(0));
        }
        RunOutcome last = runs.get(runs.size() - 1);
        if (all.runs() == 1 && last.forecast() != null) {
            // in a fleet every line names its log
            out.println((settings.several() ? Terminal.line(log.name()) + ": " : "") + "last forecast"
                    + (forecastId == null ? "" : " of " + forecastId) + ": " + ForecastWords.line(last.forecast()));
        }
    }

    /**
     * Each property's verdict on run {@code r}, a line each, worst first ({@code outcome}'s order), begun as the text
     * lines of events are; for the last run with each one's latest forecast, or why it has none.
     */
    private void properties(WatchedLog log, RunOutcome r, List<PropertyOutcome> outcome) {
        String stamp = settings.stamp().of(Instant.now()) + (settings.several() ? Terminal.line(log.name()) + ":" : "");
        PredictiveMonitor m = log.monitor();
        List<RunOutcome> runs = m.runs();
        boolean last = r.run() == runs.get(runs.size() - 1).run();
        List<String> order = outcome.stream().map(PropertyOutcome::id).toList();
        Comparator<String> worstFirst = Comparator.comparingInt(id -> order.indexOf(id) < 0 ? order.size()
                : order.indexOf(id));
        (last ? PropertyJson.latestLines(m.properties().stream()
                .sorted(Comparator.comparing(s -> s.property().id(), worstFirst)).toList())
                : PropertyJson.lines(r.properties().stream()
                .sorted(Comparator.comparing(pv -> pv.property().id(), worstFirst)).toList()))
                .forEach(l -> out.println(stamp + Terminal.line(l))); // a property's name is the abstraction's text
    }

    /**
     * One run's verdict in the {@code end} event: {@code outcome} per property, worst first; {@code warning},
     * {@code violation} and {@code lead} are the forecast property's alone, deprecated aliases kept for one release.
     */
    record RunEnd(int run, long line, long pairs, boolean warning, boolean violation, Double lead, boolean noMatch,
                  ForecastJson forecast, List<PropertyJson> properties, OutcomeJson outcome) {
    }

    /**
     * The {@code end} event. {@code outcome} is every run's, per property, worst first; {@code warning},
     * {@code violation} and {@code lead} are the forecast property's alone (deprecated aliases, kept for one release);
     * {@code properties} are every property's verdicts on the last run (each run's are in {@code runs}).
     */
    record End(String event, String stop, long records, long pairs, boolean warning, boolean violation, Double lead,
               String unit, boolean noMatch, List<RunEnd> runs, int runCount, int runsNotListed,
               Map<String, Long> unmapped, String rule, ForecastJson forecast, List<PropertyJson> properties,
               OutcomeJson outcome) {
    }
}
