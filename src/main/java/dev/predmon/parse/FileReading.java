package dev.predmon.parse;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;

/**
 * One file a {@link LogFollower} reads: its channel, read position, unterminated last line and sink. The file at the
 * path has one, and so has each file renamed away that is still read: each keeps its own partial line, so that a line
 * (and the record it belongs to) cut where a writer paused is completed by that writer's next write, whatever is
 * read from the other file meanwhile.
 */
final class FileReading {

    private static final int BUFFER_BYTES = 64 * 1024;
    /** One read buffer per thread: a fleet of thousands of logs polled by one thread holds one. */
    private static final ThreadLocal<Buffer> BUFFER = ThreadLocal.withInitial(Buffer::new);

    /** A thread's read buffer: its bytes and the one buffer wrapping them (not one wrapper per read). */
    private static final class Buffer {
        final byte[] bytes = new byte[BUFFER_BYTES];
        final ByteBuffer wrapped = ByteBuffer.wrap(bytes);
    }

    /** The open file; null while released to spare a descriptor, and once closed. */
    FileChannel channel;
    /** The file's identity ({@link FileAt#identity()}). */
    final Object identity;
    long position;
    final LineSplitter splitter;
    final LineSink sink;
    /** The last bytes read, to notice a rewrite. */
    final ReadTail tail = new ReadTail();
    /** When the file last grew (or was opened), on the follower's clock. */
    long lastGrowth;

    FileReading(FileChannel channel, Object identity, LineSink sink, int maxLineBytes, long now) {
        this.channel = channel;
        this.identity = identity;
        this.sink = sink;
        this.splitter = new LineSplitter(maxLineBytes, sink);
        this.lastGrowth = now;
    }

    /** Reading starts over from the file's beginning. */
    void rewind() {
        position = 0;
        tail.clear();
    }

    /** Reads and delivers the complete lines appended since the last read; whether anything was read. */
    boolean read(long now) throws IOException {
        Buffer b = BUFFER.get();
        ByteBuffer buffer = b.wrapped;
        byte[] bytes = b.bytes;
        boolean progress = false;
        while (true) {
            buffer.clear();
            int n = channel.read(buffer, position);
            if (n <= 0) {
                if (progress) {
                    lastGrowth = now;
                }
                return progress;
            }
            position += n;
            progress = true;
            tail.remember(bytes, n);
            splitter.feed(bytes, 0, n);
        }
    }

    /**
     * Checks that the file was neither truncated nor rewritten, and reads what was appended, in one read of the file
     * in most polls: the kept bytes before the read position are read again with what follows them. A read shorter
     * than the buffer is taken as the end of the file as it is now (a later write is announced, or polled for, anew).
     *
     * @return {@code -1} when the file was truncated or rewritten (nothing consumed), {@code 1} when something was
     *         read, {@code 0} when nothing was appended
     */
    int readChecked(long now) throws IOException {
        Buffer b = BUFFER.get();
        ByteBuffer buffer = b.wrapped;
        byte[] bytes = b.bytes;
        buffer.clear();
        int kept = tail.length();
        int n = channel.read(buffer, position - kept);
        if (kept > 0 && (n < kept || !tail.matches(bytes))) {
            return -1; // shorter than it was, or other bytes before the read position
        }
        boolean progress = false;
        while (true) {
            int fresh = Math.max(0, n) - kept;
            if (fresh > 0) {
                position += fresh;
                progress = true;
                tail.remember(bytes, kept, fresh);
                splitter.feed(bytes, kept, fresh);
            }
            if (n < bytes.length) {
                break; // a regular file's read is short only at its end
            }
            buffer.clear();
            n = channel.read(buffer, position);
            kept = 0;
        }
        if (progress) {
            lastGrowth = now;
        }
        return progress ? 1 : 0;
    }

    /**
     * {@link #readChecked}, and when the file was truncated or rewritten: its partial line out,
     * {@code restarted("truncated")}, and the file read from 0. Whether anything was consumed.
     */
    boolean readOn(long now) throws IOException {
        int read = readChecked(now);
        if (read >= 0) {
            return read > 0;
        }
        splitter.finish();
        sink.restarted("truncated");
        rewind();
        read(now);
        return true;
    }

    /** The file is done with: its unterminated last line goes out, then {@link LineSink#ended()}. */
    void end() {
        splitter.finish();
        sink.ended();
    }

    /** Closes the file, if open. */
    void close() throws IOException {
        if (channel != null) {
            FileChannel c = channel;
            channel = null;
            c.close();
        }
    }
}
