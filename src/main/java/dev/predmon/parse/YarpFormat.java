package dev.predmon.parse;

import java.nio.file.Path;
import java.time.Duration;

/** {@link LogFormat#yarp()}: followed by {@link FollowedLog}, read once by {@link LogReader}. */
final class YarpFormat implements LogFormat {

    static final YarpFormat INSTANCE = new YarpFormat();

    private YarpFormat() {
    }

    @Override
    public RecordSource follow(Path log, RecordSink sink, Duration quiet, Duration release) {
        return new FollowedLog(log, sink, quiet, release);
    }

    @Override
    public RecordSource read(Path file, RecordSink sink) {
        return new ReadOnce(file, sink);
    }

    @Override
    public String toString() {
        return "YARP monitor log";
    }

    /** A file read whole, at once, by {@link LogReader} (on a second thread for a large file). */
    private static final class ReadOnce implements RecordSource {

        private final Path file;
        private final RecordSink sink;
        private long lines;
        private boolean read;

        ReadOnce(Path file, RecordSink sink) {
            this.file = file;
            this.sink = sink;
        }

        @Override
        public boolean poll() throws java.io.IOException {
            if (read) {
                return false;
            }
            drain();
            return true;
        }

        @Override
        public void drain() throws java.io.IOException {
            if (!read) {
                read = true;
                LogReader.read(file, sink::record, sink::problem, n -> lines = n);
            }
        }

        @Override
        public long lines() {
            return lines;
        }

        @Override
        public void close() {
            // nothing is held between calls
        }
    }
}
