package dev.predmon.parse;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.util.Arrays;

/**
 * The last bytes a {@link LogFollower} read from a file, to notice that the file was truncated and written again
 * past the old read position between two looks (copytruncate rotation while the logger writes): the bytes before the
 * read position are then no longer those read there.
 */
final class ReadTail {

    /** How many of the last bytes read are kept: enough for a time stamp and more. */
    private static final int BYTES = 64;

    /** The bytes just before the read position, as read: {@code tail[0, length)}. */
    private final byte[] tail = new byte[BYTES];
    private int length;
    private final ByteBuffer check = ByteBuffer.allocate(BYTES);

    /** Keeps the last {@value #BYTES} bytes read, the {@code n} bytes of {@code bytes} being the newest. */
    void remember(byte[] bytes, int n) {
        if (n >= BYTES) {
            System.arraycopy(bytes, n - BYTES, tail, 0, BYTES);
            length = BYTES;
            return;
        }
        int keep = Math.min(length, BYTES - n);
        System.arraycopy(tail, length - keep, tail, 0, keep);
        System.arraycopy(bytes, 0, tail, keep, n);
        length = keep + n;
    }

    /** Reading starts over (from 0, or in another file). */
    void clear() {
        length = 0;
    }

    /** Whether the bytes of {@code channel} before {@code position} are no longer those read there. */
    boolean rewritten(FileChannel channel, long position) throws IOException {
        if (length == 0) {
            return false;
        }
        check.clear().limit(length);
        long at = position - length;
        while (check.hasRemaining()) {
            int n = channel.read(check, at + check.position());
            if (n <= 0) {
                return true; // shorter than it was: truncated
            }
        }
        return !Arrays.equals(check.array(), 0, length, tail, 0, length);
    }
}
