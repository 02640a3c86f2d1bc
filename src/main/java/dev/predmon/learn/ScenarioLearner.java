package dev.predmon.learn;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.mealy.MealyAlphabet;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.ModelStore;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.Traces;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.automaton.transducer.CompactMealy;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Consumer;

/**
 * Learns one scenario: every log through the shared pipeline, conflicting runs split into groups
 * ({@link ConflictGrouping}), one machine per group ({@link MealyLearner}).
 */
public final class ScenarioLearner {

    private ScenarioLearner() {
    }

    /** Reads the scenario's logs and learns it. */
    public static LearnedScenario learn(ScenarioSpec spec, Abstraction abstraction) throws BadInputException {
        return learn(spec, abstraction, read(spec.logs(), abstraction));
    }

    /** Reads logs through the shared pipeline, each once, on every core ({@link Traces#readAll}), in their order. */
    public static Map<Path, LogTrace> read(Collection<Path> logs, Abstraction abstraction) throws BadInputException {
        return read(logs, abstraction, log -> {
        });
    }

    /** {@link #read(Collection, Abstraction)}, telling {@code read} of each log in order as its trace is in. */
    public static Map<Path, LogTrace> read(Collection<Path> logs, Abstraction abstraction, Consumer<Path> read)
            throws BadInputException {
        try {
            return Traces.readAll(logs, abstraction, Runtime.getRuntime().availableProcessors(), read);
        } catch (Traces.ReadFailure e) {
            throw BadInputException.cannotRead(e.log(), e.getCause() instanceof IOException io ? io : e);
        }
    }

    /** Learns the scenario from its logs' traces, read with {@code abstraction}. */
    public static LearnedScenario learn(ScenarioSpec spec, Abstraction abstraction, Map<Path, LogTrace> traces)
            throws BadInputException {
        List<MealyTrace> samples = new ArrayList<>();
        List<String> skipped = new ArrayList<>();
        List<String> problems = new ArrayList<>();
        Map<UnmappedMessage, Long> unmapped = new TreeMap<>();
        for (Path log : spec.logs()) {
            LogTrace trace = traces.get(log);
            trace.problems().forEach(p -> problems.add(p.format(log.toString())));
            trace.unmapped().forEach((k, n) -> unmapped.merge(k, n, Long::sum));
            List<MealyTrace> runs = trace.samples(spec.runs());
            if (runs.isEmpty()) {
                skipped.add(log + ": no skill-component interface message (" + trace.records() + " records)");
            } else {
                samples.addAll(runs);
            }
        }
        if (samples.isEmpty()) {
            throw new BadInputException(spec.logs().get(0).getParent() + ": no log of scenario '" + spec.name()
                    + "' holds a skill-component interface message; nothing to learn");
        }
        LearnedScenario learned = learnSamples(spec, samples, MealyAlphabet.inputs(abstraction));
        return new LearnedScenario(spec, learned.machines(), learned.splits(), List.copyOf(skipped),
                List.copyOf(problems), Collections.unmodifiableMap(unmapped));
    }

    /** Learns from samples already mapped (used by {@code learn} and by cross-validation). */
    public static LearnedScenario learnSamples(ScenarioSpec spec, List<MealyTrace> samples, Alphabet<String> alphabet) {
        ConflictGrouping.Result grouping = ConflictGrouping.group(samples);
        List<LearnedScenario.Machine> machines = new ArrayList<>();
        int k = 1;
        for (List<MealyTrace> group : grouping.groups()) {
            String id = grouping.groups().size() == 1 ? spec.name() : spec.name() + "-" + k;
            long start = System.nanoTime();
            // In the state numbering a model directory is read back with, so that per-state statistics fit both.
            CompactMealy<String, String> m = ModelStore.canonical(MealyLearner.learn(alphabet, group), alphabet);
            long millis = (System.nanoTime() - start) / 1_000_000;
            machines.add(new LearnedScenario.Machine(id, m, group, millis));
            k++;
        }
        return new LearnedScenario(spec, List.copyOf(machines), grouping.splits(), List.of(), List.of(), Map.of());
    }
}
