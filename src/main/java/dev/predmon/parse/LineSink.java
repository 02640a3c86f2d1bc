package dev.predmon.parse;

import java.nio.charset.StandardCharsets;

/**
 * Receives the lines of a log as {@link LogReader} or {@link LogFollower} cut them out of the file.
 *
 * <p>{@link LogParser#lineSink()} is the usual implementation; a caller that wants to see restarts too
 * (to print them, say) wraps it.
 */
public interface LineSink {

    /** One complete line, decoded from UTF-8 (malformed bytes replaced by U+FFFD), without its terminator. */
    void line(String line);

    /**
     * One complete line as the bytes of the file, without its terminator (a trailing {@code '\r'} already
     * removed). The default decodes it as UTF-8 and calls {@link #line(String)}; a sink that can read bytes
     * directly (the parser, for its hot path) overrides it. The bytes are only valid during the call.
     */
    default void line(byte[] bytes, int offset, int length) {
        line(new String(bytes, offset, length, StandardCharsets.UTF_8));
    }

    /**
     * The input's last line, which no line terminator ended: the writer may have been stopped in the middle of it.
     * The default takes it as any other line.
     */
    default void lastLine(byte[] bytes, int offset, int length) {
        line(bytes, offset, length);
    }

    /**
     * The file was truncated ({@code "truncated"}) or replaced by another one ({@code "replaced"}); the lines
     * that follow come from its beginning. Everything of the old content was delivered before this call.
     */
    void restarted(String reason);

    /**
     * The file these lines came from is done with: no line of it follows (a file renamed away at a rotation that is
     * let go, or the end of a single pass). Its unterminated last line was delivered before. The default does nothing.
     */
    default void ended() {
    }

    /**
     * A line longer than the cap was skipped without being held in memory. It still counts as a line.
     * The default delivers an empty line in its place so that line numbers stay right;
     * {@link LogParser#lineSink()} reports it as an error instead.
     *
     * @param bytes the length of the skipped line in bytes, without its terminator
     */
    default void overlongLine(long bytes) {
        line("");
    }
}
