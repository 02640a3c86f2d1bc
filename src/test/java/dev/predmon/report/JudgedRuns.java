package dev.predmon.report;

import dev.predmon.evaluate.Confusion;
import dev.predmon.evaluate.Evaluation;
import dev.predmon.evaluate.RunResult;
import dev.predmon.evaluate.ScenarioSummary;
import dev.predmon.evaluate.Verdict;
import dev.predmon.pipeline.RunId;

import java.util.ArrayList;
import java.util.List;

/** Run results written by hand, one of each verdict, for tests of how the report shows them. */
final class JudgedRuns {

    /** Where every hand-written run starts: an epoch time, as a yarplogger log with absolute stamps has. */
    static final double START = 1_646_377_250.0;

    private JudgedRuns() {
    }

    /**
     * A run of {@code log}, its times given from {@code START}; null for absent ones. {@code nearBound} readings lay
     * near the bound before the violation.
     */
    static RunResult run(String log, boolean faulty, Double warning, Double violation, Double noMatch, int nearBound,
                         RunResult.Elimination... eliminations) {
        Double w = warning == null ? null : START + warning;
        Double v = violation == null ? null : START + violation;
        Verdict verdict = Verdict.of(faulty, w, v);
        Double lead = verdict == Verdict.WARNED_BEFORE_VIOLATION ? v - w : null;
        return new RunResult(faulty ? "depleted" : "recharge", faulty, id(log), 0, verdict, w, w == null ? null : 4019L,
                w == null ? List.of() : List.of("depleted"), w == null ? null : 28.7, v, lead, noMatch != null,
                noMatch == null ? null : START + noMatch, 873, 18, 0, List.of(eliminations), true, "s",
                v != null && nearBound < RunResult.SUDDEN_READINGS, START, nearBound, v == null ? null : 25.0);
    }

    /** A model eliminated at {@code time} from the start, on {@code line}. */
    /** The run a fixture names: {@code file}, or {@code file#k} for run k of a log of several. */
    private static RunId id(String name) {
        int hash = name.indexOf('#');
        return hash < 0 ? RunId.of(java.nio.file.Path.of(name), 0, 1)
                : RunId.of(java.nio.file.Path.of(name.substring(0, hash)), Integer.parseInt(name.substring(hash + 1)), 2);
    }

    static RunResult.Elimination gone(String model, double time, long line) {
        return new RunResult.Elimination(model, model, model.equals("depleted"), START + time, line,
                "cannot take input level_i_after_o_level_high at step 10");
    }

    /** One run of each verdict, and one no-match run that was not warned. */
    static List<RunResult> oneOfEach() {
        return List.of(
                run("logs/depleted/depleted-1.log", true, 23.5, 27.4, null, 6, gone("direct", 15.6, 2885),
                        gone("recharge", 23.5, 4019)),
                run("logs/depleted/depleted-2.log", true, 27.4, 27.4, null, 0, gone("recharge", 27.4, 4019)),
                run("logs/depleted/depleted-3.log", true, null, 44.0, null, 30),
                run("logs/recharge/recharge-8.log", false, 25.0, null, 25.0, 0, gone("recharge-1", 25.0, 4019)),
                run("logs/recharge/recharge-1.log#1", false, null, null, 19.6, 0, gone("direct", 2.0, 2885),
                        gone("depleted", 19.6, 3410), gone("recharge", 19.6, 3473)),
                run("logs/recharge/recharge-2.log", false, null, null, null, 0, gone("direct", 2.0, 2885)));
    }

    /** An evaluation of {@code runs}, without models. */
    static Evaluation evaluation(List<RunResult> runs) {
        List<ScenarioSummary> scenarios = new ArrayList<>();
        for (String s : List.of("depleted", "recharge")) {
            List<RunResult> own = runs.stream().filter(r -> r.scenario().equals(s)).toList();
            scenarios.add(ScenarioSummary.of(s, s.equals("depleted"), own));
        }
        return new Evaluation("cross-validation", 2, 0, "thesis", scenarios, Confusion.of(runs), runs, List.of(), null);
    }
}
