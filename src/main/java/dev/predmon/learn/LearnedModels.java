package dev.predmon.learn;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.mealy.MealyAlphabet;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelIndex;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.automaton.transducer.CompactMealy;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/** Turns learned scenarios into what is stored ({@link ModelIndex}, DOT texts) or used in memory ({@link ModelSet}). */
public final class LearnedModels {

    private LearnedModels() {
    }

    /** The index describing {@code scenarios}, learned with {@code abstraction}. */
    public static ModelIndex index(List<LearnedScenario> scenarios, Abstraction abstraction) {
        List<ModelIndex.Scenario> entries = new ArrayList<>();
        for (LearnedScenario s : scenarios) {
            List<ModelIndex.Model> models = new ArrayList<>();
            int samples = 0;
            for (LearnedScenario.Machine m : s.machines()) {
                List<String> logs = m.samples().stream().map(t -> Path.of(t.source()).getFileName().toString()).toList();
                models.add(new ModelIndex.Model(m.id() + ".dot", m.machine().size(), m.samples().size(), logs));
                samples += m.samples().size();
            }
            entries.add(new ModelIndex.Scenario(s.spec().name(), s.spec().faulty(), s.spec().description(), samples,
                    List.copyOf(models), s.spec().violates()));
        }
        try {
            ModelIndex.AbstractionInfo info = new ModelIndex.AbstractionInfo(abstraction.name(),
                    abstraction.fingerprint(), new ObjectMapper().readTree(abstraction.canonicalJson()),
                    abstraction.learnedHysteresis());
            return new ModelIndex(ModelIndex.FORMAT, info, List.copyOf(MealyAlphabet.inputs(abstraction)),
                    List.copyOf(entries));
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("the abstraction's canonical JSON does not parse", e);
        }
    }

    /** DOT text of every machine by file name, in scenario order. */
    public static Map<String, String> dots(List<LearnedScenario> scenarios, Alphabet<String> alphabet) {
        Map<String, String> dots = new LinkedHashMap<>();
        for (LearnedScenario s : scenarios) {
            for (LearnedScenario.Machine m : s.machines()) {
                dots.put(m.id() + ".dot", ModelStore.toDot(m.machine(), alphabet));
            }
        }
        return dots;
    }

    /** The learned machines as a model set in memory, as {@code watch} would load them. */
    public static ModelSet modelSet(List<LearnedScenario> scenarios, Abstraction abstraction) {
        return modelSet(scenarios, abstraction, null);
    }

    /** The machines by id, in scenario order. */
    public static Map<String, CompactMealy<String, String>> machines(List<LearnedScenario> scenarios) {
        Map<String, CompactMealy<String, String>> machines = new LinkedHashMap<>();
        scenarios.forEach(s -> s.machines().forEach(m -> machines.put(m.id(), m.machine())));
        return machines;
    }

    /** The learned machines and their forecast as a model set in memory, as {@code watch} would load them. */
    public static ModelSet modelSet(List<LearnedScenario> scenarios, Abstraction abstraction, ForecastModel forecast) {
        return new ModelSet(null, index(scenarios, abstraction), models(scenarios, MealyAlphabet.inputs(abstraction)),
                forecast);
    }

    /** Every machine of {@code scenarios} as the monitor matches it, over {@code alphabet}, in scenario order. */
    public static List<LearnedModel> models(List<LearnedScenario> scenarios, Alphabet<String> alphabet) {
        List<LearnedModel> models = new ArrayList<>();
        for (LearnedScenario s : scenarios) {
            for (LearnedScenario.Machine m : s.machines()) {
                models.add(new LearnedModel(m.id(), s.spec().name(), s.spec().faulty(), m.machine(), alphabet));
            }
        }
        return List.copyOf(models);
    }

    /** All samples of a scenario, for export. */
    public static List<MealyTrace> samples(LearnedScenario s) {
        return s.machines().stream().flatMap(m -> m.samples().stream()).toList();
    }
}
