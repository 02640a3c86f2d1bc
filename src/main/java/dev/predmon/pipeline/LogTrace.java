package dev.predmon.pipeline;

import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.compact.IoPair;
import dev.predmon.mealy.MealyMapping;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.parse.ParseProblem;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * A whole log read offline through the {@link TracePipeline}.
 *
 * @param log              the file
 * @param pairs            the compacted trace, every run's pairs in log order
 * @param problems         what the parser reported (first {@link Traces#MAX_PROBLEMS} only)
 * @param lines            lines read
 * @param records          records parsed
 * @param interfaceRecords records of the skill-component interface
 * @param unmapped         interface messages no rule maps, by key
 * @param runs             the runs the log holds (one, unless the robot ran several missions in it)
 * @param span             the lines from its first record to the end of its last ({@link TracePipeline#span()})
 */
public record LogTrace(Path log, List<IoPair> pairs, List<ParseProblem> problems, long lines, long records,
                       long interfaceRecords, Map<UnmappedMessage, Long> unmapped, List<Run> runs, long span) {

    /**
     * One run of a log.
     *
     * @param index     0, 1, ... in log order
     * @param firstLine the line of its first record
     * @param pairs     its compacted trace
     * @param violated  whether the safety monitor saw its property violated in this run
     * @param readings  the values of each continuous rule's replies in order, by the rule's input
     *                  ({@code level_i}): what the learner estimates a sensor's noise from
     * @param timing    when each pair came, the property's value then, and when the run violated and ended: what the
     *                  forecast's statistics are learned from
     */
    public record Run(int index, long firstLine, List<IoPair> pairs, boolean violated, Map<String, List<Double>> readings,
                      RunTiming timing) {

        /** A run without timing (tests of what does not need it). */
        public Run(int index, long firstLine, List<IoPair> pairs, boolean violated, Map<String, List<Double>> readings) {
            this(index, firstLine, pairs, violated, readings, RunTiming.none(pairs.size()));
        }

        /**
         * Whether the run violated the property {@code id} (its outcome is the set of properties it violated,
         * {@link RunTiming#violations}); when {@code id} is null, the property the forecast follows
         * ({@link #violated()}).
         */
        public boolean violated(String id) {
            return id == null ? violated : timing.violated(id);
        }
    }

    /** The trace as one Mealy sample (a log of one run). */
    public MealyTrace mealy() {
        return MealyMapping.toTrace(pairs, log.toString());
    }

    /**
     * One Mealy sample per run with interface messages, of the runs {@code label} selects; a run after the first is
     * named {@code log#run}.
     */
    public List<MealyTrace> samples(RunLabel label) {
        List<MealyTrace> samples = new ArrayList<>();
        for (Run r : runs) {
            if (!r.pairs().isEmpty() && label.selects(r.violated())) {
                samples.add(MealyMapping.toTrace(r.pairs(), RunId.of(log, r.index(), runs.size()).name()));
            }
        }
        return samples;
    }

    /**
     * The samples verify, classify and explain judge: one per run with interface messages in a log of several runs,
     * else the whole trace.
     */
    public List<MealyTrace> judgedRuns() {
        return runs.size() > 1 ? samples(RunLabel.ALL) : List.of(mealy());
    }

    /**
     * The runs behind {@link #judgedRuns}, in the same order: whether each violated the property, and when each pair
     * and the violation came.
     */
    public List<Run> judgedRunsInFull() {
        return runs.size() > 1 ? runs.stream().filter(r -> !r.pairs().isEmpty()).toList() : runs;
    }

}
