package dev.predmon.pipeline;

import dev.predmon.parse.ParseProblem;

import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;
import java.util.function.LongSupplier;

/**
 * No verdict on zero evidence. A log with no YARP monitor record ({@code /var/log/dpkg.log}, an empty file, random
 * bytes), or with records but no query/reply pair the abstraction maps, gives the models nothing to judge: every
 * model "matches" an empty trace, so a verdict on it would be silently wrong. This class says so in one line.
 *
 * @param log              the log
 * @param lines            its lines (only asked for when there is no record: it may cost a second read)
 * @param records          monitor records parsed
 * @param interfaceRecords records of the skill-component interface, mapped or not
 * @param pairs            compacted query/reply pairs
 * @param unmapped         interface messages no rule maps, by key
 * @param abstraction      the abstraction's name
 * @param firstProblem     the first parse problem, or null
 */
public record Evidence(Path log, LongSupplier lines, long records, long interfaceRecords, long pairs,
                       Map<String, Long> unmapped, String abstraction, ParseProblem firstProblem) {

    /** While following, nothing recognisable in this many lines (or records) is said once. */
    public static final long FIRST = 200;

    /** The evidence of a whole log read offline. */
    public static Evidence of(LogTrace trace, String abstraction) {
        return new Evidence(trace.log(), () -> Traces.countLines(trace.log()), trace.records(),
                trace.interfaceRecords(), trace.pairs().size(), trace.unmapped(), abstraction,
                trace.problems().isEmpty() ? null : trace.problems().get(0));
    }

    /** Why the complete log gives no evidence, in one line naming it; empty when it gives some. */
    public Optional<String> missing() {
        if (records == 0) {
            long n = lines.getAsLong();
            return Optional.of(log + ": no YARP monitor record in " + n + (n == 1 ? " line" : " lines")
                    + "; is this a monitor log?" + (firstProblem == null ? ""
                    : " (first problem: line " + firstProblem.line() + ": " + firstProblem.message() + ")"));
        }
        if (pairs == 0) {
            return Optional.of(log + ": " + nothingMapped("in " + records + (records == 1 ? " record" : " records"))
                    + "; no verdict without one: is this the robot's monitor log, and the right --abstraction?");
        }
        return Optional.empty();
    }

    /**
     * While following: after the first {@value #FIRST} lines without a record, or the first {@value #FIRST}
     * records without an interface message the abstraction maps, the line to say once; else empty.
     */
    public Optional<String> earlyNotice() {
        if (records == 0) {
            long n = lines.getAsLong();
            return n < FIRST ? Optional.empty() : Optional.of(log + ": no YARP monitor record in the first " + n
                    + " lines; is this a monitor log? (still watching)");
        }
        if (records >= FIRST && mapped() == 0) {
            return Optional.of(log + ": " + nothingMapped("in the first " + records + " records")
                    + "; is this the right --abstraction? (still watching)");
        }
        return Optional.empty();
    }

    /** Whether the log has shown something the abstraction maps: no notice can come any more. */
    public boolean recognised() {
        return records > 0 && mapped() > 0;
    }

    private long mapped() {
        return interfaceRecords - unmapped.values().stream().mapToLong(Long::longValue).sum();
    }

    private String nothingMapped(String where) {
        if (mapped() > 0) {
            return mapped() + " interface message(s) the abstraction '" + abstraction
                    + "' maps, but no complete query/reply pair " + where;
        }
        return "no skill-component interface message the abstraction '" + abstraction + "' maps " + where
                + (unmapped.isEmpty() ? "" : " (only " + String.join(", ", unmapped.keySet().stream().limit(3).toList())
                + (unmapped.size() > 3 ? ", ..." : "") + ")");
    }
}
