package dev.predmon.forecast;

import dev.predmon.compact.IoPair;
import dev.predmon.mealy.MealyMapping;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunTiming;
import dev.predmon.pipeline.TriggerInputs;
import net.automatalib.automaton.transducer.CompactMealy;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * Learns the forecast's statistics: every training run, nominal and faulty, is replayed through every learned
 * machine for as long as the machine takes it (and never past the run's violation, which is what is forecast). Each
 * state counts the runs that passed through it and how many of them went on to violate, as Prevent's per-state
 * table does; the times to the violation or to the end, and the drift of the property, come with it.
 *
 * <p>Replaying the faulty runs through the nominal machines too is what makes the counts informative: a nominal
 * state that faulty runs also pass through is not safe, and a faulty state that nominal runs reach is not doomed.
 */
public final class StatsLearner {

    private StatsLearner() {
    }

    /**
     * The statistics of {@code machines} (by id) over {@code runs}.
     *
     * @param unit  the log's unit ({@code s} or {@code ticks})
     * @param limit the safety property's threshold, NaN without a property
     */
    public static ForecastModel learn(Map<String, CompactMealy<String, String>> machines, List<LogTrace.Run> runs,
                                      String unit, double limit) {
        Map<String, Map<Integer, StateStats>> states = new TreeMap<>();
        for (Map.Entry<String, CompactMealy<String, String>> m : machines.entrySet()) {
            states.put(m.getKey(), machineStats(m.getValue(), runs));
        }
        List<Double> safe = new ArrayList<>();
        List<Double> violating = new ArrayList<>();
        int counted = 0;
        int violated = 0;
        TreeSet<String> starts = new TreeSet<>();
        for (LogTrace.Run r : runs) {
            if (r.pairs().isEmpty()) {
                continue;
            }
            counted++;
            violated += r.violated() ? 1 : 0;
            starts.add(r.pairs().get(0).input());
            double low = r.timing().lowestSafeValue();
            if (!Double.isNaN(low)) {
                (r.violated() ? violating : safe).add(low);
            }
        }
        return new ForecastModel(ForecastModel.FORMAT, unit, limit, counted, violated,
                new Lows(toArray(safe), toArray(violating)), 0.5, "not chosen", false, states, List.copyOf(starts),
                Calibration.IDENTITY, List.of(), obligations(runs));
    }

    /** Per bounded-response property, how long the runs' obligations stayed pending, discharged or censored. */
    public static Map<String, Survival> obligations(List<LogTrace.Run> runs) {
        Map<String, List<RunTiming.Obligation>> byProperty = new TreeMap<>();
        for (LogTrace.Run r : runs) {
            for (RunTiming.Obligation o : r.timing().obligations()) {
                byProperty.computeIfAbsent(o.property(), k -> new ArrayList<>()).add(o);
            }
        }
        Map<String, Survival> out = new TreeMap<>();
        byProperty.forEach((id, all) -> {
            Map<String, List<RunTiming.Obligation>> byInput = new TreeMap<>();
            for (RunTiming.Obligation o : all) {
                if (o.input() != null) { // under its full condition, and under its trigger's input alone
                    byInput.computeIfAbsent(o.input(), k -> new ArrayList<>()).add(o);
                    String input = TriggerInputs.input(o.input());
                    if (!input.equals(o.input())) {
                        byInput.computeIfAbsent(input, k -> new ArrayList<>()).add(o);
                    }
                }
            }
            Map<String, Survival> contexts = new TreeMap<>();
            byInput.forEach((input, os) -> contexts.put(input, survival(os)));
            out.put(id, survival(all).withContexts(contexts));
        });
        return out;
    }

    /** The curve of {@code obligations}, discharged or censored. */
    private static Survival survival(List<RunTiming.Obligation> obligations) {
        return new Survival(toArray(obligations.stream().filter(RunTiming.Obligation::discharged)
                .map(RunTiming.Obligation::duration).toList()), toArray(obligations.stream()
                .filter(o -> !o.discharged()).map(RunTiming.Obligation::duration).toList()));
    }

    /** Per state of {@code machine}: counts, times and drift over the runs it takes. */
    static Map<Integer, StateStats> machineStats(CompactMealy<String, String> machine, List<LogTrace.Run> runs) {
        Map<Integer, Acc> acc = new HashMap<>();
        for (LogTrace.Run r : runs) {
            replay(machine, r, acc);
        }
        Map<Integer, StateStats> out = new TreeMap<>();
        acc.forEach((state, a) -> out.put(state, a.stats()));
        return out;
    }

    private static void replay(CompactMealy<String, String> machine, LogTrace.Run run, Map<Integer, Acc> acc) {
        RunTiming t = run.timing();
        List<IoPair> pairs = run.pairs();
        Map<Integer, Integer> firstVisit = new LinkedHashMap<>(); // state -> the pair that first reached it
        Map<Integer, double[]> drift = new HashMap<>(); // state -> {sum of value change, sum of time}
        int state = machine.getInitialState();
        for (int i = 0; i < pairs.size(); i++) {
            double time = t.time(i);
            if (run.violated() && !(time < t.violationTime())) {
                break; // what comes after the violation is not forecast
            }
            int next = MealyMapping.pairStep(machine, state, pairs.get(i).input(), pairs.get(i).output());
            if (next < 0) {
                break;
            }
            state = next;
            firstVisit.putIfAbsent(state, i);
            if (i + 1 < pairs.size()) {
                double dt = t.time(i + 1) - time;
                double dv = t.value(i + 1) - t.value(i);
                if (dt > 0 && !Double.isNaN(dv) && (!run.violated() || t.time(i + 1) < t.violationTime())) {
                    double[] d = drift.computeIfAbsent(state, s -> new double[2]);
                    d[0] += dv;
                    d[1] += dt;
                }
            }
        }
        double end = run.violated() ? t.violationTime() : t.endTime();
        double[] suffixLow = suffixMinima(t, run);
        for (Map.Entry<Integer, Integer> v : firstVisit.entrySet()) {
            Acc a = acc.computeIfAbsent(v.getKey(), s -> new Acc());
            a.runs++;
            double low = suffixLow[v.getValue()];
            if (!Double.isNaN(low)) {
                (run.violated() ? a.violatingLows : a.safeLows).add(low);
            }
            double left = end - t.time(v.getValue());
            if (run.violated()) {
                a.violated++;
                if (!Double.isNaN(left)) {
                    a.toViolation.add(left);
                }
            } else if (!Double.isNaN(left)) {
                a.toEnd.add(left);
            }
            double[] d = drift.get(v.getKey());
            if (d != null && d[1] > 0) {
                a.rates.add(d[0] / d[1]);
            }
        }
    }

    /**
     * For each pair, the lowest value the run read at that pair or later, before its violation: the readings between
     * pairs count, since the battery falls inside a band without a pair to show it.
     */
    private static double[] suffixMinima(RunTiming t, LogTrace.Run run) {
        double[] low = new double[t.size()];
        List<RunTiming.Reading> readings = t.readings();
        int r = readings.size() - 1;
        double min = Double.NaN;
        for (int i = t.size() - 1; i >= 0; i--) {
            for (; r >= 0 && readings.get(r).pairsBefore() > i; r--) {
                min = lower(min, readings.get(r).value(), readings.get(r).time(), t, run);
            }
            min = lower(min, t.value(i), t.time(i), t, run);
            low[i] = min;
        }
        return low;
    }

    private static double lower(double min, double v, double time, RunTiming t, LogTrace.Run run) {
        boolean safe = !run.violated() || time < t.violationTime();
        return safe && !Double.isNaN(v) && !(v >= min) ? v : min;
    }

    /** {@code values} sorted. */
    private static double[] sorted(List<Double> values) {
        double[] s = toArray(values);
        Arrays.sort(s);
        return s;
    }

    /** The {@code q}-quantile of {@code sorted} values (nearest rank), NaN when empty. */
    static double quantile(double[] sorted, double q) {
        if (sorted.length == 0) {
            return Double.NaN;
        }
        int i = (int) Math.round(q * (sorted.length - 1));
        return sorted[Math.max(0, Math.min(sorted.length - 1, i))];
    }

    private static double[] toArray(List<Double> values) {
        return values.stream().mapToDouble(Double::doubleValue).toArray();
    }

    private static final class Acc {
        int runs;
        int violated;
        final List<Double> toViolation = new ArrayList<>();
        final List<Double> toEnd = new ArrayList<>();
        final List<Double> rates = new ArrayList<>();
        final List<Double> safeLows = new ArrayList<>();
        final List<Double> violatingLows = new ArrayList<>();

        StateStats stats() {
            double mean = Double.NaN;
            double spread = Double.NaN;
            if (!rates.isEmpty()) {
                mean = rates.stream().mapToDouble(Double::doubleValue).average().orElse(Double.NaN);
                double m = mean;
                spread = Math.sqrt(rates.stream().mapToDouble(r -> (r - m) * (r - m)).sum() / rates.size());
            }
            double[] times = sorted(toViolation);
            return new StateStats(runs, violated, quantile(times, 0.1), quantile(times, 0.5), quantile(times, 0.9),
                    quantile(sorted(toEnd), 0.5), mean, spread, rates.size(),
                    new Lows(toArray(safeLows), toArray(violatingLows)));
        }
    }
}
