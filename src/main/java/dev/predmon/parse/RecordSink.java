package dev.predmon.parse;

import java.util.function.Consumer;

/** Where a {@link RecordSource} delivers what it reads from a log: records, problems and restarts, in log order. */
public interface RecordSink {

    /** The next record of the log. */
    void record(LogRecord record);

    /** Something in the log that could not be taken as a record. */
    void problem(ParseProblem problem);

    /**
     * The log was truncated ({@code "truncated"}) or replaced by another file ({@code "replaced"}), or a live robot's
     * connection was lost and made again ({@code "reconnected"}): the records that follow begin a new run. A source
     * that reads a file once never says so.
     */
    default void restarted(String reason) {
    }

    /** A sink of records and problems that ignores restarts (for a log read once). */
    static RecordSink of(Consumer<LogRecord> records, Consumer<ParseProblem> problems) {
        return new RecordSink() {
            @Override
            public void record(LogRecord record) {
                records.accept(record);
            }

            @Override
            public void problem(ParseProblem problem) {
                problems.accept(problem);
            }
        };
    }
}
