package dev.predmon.learn;

import de.learnlib.algorithm.rpni.BlueFringeRPNIMealy;
import dev.predmon.mealy.MealyTrace;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.automaton.transducer.CompactMealy;
import net.automatalib.automaton.transducer.MealyMachine;
import net.automatalib.util.automaton.copy.AutomatonCopyMethod;
import net.automatalib.util.automaton.copy.AutomatonLowLevelCopy;

import java.util.List;

/**
 * A thin, reproducible wrapper of LearnLib's {@link BlueFringeRPNIMealy} (the thesis's Algorithm 3) that keeps
 * its pitfalls away from callers:
 * <ul>
 *   <li>samples are checked for conflicts first (LearnLib would throw a message-less
 *       {@code IllegalArgumentException} and lose the rest of a batch): callers get a {@link Conflict};</li>
 *   <li>samples go in one by one with {@code addSample(Word, Word)}, never through {@code DefaultQuery}, whose
 *       constructors are ambiguous when inputs and outputs are both strings;</li>
 *   <li>{@code computeModel()} is called once, and its result (a live view of the learner's prefix tree) is
 *       copied breadth-first into a {@link CompactMealy}, which also numbers states deterministically;</li>
 *   <li>the default canonical merge order, no parallelism: the same samples give the same machine.</li>
 * </ul>
 */
public final class MealyLearner {

    private MealyLearner() {
    }

    /**
     * Learns one Mealy machine from conflict-free samples.
     *
     * @throws IllegalArgumentException naming the two samples when some pair conflicts
     */
    public static CompactMealy<String, String> learn(Alphabet<String> alphabet, List<MealyTrace> samples) {
        for (int i = 0; i < samples.size(); i++) {
            for (int j = i + 1; j < samples.size(); j++) {
                Conflict c = Conflict.between(samples.get(i), samples.get(j));
                if (c != null) {
                    throw new IllegalArgumentException("conflicting samples: " + c.describe());
                }
            }
        }
        BlueFringeRPNIMealy<String, String> learner = new BlueFringeRPNIMealy<>(alphabet);
        learner.setDeterministic(true);
        for (MealyTrace s : samples) {
            learner.addSample(s.inputs(), s.outputs());
        }
        MealyMachine<?, String, ?, String> live = learner.computeModel();
        return copy(live, alphabet);
    }

    private static <S, T> CompactMealy<String, String> copy(MealyMachine<S, String, T, String> live,
                                                            Alphabet<String> alphabet) {
        CompactMealy<String, String> out = new CompactMealy<>(alphabet);
        AutomatonLowLevelCopy.copy(AutomatonCopyMethod.BFS, live, alphabet, out);
        return out;
    }
}
