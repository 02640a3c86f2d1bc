package dev.predmon.monitor;

import dev.predmon.ros2.Recordings;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileSystemException;
import java.nio.file.FileSystems;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import java.nio.file.PathMatcher;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.PatternSyntaxException;

/**
 * One look at what a directory or a glob stands for now, costing a stat only for what is new: a directory's log
 * named at the last look ({@code known}, with its identity then) is taken from the directory's listing without a
 * stat, so that a look at a directory of 10,000 followed logs is one listing, not 10,000 stats. Every other entry is
 * statted once, which tells a log file, a recording and its identity at a time. A glob's walk stats each entry it
 * passes anyway, and its files' identities are taken from that.
 */
final class Listing {

    /**
     * A file found: its path as listed, its absolute normal form, and its identity (null when there is none to be
     * had); {@code remembered} when the identity is the one the last look had, not read now.
     */
    record Entry(Path path, Path key, Object id, boolean remembered) {

        /** This entry with its identity read now. */
        Entry refreshed(Listing listing) {
            return new Entry(path, key, listing.identity(path), false);
        }
    }

    private static final Comparator<Entry> BY_PATH = Comparator.comparing(Entry::path);

    /** The files listed by the last look, by key, with their identities then. */
    private final Map<Path, Object> known;
    /** Stats made so far, counted for tests: a look at known logs makes none. */
    private long stats;

    Listing(Map<Path, Object> known) {
        this.known = known;
    }

    long stats() {
        return stats;
    }

    /** One file named as such: whether or not it exists. */
    Entry file(Path p) {
        return new Entry(p, p.toAbsolutePath().normalize(), identity(p), false);
    }

    /**
     * The log files directly in {@code dir}, in the order listed: its {@code *.log} and {@code *.txt} files and its ROS 2
     * recordings; none for a directory that is gone.
     */
    List<Entry> directory(Path dir) throws IOException {
        List<Entry> out = new ArrayList<>();
        Path dirKey = dir.toAbsolutePath().normalize();
        try (DirectoryStream<Path> entries = Files.newDirectoryStream(dir)) {
            for (Path p : entries) {
                Path name = p.getFileName();
                Path key = dirKey.resolve(name);
                boolean logName = LogSources.isLogName(name.toString());
                Object id = logName ? known.get(key) : null;
                if (id != null) {
                    out.add(new Entry(p, key, id, true)); // a log file at the last look: no stat
                    continue;
                }
                BasicFileAttributes a = attributes(p);
                if (a != null && ((a.isRegularFile() && logName) || Recordings.isRecording(p))) {
                    out.add(new Entry(p, key, a.fileKey(), false));
                }
            }
        } catch (NoSuchFileException | NotDirectoryException gone) {
            return List.of(); // moved away or replaced: its logs are looked for again at the next rescan
        }
        return out; // unsorted: sorted only when the look found something other than the last one
    }

    /** Sorts a name's files by path, as they are listed. */
    static void sort(List<Entry> entries) {
        entries.sort(BY_PATH);
    }

    /** The files below the glob's fixed leading directories whose path from there matches the rest of the glob. */
    List<Entry> glob(Path name, LogSources.GlobRoot g) throws IOException {
        if (!Files.isDirectory(g.from())) {
            return List.of();
        }
        PathMatcher matcher;
        try {
            matcher = FileSystems.getDefault().getPathMatcher("glob:" + g.rest());
        } catch (PatternSyntaxException e) {
            // the JDK's description of the syntax error is garbled ("Missing '])"): the pattern itself says more
            throw new FileSystemException(name.toString(), null, "no such file, and not a valid glob");
        }
        List<Entry> out = new ArrayList<>();
        Files.walkFileTree(g.from(), Set.of(), g.depth(), new SimpleFileVisitor<>() {
            @Override
            public FileVisitResult visitFile(Path p, BasicFileAttributes listed) {
                stats++;
                // a link is not walked into, but a link to a file is that file
                BasicFileAttributes a = listed.isSymbolicLink() ? attributes(p) : listed;
                if (a != null && a.isRegularFile()) {
                    Path relative = g.from().relativize(p);
                    if (matcher.matches(relative)) {
                        Path found = g.base() == null ? relative : g.base().resolve(relative);
                        out.add(new Entry(found, found.toAbsolutePath().normalize(), a.fileKey(), false));
                    }
                }
                return FileVisitResult.CONTINUE;
            }
        });
        out.sort(BY_PATH);
        return out;
    }

    /** The identity of the file at {@code p}, links followed; null when there is none to be had. */
    Object identity(Path p) {
        BasicFileAttributes a = attributes(p);
        return a == null ? null : a.fileKey();
    }

    private BasicFileAttributes attributes(Path p) {
        stats++;
        try {
            return Files.readAttributes(p, BasicFileAttributes.class);
        } catch (IOException | UnsupportedOperationException e) {
            return null; // not there (yet), or gone between the listing and now: it is its own
        }
    }
}
