package dev.predmon.forecast;

import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunTiming;
import dev.predmon.property.Bound;

import java.util.ArrayList;
import java.util.List;

/**
 * The training runs as one bound property other than the safety property sees them: labelled by that property's own
 * violation, with its own value at each pair, its own readings and its own lowest safe value, on the scale of the side
 * forecast ({@link BoundModel}: a ceiling mirrored). {@link StatsLearner} learns the property's forecast from them as it
 * learns the safety property's from the runs themselves.
 */
public final class BoundRuns {

    private BoundRuns() {
    }

    /**
     * The side of {@code b} its forecast predicts: its only one, or for a bound with both a floor and a ceiling, the
     * side more of the violating {@code runs} crossed first (the floor on a tie, or with no violating run); null for a
     * bound with neither.
     */
    public static String side(Bound b, List<LogTrace.Run> runs) {
        boolean floor = b.hasFloor();
        boolean ceiling = b.ceiling() != Double.POSITIVE_INFINITY;
        if (!ceiling) {
            return floor ? BoundModel.FLOOR : null;
        }
        if (!floor) {
            return BoundModel.CEILING;
        }
        int below = 0;
        int above = 0;
        for (LogTrace.Run r : runs) {
            if (!r.timing().violated(b.id())) {
                continue;
            }
            for (RunTiming.Reading x : readings(r, b)) {
                if (b.violatedBy(x.value())) {
                    below += x.value() < b.floor() ? 1 : 0;
                    above += x.value() > b.ceiling() ? 1 : 0;
                    break;
                }
            }
        }
        return above > below ? BoundModel.CEILING : BoundModel.FLOOR;
    }

    /** {@code runs} as {@code b} sees them, forecast on {@code side}. */
    public static List<LogTrace.Run> view(Bound b, String side, List<LogTrace.Run> runs) {
        List<LogTrace.Run> out = new ArrayList<>(runs.size());
        for (LogTrace.Run r : runs) {
            out.add(view(b, side, r));
        }
        return out;
    }

    private static LogTrace.Run view(Bound b, String side, LogTrace.Run run) {
        RunTiming t = run.timing();
        boolean mirrored = BoundModel.CEILING.equals(side);
        boolean violated = t.violated(b.id());
        double violationTime = violated ? t.violations().get(b.id()) : Double.NaN;
        List<RunTiming.Reading> own = new ArrayList<>();
        double[] values = new double[t.size()];
        double lowest = Double.NaN;
        double value = Double.NaN;
        int next = 0;
        List<RunTiming.Reading> readings = readings(run, b);
        for (RunTiming.Reading x : readings) {
            double v = mirrored ? -x.value() : x.value();
            own.add(new RunTiming.Reading(x.time(), v, x.pairsBefore()));
            if ((!violated || x.time() < violationTime) && !(v >= lowest)) {
                lowest = v;
            }
        }
        for (int i = 0; i < values.length; i++) {
            // the value at pair i: the last reading before it completed
            for (; next < own.size() && own.get(next).pairsBefore() <= i; next++) {
                value = own.get(next).value();
            }
            values[i] = value;
        }
        RunTiming timing = new RunTiming(t.times(), values, violationTime, t.endTime(), lowest, t.unit(), own,
                t.gaps(), List.of(), t.violations());
        return new LogTrace.Run(run.index(), run.firstLine(), run.pairs(), violated, run.readings(), timing);
    }

    private static List<RunTiming.Reading> readings(LogTrace.Run r, Bound b) {
        return r.timing().bounds().getOrDefault(b.id(), List.of());
    }
}
