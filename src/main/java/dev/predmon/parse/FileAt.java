package dev.predmon.parse;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.FileTime;
import java.util.List;

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

    /**
     * Opens this regular file for reading; null if it is not regular, or went or changed since it was looked at.
     * Only a regular file is opened: opening a FIFO would block until a writer comes.
     */
    FileChannel open() throws IOException {
        if (!regular) {
            return null;
        }
        FileChannel opened;
        try {
            opened = FileChannel.open(path, StandardOpenOption.READ);
        } catch (NoSuchFileException gone) {
            return null; // deleted between the look and the open: as if not there yet
        }
        FileAt now = look(path);
        if (now == null || !identity.equals(now.identity())) {
            opened.close(); // replaced between the look and the open: it may be the wrong file
            return null;
        }
        return opened;
    }

    /** Closes every channel, throwing the first failure with the others suppressed. */
    static void closeAll(List<FileChannel> channels) throws IOException {
        IOException first = null;
        for (FileChannel c : channels) {
            try {
                c.close();
            } catch (IOException e) {
                if (first == null) {
                    first = e;
                } else {
                    first.addSuppressed(e);
                }
            }
        }
        if (first != null) {
            throw first;
        }
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
