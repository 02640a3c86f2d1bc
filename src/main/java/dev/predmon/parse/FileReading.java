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
    private static final ThreadLocal<byte[]> BUFFER = ThreadLocal.withInitial(() -> new byte[BUFFER_BYTES]);

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

    /** Whether the file holds less than was read, or other bytes before the read position (truncated, rewritten). */
    boolean truncated() throws IOException {
        return channel.size() < position || tail.rewritten(channel, position);
    }

    /** Reading starts over from the file's beginning. */
    void rewind() {
        position = 0;
        tail.clear();
    }

    /** Reads and delivers the complete lines appended since the last read; whether anything was read. */
    boolean read(long now) throws IOException {
        byte[] bytes = BUFFER.get();
        ByteBuffer buffer = ByteBuffer.wrap(bytes);
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
