package dev.predmon.simulate;

import com.fasterxml.jackson.annotation.JsonInclude;

/**
 * Whether a run violated one property, and where first: one entry of the truth's {@code properties}, judged by the
 * simulator from what it did ({@link PropertyJudge}), not read back from the log.
 *
 * @param violated whether the run violated the property
 * @param line     the log line of the record at which it was first violated (the line of its header), or null
 * @param tick     the tick of the tree in which it was first violated, or null
 * @param time     the log time of that record in seconds, or null
 */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record PropertyTruth(boolean violated, Long line, Integer tick, Double time) {

    /** The property held. */
    public static final PropertyTruth HOLDS = new PropertyTruth(false, null, null, null);

    /** The same verdict for the run {@code lines} lines and {@code seconds} later in its log. */
    PropertyTruth shifted(long lines, double seconds) {
        return violated ? new PropertyTruth(true, line + lines, tick, time + seconds) : this;
    }
}
