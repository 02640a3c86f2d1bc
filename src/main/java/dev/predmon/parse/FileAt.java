package dev.predmon.parse;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.FileTime;

/**
 * What is at a followed path now, from one {@code stat}: a regular file (its identity, size and time of last change)
 * or something a follower must not open. Opening a FIFO for reading blocks until a writer comes, and a directory or a
 * socket cannot be read as a log, so {@link LogFollower} looks before it opens, and opens only a regular file.
 *
 * @param identity the file's identity ({@link BasicFileAttributes#fileKey()}: device and inode on Unix, or the
 *                 creation time where the file system has no keys)
 * @param regular  whether it is a regular file (links followed)
 * @param size     its size in bytes
 * @param modified when it last changed
 * @param path     the path looked at
 */
record FileAt(Object identity, boolean regular, long size, FileTime modified, Path path) {

    /** The file at {@code path}, or null when there is none. */
    static FileAt look(Path path) throws IOException {
        BasicFileAttributes a;
        try {
            a = Files.readAttributes(path, BasicFileAttributes.class);
        } catch (NoSuchFileException | NotDirectoryException absent) {
            return null;
        }
        Object key = a.fileKey();
        return new FileAt(key != null ? key : a.creationTime(), a.isRegularFile(), a.size(), a.lastModifiedTime(),
                path);
    }

    /** What a path that is not a regular file holds, in a few words: {@code a FIFO}, {@code a directory}. */
    String kind() {
        try {
            if (Files.isDirectory(path)) {
                return "a directory";
            }
            int type = ((Integer) Files.getAttribute(path, "unix:mode")) & 0170000;
            return switch (type) {
                case 0010000 -> "a FIFO";
                case 0140000 -> "a socket";
                case 0020000 -> "a character device";
                case 0060000 -> "a block device";
                default -> "not a regular file";
            };
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException | ClassCastException e) {
            return "not a regular file";
        }
    }
}
