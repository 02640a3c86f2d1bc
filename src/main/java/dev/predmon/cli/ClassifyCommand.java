package dev.predmon.cli;

import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.Classifier;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunLabel;
import dev.predmon.pipeline.Traces;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;

/** {@code predmon classify}: Algorithm 7 on a complete log. */
@Command(name = "classify", mixinStandardHelpOptions = true,
        description = {"Classify a complete log against every model (thesis Algorithm 7): discrepancies per model, "
                + "models that could not take the trace, the best match and whether it is faulty.",
                "Exit 1 when the best match is a faulty scenario, 0 otherwise."})
final class ClassifyCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--log", required = true, paramLabel = "FILE", description = "The log to classify.")
    Path log;

    @Mixin
    ThresholdOption threshold;

    @Option(names = "--json", description = "Print the result as one JSON object.")
    boolean json;

    @Mixin
    ModelOptions models;

    @Mixin
    AbstractionOption abstractionOption;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        Abstraction abstraction = abstractionOption.load();
        ModelSet set = models.load(abstraction);
        abstraction = set.tune(abstraction); // the hysteresis learn estimated from the training runs' sensor noise
        LogTrace trace = Traces.read(log, abstraction);
        Problems.print(spec.commandLine().getErr(), log, trace);
        // A log of several runs (the tick counter started again) is classified run by run.
        List<MealyTrace> runs = trace.runs().size() > 1 ? trace.samples(RunLabel.ALL) : List.of(trace.mealy());
        boolean faulty = false;
        List<Map<String, Object>> results = new ArrayList<>();
        for (MealyTrace run : runs) {
            Classifier.Result r = Classifier.classify(set, run, threshold.value);
            faulty |= r.faulty();
            if (json) {
                results.add(toJson(r, run));
            } else {
                print(out, r, run);
            }
        }
        if (json) {
            Object o = results.size() == 1 ? results.get(0) : Map.of("log", log.toString(), "runs", results);
            out.println(new ObjectMapper().writeValueAsString(o));
        }
        out.flush();
        return faulty ? ExitCodes.WARNING : ExitCodes.OK;
    }

    private Map<String, Object> toJson(Classifier.Result r, MealyTrace run) {
        List<Map<String, Object>> scores = new ArrayList<>();
        for (Classifier.Score s : r.scores()) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("model", s.model().id());
            m.put("scenario", s.model().scenario());
            m.put("faulty", s.model().faulty());
            m.put("deleted", s.deleted());
            m.put("discrepancies", s.discrepancies());
            m.put("reason", s.failure() == null ? null : s.failure().describe());
            scores.add(m);
        }
        Map<String, Object> o = new LinkedHashMap<>();
        o.put("log", run.source());
        o.put("pairs", run.length() / 2);
        o.put("models", scores);
        o.put("best", r.best().map(s -> s.model().id()).orElse(null));
        o.put("scenario", r.best().map(s -> s.model().scenario()).orElse(null));
        o.put("faulty", r.faulty());
        return o;
    }

    private void print(PrintWriter out, Classifier.Result r, MealyTrace run) {
        out.println(run.source() + ": " + run.length() / 2 + " compacted pairs");
        for (Classifier.Score s : r.scores()) {
            out.printf("  %-16s %-8s %s%n", s.model().id(), s.model().faulty() ? "faulty" : "nominal",
                s.deleted() ? "deleted: " + s.failure().describe()
                        : s.discrepancies() + " discrepancies" + (s.failure() == null ? "" : "; first: " + s.failure().describe()));
        }
        out.println(r.best().map(s -> "best match: " + s.model().scenario() + " (" + s.model().id() + ", "
                + s.discrepancies() + " discrepancies)" + (s.model().faulty() ? ": FAULTY" : ""))
                .orElse("no model matches within threshold " + threshold.value));
    }
}
