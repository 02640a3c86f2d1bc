package dev.predmon.rosbag;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

/**
 * Reads ROS 2 recordings: a rosbag2 folder (its {@code metadata.yaml} is optional; its data files are read in
 * order), an MCAP file, or a rosbag2 sqlite3 ({@code .db3}) file. Files are recognised by their content (the MCAP
 * magic, the SQLite header), whatever their names.
 *
 * <p>Every message is decoded from CDR with the message definitions the recording carries (or predmon's bundled
 * ones for the common types, where it carries none) and handed to the sink in reading order. What cannot be read
 * is one problem line naming the file, the record (its byte offset or its row) and what was expected; the messages
 * before it have been delivered. A structural fault (a file cut short, a bad CRC, an impossible length) ends the
 * reading of the recording there; a topic that cannot be decoded is reported once and skipped, and the others go
 * on. To follow a recording while it is being written, see {@link BagFollower}.
 */
public final class Bags {

    private Bags() {
    }

    /**
     * Whether {@code path} is a ROS 2 recording: a folder with a {@code metadata.yaml} or a data file, or a file
     * that begins as an MCAP or SQLite file does (or, still empty, is named {@code .mcap} or {@code .db3}).
     */
    public static boolean looksLikeBag(Path path) {
        if (Files.isDirectory(path)) {
            if (Files.isRegularFile(path.resolve(BagFolder.METADATA))) {
                return true;
            }
            try {
                return !BagFolder.contents(path).files().isEmpty();
            } catch (IOException e) {
                return false;
            }
        }
        return BagFolder.isDataFile(path);
    }

    /**
     * Reads the recording at {@code fileOrFolder} to its end, delivering every message and problem to {@code sink}.
     *
     * @throws IOException if the recording cannot be opened or read (a missing file, no permission, a disk error)
     */
    public static void read(Path fileOrFolder, BagSink sink) throws IOException {
        if (!Files.exists(fileOrFolder)) {
            throw new NoSuchFileException(fileOrFolder.toString(), null, "no such file or folder");
        }
        if (Files.isDirectory(fileOrFolder)) {
            BagFolder.Contents c = BagFolder.contents(fileOrFolder);
            c.problems().forEach(sink::problem);
            if (c.files().isEmpty()) {
                sink.problem(fileOrFolder + ": expected a rosbag2 folder with .mcap or .db3 files, found none");
            }
            for (Path f : c.files()) {
                if (!readFile(f, sink)) {
                    return; // a recording cut short: what follows would not continue it
                }
            }
        } else {
            readFile(fileOrFolder, sink);
        }
    }

    /** Reads one data file; false if a structural problem stopped it. */
    static boolean readFile(Path file, BagSink sink) throws IOException {
        BagFolder.Storage storage = BagFolder.storage(file);
        if (storage == BagFolder.Storage.SQLITE3) {
            Db3Reader.read(file, sink);
            return true;
        }
        if (storage == null) {
            sink.problem(file + ": byte 0: expected an MCAP file (magic 89 4D 43 41 50 30 0D 0A) or a SQLite "
                    + "database (\"SQLite format 3\"), found neither");
            return false;
        }
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.READ)) {
            McapScanner scan = new McapScanner(ch, new Topics(file, sink));
            return scan.advance(ch.size(), true) == McapScanner.State.DONE;
        }
    }
}
