package dev.predmon.rosbag;

import java.io.Closeable;
import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;

/**
 * Follows an MCAP recording while it is being written: {@code ros2 bag record} appends whole chunks to its current
 * file and, at its size limit, closes that file and starts the next ({@code name_0.mcap}, {@code name_1.mcap},
 * ...). Each {@link #poll} delivers every message of the records appended since the last poll, and only whole
 * records: a chunk half written is read at a later poll, once all its bytes are there.
 *
 * <p>Given a folder, the follower takes its MCAP files in split order and moves to the next once the current one
 * has its end records. The recorder closes a file before it starts the next, so a file that has a successor but no
 * end records, and has stopped growing, was cut (the recorder was killed): that is one problem line, and the
 * follower goes on with the next file. A sqlite3 file is read whole once it is there, since its rows are not
 * appended in a readable order.
 */
public final class BagFollower implements Closeable {

    private final Path path;
    private final BagSink sink;
    private final boolean folder;
    private Path current;
    private FileChannel channel;
    private McapScanner scanner;
    private Topics topics;
    private int done;
    private boolean ended;

    /** Follows {@code fileOrFolder}, an MCAP file or a rosbag2 folder (which may not have files yet). */
    public BagFollower(Path fileOrFolder, BagSink sink) {
        this.path = fileOrFolder;
        this.sink = sink;
        this.folder = Files.isDirectory(fileOrFolder);
    }

    /**
     * Reads what was appended since the last poll; never waits.
     *
     * @return the number of messages delivered by this poll
     */
    public long poll() throws IOException {
        long delivered = 0;
        while (!ended) {
            List<Path> files = folder ? BagFolder.contents(path).files() : Files.exists(path) ? List.of(path) : List.of();
            if (files.size() <= done) {
                return delivered; // the next file is not there yet
            }
            boolean hasNext = files.size() > done + 1;
            Path file = files.get(done);
            if (BagFolder.storage(file) == BagFolder.Storage.SQLITE3) {
                Db3Reader.read(file, sink);
                next(folder);
                continue;
            }
            if (!file.equals(current)) {
                open(file);
            }
            long before = topics.delivered();
            // Listed before its size is read: if a next file was there, this one was closed before, and its size
            // is final.
            McapScanner.State s = scanner.advance(channel.size(), hasNext);
            delivered += topics.delivered() - before;
            if (s == McapScanner.State.MORE) {
                return delivered;
            }
            next(folder);
        }
        return delivered;
    }

    private void open(Path file) throws IOException {
        closeCurrent();
        current = file;
        channel = FileChannel.open(file, StandardOpenOption.READ);
        topics = new Topics(file, sink);
        scanner = new McapScanner(channel, topics);
    }

    private void next(boolean more) throws IOException {
        closeCurrent();
        done++;
        ended = !more;
    }

    /** Whether the recording has ended: a single file read to its end records (a folder is never ended). */
    public boolean ended() {
        return ended;
    }

    private void closeCurrent() throws IOException {
        if (channel != null) {
            channel.close();
        }
        channel = null;
        scanner = null;
        current = null;
    }

    @Override
    public void close() throws IOException {
        closeCurrent();
        ended = true;
    }
}
