package dev.predmon.forecast;

import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunTiming;
import dev.predmon.property.Property;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The training runs as one absence or precedence sees them, so that {@link StatsLearner} learns its forecast as it
 * learns a bound's ({@link BoundRuns}): labelled by the property's own violation (its event came, or came out of
 * order), at the time the checker saw it, with the property's <em>indicator</em> as its value: {@value EventModel#HOLDS}
 * while it holds, {@value EventModel#BROKEN} once violated. The forecast of an event is the forecast of that indicator
 * falling below its floor of {@value EventModel#HOLDS}: a value that never moves before the violation, so that what
 * each state's table counts is only which runs passed through the state and how many of them went on to violate.
 *
 * <p>A run that gave no evidence for the property (nothing it speaks of occurred: {@link RunTiming#unobserved}) is
 * neither safe nor violating for it and is left out.
 */
public final class EventRuns {

    private EventRuns() {
    }

    /** {@code runs} as {@code p} sees them: those with evidence for it, each labelled by its own violation. */
    public static List<LogTrace.Run> view(Property p, List<LogTrace.Run> runs) {
        List<LogTrace.Run> out = new ArrayList<>(runs.size());
        for (LogTrace.Run r : runs) {
            if (!r.timing().unobserved().contains(p.id())) {
                out.add(view(p.id(), r));
            }
        }
        return out;
    }

    private static LogTrace.Run view(String id, LogTrace.Run run) {
        RunTiming t = run.timing();
        boolean violated = t.violated(id);
        double[] values = new double[t.size()];
        Arrays.fill(values, EventModel.HOLDS);
        RunTiming timing = new RunTiming(t.times(), values, violated ? t.violations().get(id) : Double.NaN,
                t.endTime(), EventModel.HOLDS, t.unit(), List.of(), t.gaps(), List.of(), t.violations());
        return new LogTrace.Run(run.index(), run.firstLine(), run.pairs(), violated, run.readings(), timing);
    }
}
