package dev.predmon.pipeline;

import dev.predmon.compact.IoPair;
import dev.predmon.mealy.MealyMapping;
import dev.predmon.mealy.MealyTrace;
import dev.predmon.parse.ParseProblem;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * A whole log read offline through the {@link TracePipeline}.
 *
 * @param log              the file
 * @param pairs            the compacted trace
 * @param problems         what the parser reported (first {@link Traces#MAX_PROBLEMS} only)
 * @param records          records parsed
 * @param interfaceRecords records of the skill-component interface
 * @param unmapped         interface messages no rule maps, by key
 */
public record LogTrace(Path log, List<IoPair> pairs, List<ParseProblem> problems, long records,
                       long interfaceRecords, Map<String, Long> unmapped) {

    /** The trace as a Mealy sample. */
    public MealyTrace mealy() {
        return MealyMapping.toTrace(pairs, log.toString());
    }
}
