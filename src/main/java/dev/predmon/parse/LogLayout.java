package dev.predmon.parse;

/**
 * The grammar of one layout of monitor logs. {@link LogParser} detects the layout once per file and feeds every
 * line to its grammar; the grammar emits complete records and reports broken ones. Lines are numbered by the
 * parser and arrive without their terminator.
 */
interface LogLayout {

    /** One line, decoded. */
    void line(String text, long number);

    /**
     * One line as bytes, for the layout's fast path: returns {@code false}, having done nothing, when the line
     * must take the general path ({@link #line(String, long)}) instead.
     */
    default boolean fastLine(byte[] b, int offset, int length, long number) {
        return false;
    }

    /** A line longer than the reader's cap was skipped (it breaks the record in progress). */
    void overlongLine(long number, long bytes);

    /** The input is over: a record still in progress is reported once as a warning. */
    void endOfInput();
}
