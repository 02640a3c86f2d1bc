package dev.predmon.parse;

import java.util.Arrays;

/**
 * Cuts a byte stream into lines for {@link LogReader} and {@link LogFollower}: splits on {@code '\n'}, drops a
 * trailing {@code '\r'}, decodes each line as UTF-8 replacing malformed input, and skips lines longer than a cap
 * without holding them.
 *
 * <p>Splitting bytes before decoding is safe because in UTF-8 the byte {@code '\n'} never occurs inside a
 * multi-byte character. The partial line is the only state; it never grows beyond the cap, so memory is constant.
 */
final class LineSplitter {

    /** Lines longer than this many bytes are skipped: a log line is a few hundred bytes, 1 MiB is garbage. */
    static final int DEFAULT_MAX_LINE_BYTES = 1 << 20;

    private final int maxLineBytes;
    private final LineSink sink;
    private byte[] partial = new byte[256];
    private int partialLength;
    /** Bytes of the current line seen beyond the cap; positive once the line is known to be overlong. */
    private long overflow;

    LineSplitter(int maxLineBytes, LineSink sink) {
        if (maxLineBytes < 1) {
            throw new IllegalArgumentException("maxLineBytes must be positive, got " + maxLineBytes);
        }
        this.maxLineBytes = maxLineBytes;
        this.sink = sink;
    }

    /** Consumes {@code length} bytes of {@code bytes} from {@code offset}, delivering each line they complete. */
    void feed(byte[] bytes, int offset, int length) {
        int start = offset;
        int end = offset + length;
        for (int i = Bytes.indexOfNewline(bytes, start, end); i >= 0; i = Bytes.indexOfNewline(bytes, start, end)) {
            if (partialLength == 0 && overflow == 0 && i - start <= maxLineBytes) {
                // The whole line is in this chunk: hand it over in place, without copying it first.
                deliver(bytes, start, i - start);
            } else {
                append(bytes, start, i - start);
                deliver(false);
            }
            start = i + 1;
        }
        append(bytes, start, end - start);
    }

    /** Whether bytes of an unterminated line are held. */
    boolean hasPartialLine() {
        return partialLength > 0 || overflow > 0;
    }

    /** The input is over: an unterminated last line is still a line and is delivered, as the last one. */
    void finish() {
        if (hasPartialLine()) {
            deliver(true);
        }
    }

    /** Forgets an unterminated line without delivering it. */
    void clear() {
        partialLength = 0;
        overflow = 0;
        shrink();
    }

    private void append(byte[] bytes, int offset, int length) {
        if (length == 0) {
            return;
        }
        if (overflow > 0 || partialLength + length > maxLineBytes) {
            // Once over the cap the line is lost anyway: count its bytes, keep none of them.
            overflow += partialLength + length;
            partialLength = 0;
            shrink();
            return;
        }
        if (partialLength + length > partial.length) {
            partial = Arrays.copyOf(partial, Math.min(maxLineBytes, Math.max(partial.length * 2, partialLength + length)));
        }
        System.arraycopy(bytes, offset, partial, partialLength, length);
        partialLength += length;
    }

    private void deliver(boolean last) {
        if (overflow > 0) {
            long bytes = overflow;
            overflow = 0;
            sink.overlongLine(bytes);
            return;
        }
        int length = partialLength;
        partialLength = 0;
        if (last) {
            sink.lastLine(partial, 0, length > 0 && partial[length - 1] == '\r' ? length - 1 : length);
        } else {
            deliver(partial, 0, length);
        }
        shrink();
    }

    /** Hands a line to the sink without a trailing {@code '\r'}. */
    private void deliver(byte[] bytes, int offset, int length) {
        if (length > 0 && bytes[offset + length - 1] == '\r') {
            length--;
        }
        sink.line(bytes, offset, length);
    }

    /** Gives back the buffer a long line made grow, so that one long line does not pin a MiB for ever. */
    private void shrink() {
        if (partial.length > 64 * 1024 && partialLength == 0) {
            partial = new byte[256];
        }
    }
}
