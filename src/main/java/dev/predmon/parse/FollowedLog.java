package dev.predmon.parse;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Objects;
import java.util.Optional;

/**
 * A followed YARP log as a {@link RecordSource}: {@link LogFollower} (tail -F) feeds the lines of each file it reads
 * to a {@link LogParser} of that file's own, whose records and problems go to the sink.
 *
 * <p>Rotation: a truncation restarts the file's parser and is told at once. A file that replaces another gets a
 * parser of its own, and the sink hears {@code restarted("replaced")} just before the first record read from it, not
 * at the turn: until then, what the old writer adds to the renamed file, which the follower reads on while it grows,
 * continues the run it was in, exactly as if it had been written to one file (a record cut where the writer paused
 * is completed there). Records are delivered in the order they are read, each file's in its own order; a poll reads
 * the renamed file before the file at the path. Once the new file has given a record, a record the renamed file still
 * gives goes into the run under way, and the user is told once that two writers are read as one.
 */
final class FollowedLog implements RecordSource {

    private final RecordSink sink;
    private final LogFollower follower;
    /** The parser of the file at the path (the file last taken up). */
    private FileParser current;
    private long lines;
    /** What the user should be told once, or null; whether two writers were told of already. */
    private String notice;
    private boolean toldTwoWriters;

    FollowedLog(Path log, RecordSink sink, Duration quiet, Duration release) {
        this.sink = Objects.requireNonNull(sink, "sink");
        this.follower = LogFollower.perFile(log, FileParser::new, quiet, release);
    }

    /** The lines of one file the follower reads, parsed on their own. */
    private final class FileParser implements LineSink {

        private final LogParser parser = new LogParser(this::record, sink::problem);
        private final LineSink parsed = parser.lineSink();
        /** Whether this file replaced another and has given no record yet: its first one begins a new run. */
        private boolean replacement;
        private boolean gaveRecord;

        FileParser() {
            current = this;
        }

        private void record(LogRecord record) {
            if (replacement) {
                replacement = false;
                if (this == current || !current.gaveRecord) { // else a later file began the run under way
                    sink.restarted("replaced");
                }
            }
            if (this != current && current.gaveRecord && !toldTwoWriters) {
                toldTwoWriters = true;
                notice = "the file renamed away at a rotation is still written after the file now at the path gave "
                        + "records: two writers, whose records are taken in the order they are read, as one run";
            }
            gaveRecord = true;
            sink.record(record);
        }

        @Override
        public void line(String line) {
            lines++;
            parsed.line(line);
        }

        @Override
        public void line(byte[] bytes, int offset, int length) {
            lines++;
            parsed.line(bytes, offset, length);
        }

        @Override
        public void overlongLine(long bytes) {
            lines++;
            parsed.overlongLine(bytes);
        }

        @Override
        public void lastLine(byte[] bytes, int offset, int length) {
            parsed.lastLine(bytes, offset, length);
        }

        @Override
        public void restarted(String reason) {
            lines = 0;
            if (reason.equals("replaced")) {
                replacement = true; // a new parser: nothing of the file before is in it
                return;
            }
            parsed.restarted(reason); // reports a record the truncation cut, then starts the parser over
            replacement = false;
            gaveRecord = false;
            sink.restarted(reason);
        }

        @Override
        public void ended() {
            parsed.ended(); // a record the file ends in the middle of is reported as cut
        }
    }

    @Override
    public boolean poll() throws IOException {
        return follower.poll();
    }

    @Override
    public boolean pollWritten() throws IOException {
        return follower.pollWritten();
    }

    @Override
    public void drain() throws IOException {
        follower.drainToEnd(); // ends every file's parser
    }

    @Override
    public long lines() {
        return lines;
    }

    /** The YARP lines of the file last taken up, before its first record ({@link LogParser#yarpLines()}). */
    @Override
    public long yarpLines() {
        return current == null ? 0 : current.parser.yarpLines();
    }

    @Override
    public boolean replacing() {
        return follower.replacing();
    }

    @Override
    public boolean readingRenamed() {
        return follower.readingRenamed();
    }

    @Override
    public Optional<String> obstacle() {
        return follower.obstacle();
    }

    @Override
    public Optional<String> takeNotice() {
        Optional<String> out = Optional.ofNullable(notice);
        notice = null;
        return out;
    }

    @Override
    public int openFiles() {
        return follower.openFiles();
    }

    @Override
    public boolean release() throws IOException {
        return follower.release();
    }

    @Override
    public void close() throws IOException {
        follower.close();
    }
}
