package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.parse.ParseProblem;

import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.LongSupplier;

/**
 * No verdict on zero evidence. A log with no YARP monitor record ({@code /var/log/dpkg.log}, an empty file, random
 * bytes), or with records but no query/reply pair the abstraction maps, gives the models nothing to judge: every
 * model "matches" an empty trace, so a verdict on it would be silently wrong. Nor does a file that is mostly not
 * records (a fragment of a log amid other bytes: {@link #fragment()}), nor a log the models' abstraction does not fit
 * (most of its interface messages unmapped, or locations and commands the models never saw: {@link #misfit()}).
 * This class says so in one line.
 *
 * @param log              the log
 * @param lines            its lines (only asked for when there is no record: it may cost a second read)
 * @param records          monitor records parsed
 * @param interfaceRecords records of the skill-component interface, mapped or not
 * @param pairs            compacted query/reply pairs
 * @param unmapped         interface messages no rule maps, by key
 * @param abstraction      the abstraction the log is read with
 * @param firstProblem     the first parse problem, or null
 * @param span             the lines from the first record to the end of the last ({@link TracePipeline#span()})
 */
public record Evidence(Path log, LongSupplier lines, long records, long interfaceRecords, long pairs,
                       Map<UnmappedMessage, Long> unmapped, Abstraction abstraction, ParseProblem firstProblem, long span) {

    /** While following, nothing recognisable in this many records is said once. */
    public static final long FIRST = 200;
    /** While following, a file with no monitor record in this many lines is not a monitor log. */
    public static final long NOT_A_LOG_LINES = 1000;
    /** ... nor one that has had lines for this long without a monitor record. */
    public static final long NOT_A_LOG_MILLIS = 2500;
    /** The lines of a record (header and six fields), in every layout but the oldest, which has fewer. */
    static final int RECORD_LINES = 7;

    /** The evidence of a whole log read offline. */
    public static Evidence of(LogTrace trace, Abstraction abstraction) {
        return new Evidence(trace.log(), trace::lines, trace.records(),
                trace.interfaceRecords(), trace.pairs().size(), trace.unmapped(), abstraction,
                trace.problems().isEmpty() ? null : trace.problems().get(0), trace.span());
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
     * Why a whole file that holds records is still no evidence: its records make up less than half of its lines,
     * and lie within less than half of them (random bytes around a fragment of a log). A monitor's capture is
     * records from end to end, but for the lines of other programs between them (real captures: 1%, the simulator's
     * noisiest logs: 13%); a capture where another program wrote more lines than the monitor between its records is
     * still records from end to end, and is judged, as it is while followed.
     */
    public Optional<String> fragment() {
        long n = lines.getAsLong();
        if (records == 0 || records * RECORD_LINES * 2 >= n || span * 2 >= n) {
            return Optional.empty();
        }
        return Optional.of(log + ": only " + records + (records == 1 ? " monitor record" : " monitor records")
                + " in " + n + " lines (about " + Math.max(1, records * RECORD_LINES * 100 / n) + "% of the file); a "
                + "file that is mostly not a monitor log is no evidence: no verdict");
    }

    /** Why the models cannot judge this log, when the abstraction does not fit it ({@link UnmappedMessages#misfit}). */
    public Optional<String> misfit() {
        return UnmappedMessages.misfit(log.toString(), interfaceRecords, unmapped, abstraction, "no verdict");
    }

    /**
     * While following, {@code millis} after its first line: a file whose first {@value #NOT_A_LOG_LINES} lines, or
     * lines for {@value #NOT_A_LOG_MILLIS} ms, held no monitor record is not a monitor log: the line that says so;
     * else empty. YARP's own lines ({@code yarp} of them, {@code Port /monitor active at ...}) are a monitor log's
     * preamble, not evidence against it: with one, only {@value #NOT_A_LOG_LINES} lines of other programs without a
     * record make the file no monitor log, however long the monitor waits for the robot ({@link #preamble}).
     */
    public Optional<String> notALog(long millis, long yarp) {
        long n = records > 0 ? 0 : lines.getAsLong();
        long others = Math.max(0, n - yarp);
        if (n == 0 || (others < NOT_A_LOG_LINES && (yarp > 0 || millis < NOT_A_LOG_MILLIS))) {
            return Optional.empty();
        }
        return Optional.of(log + ": not a monitor log? no YARP monitor record in " + (n < NOT_A_LOG_LINES
                ? n + (n == 1 ? " line" : " lines") + " over " + String.format(Locale.ROOT, "%.1f", millis / 1000.0)
                + " s" : "the first " + n + " lines") + " (the monitor prints 'Command intercepted:' and 'Reply intercepted:'"
                + " records; see docs/logs.md)" + (firstProblem == null ? ""
                : "; first problem: line " + firstProblem.line() + ": " + firstProblem.message()));
    }

    /**
     * While following, {@code millis} after its first line: a file that after {@value #NOT_A_LOG_MILLIS} ms holds
     * YARP's start-up lines ({@code yarp} of them) and no record yet is a monitor started before the robot: the line
     * that says so, once, and that it is followed on; else empty.
     */
    public Optional<String> preamble(long millis, long yarp) {
        if (records > 0 || yarp == 0 || millis < NOT_A_LOG_MILLIS) {
            return Optional.empty();
        }
        return Optional.of(log + ": only YARP's start-up lines so far (" + yarp + (yarp == 1 ? " line" : " lines")
                + " such as 'Port /monitor active at ...'), no monitor record yet: the monitor runs and waits for "
                + "the robot; still watching");
    }

    /**
     * While following: after the first {@value #FIRST} records without an interface message the abstraction maps,
     * or of a log it does not fit, the line to say once; else empty ({@link #notALog} says when there is no record).
     */
    public Optional<String> earlyNotice() {
        if (records == 0) {
            return Optional.empty();
        }
        if (records >= FIRST && mapped() == 0) {
            return Optional.of(log + ": " + nothingMapped("in the first " + records + " records")
                    + "; is this the right --abstraction? (still watching)");
        }
        if (records >= FIRST) {
            return UnmappedMessages.misfit(log.toString(), interfaceRecords, unmapped, abstraction,
                    "still watching, after " + records + " records");
        }
        return Optional.empty();
    }

    /** Whether no notice can come any more: the first {@value #FIRST} records showed what the abstraction maps. */
    public boolean recognised() {
        return records >= FIRST && mapped() > 0;
    }

    private long mapped() {
        return interfaceRecords - unmapped.values().stream().mapToLong(Long::longValue).sum();
    }

    private String nothingMapped(String where) {
        if (mapped() > 0) {
            return mapped() + " interface message(s) the abstraction '" + abstraction.name()
                    + "' maps, but no complete query/reply pair " + where;
        }
        return "no skill-component interface message the abstraction '" + abstraction.name() + "' maps " + where
                + (unmapped.isEmpty() ? "" : " (only " + String.join(", ", unmapped.keySet().stream().limit(3).map(UnmappedMessage::text)
                .toList())
                + (unmapped.size() > 3 ? ", ..." : "") + ")");
    }
}
