package dev.predmon.watch;

import dev.predmon.Terminal;
import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.event.EventJson;
import dev.predmon.event.ForecastJson;
import dev.predmon.event.PropertyJson;
import dev.predmon.forecast.ForecastWords;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.RunOutcome;
import dev.predmon.monitor.RunsSummary;
import dev.predmon.monitor.WatchedLog;
import dev.predmon.pipeline.UnmappedMessages;

import java.io.PrintWriter;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Optional;
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
        List<RunEnd> perRun = runs.stream().map(r -> new RunEnd(r.run(), r.firstLine(), r.pairs(),
                r.warning() != null, r.violation() != null, r.lead().orElse(null), r.noMatch(),
                ForecastJson.of(r.forecast()), r.run() == last.run() ? latest : PropertyJson.of(r.properties())))
                .toList();
        End end = new End("end", stop, m.records(), all.pairs(), m.warning().isPresent(), m.violation().isPresent(),
                first.lead().orElse(null), m.clock().unit(), all.noMatch(), perRun, all.runs(), all.dropped(),
                UnmappedMessages.texts(m.unmapped()), m.rule().id(), ForecastJson.of(last.forecast()), latest);
        out.println(EventJson.line(EventJson.stamped(end, settings.several() ? log.name() : null, Instant.now())));
    }

    private void text(WatchedLog log, String stop, boolean judged, IntFunction<Optional<String>> restartBefore) {
        PredictiveMonitor m = log.monitor();
        List<RunOutcome> runs = m.runs();
        RunsSummary all = m.summary();
        if (all.dropped() > 0) {
            out.println("(the first " + all.dropped() + " of " + all.runs() + " runs are counted, not listed)");
        }
        if (all.runs() > 1) {
            for (RunOutcome r : runs) {
                out.println("run " + r.run() + " (from line " + r.firstLine()
                        + restartBefore.apply(r.run()).map(how -> ", after the log was " + how).orElse("")
                        + "): " + r.pairs() + " compacted pairs; "
                        + (r.warned() ? "warning raised" : "no warning")
                        + (r.noMatch() ? ", no model matches the run" : "")
                        + (r.violation() != null ? ", property violated"
                        : r.safetyObserved() ? ", property held" : ", property not observed")
                        + r.lead().map(l -> ", lead " + EventPrinter.span(l, m.clock())).orElse("")
                        + (r.forecast() == null ? "" : "; last forecast " + ForecastWords.line(r.forecast())));
                if (judged) {
                    properties(log, r);
                }
            }
        }
        String verdict = !judged ? "no verdict"
                : (all.warned() ? "warning raised" : "no warning")
                + (all.noMatch() ? ", no model matches the run" : "")
                + (m.violation().isPresent() ? ", property violated"
                : all.safetyObserved() ? ", property held" : ", property not observed");
        out.println(settings.stamp().of(Instant.now()) + "end of " + Terminal.line(log.name())
                + (stop.equals("end-of-file") ? "" : " (stopped: " + stop + ")") + ": " + m.records() + " records, "
                + (all.runs() > 1 ? all.runs() + " runs, " : "") + all.pairs() + " compacted pairs; " + verdict);
        if (all.runs() == 1 && judged) {
            properties(log, runs.get(0));
        }
        RunOutcome last = runs.get(runs.size() - 1);
        if (all.runs() == 1 && last.forecast() != null) {
            // in a fleet every line names its log
            out.println((settings.several() ? Terminal.line(log.name()) + ": " : "") + "last forecast: "
                    + ForecastWords.line(last.forecast()));
        }
    }

    /**
     * Each property's verdict on run {@code r}, a line each, begun as the text lines of events are; for the last run
     * with each one's latest forecast, or why it has none.
     */
    private void properties(WatchedLog log, RunOutcome r) {
        String stamp = settings.stamp().of(Instant.now()) + (settings.several() ? Terminal.line(log.name()) + ":" : "");
        PredictiveMonitor m = log.monitor();
        List<RunOutcome> runs = m.runs();
        boolean last = r.run() == runs.get(runs.size() - 1).run();
        (last ? PropertyJson.latestLines(m.properties()) : PropertyJson.lines(r.properties()))
                .forEach(l -> out.println(stamp + Terminal.line(l))); // a property's name is the abstraction's text
    }

    /** One run's verdict in the {@code end} event. */
    record RunEnd(int run, long line, long pairs, boolean warning, boolean violation, Double lead, boolean noMatch,
                  ForecastJson forecast, List<PropertyJson> properties) {
    }

    /**
     * The {@code end} event. {@code violation} and {@code lead} are the forecast property's; {@code properties} are
     * every property's verdicts on the last run (each run's are in {@code runs}).
     */
    record End(String event, String stop, long records, long pairs, boolean warning, boolean violation, Double lead,
               String unit, boolean noMatch, List<RunEnd> runs, int runCount, int runsNotListed,
               Map<String, Long> unmapped, String rule, ForecastJson forecast, List<PropertyJson> properties) {
    }
}
