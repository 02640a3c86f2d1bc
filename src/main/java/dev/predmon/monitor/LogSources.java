package dev.predmon.monitor;

import dev.predmon.BadInputException;
import dev.predmon.ros2.Recordings;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.FileSystemException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.NotDirectoryException;
import java.nio.file.Path;
import java.nio.file.PathMatcher;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.PatternSyntaxException;
import java.util.stream.Stream;

/**
 * The logs a fleet watches, as named on the command line. Each name is one of:
 * <ul>
 *   <li>a file, watched whether or not it exists yet (as {@code tail -F} does);</li>
 *   <li>a directory: every {@code *.log} and {@code *.txt} file directly in it, now and as they appear (a robot that
 *       starts later adds its log there);</li>
 *   <li>a glob ({@code logs/robot-*.log}, quoted so that the shell leaves it alone, {@code **} for any depth): the
 *       files below its fixed leading directories that match the rest, now and as they appear.</li>
 * </ul>
 * {@link #find()} lists the files in the order the names were given, each name's files sorted, each file once, even
 * one with several names (a {@code latest.log} link to the newest log).
 */
public final class LogSources {

    private static final String GLOB_CHARS = "*?[{";

    /** What a name stands for, decided when it is given: a directory that goes away stays a directory. */
    private enum Kind { FILE, DIRECTORY, GLOB }

    private record Name(Path path, Kind kind) {
    }

    private final List<Name> names = new ArrayList<>();
    /** The name each file with several names was listed by at the latest {@link #find()}, by its identity. */
    private final Map<Object, Path> chosen = new HashMap<>();

    /** @param names files, directories or globs; at least one */
    /** No log at all: what a watch of a source that is no file ({@code --rosbridge}) follows beside it. */
    public static LogSources none() {
        return new LogSources(List.of(), true);
    }

    public LogSources(List<Path> names) {
        this(names, false);
    }

    private LogSources(List<Path> names, boolean none) {
        if (names.isEmpty() && !none) {
            throw new IllegalArgumentException("no log named");
        }
        for (Path n : names) {
            // A name that exists is that file or directory, even with glob characters in it (robot[1].log).
            // A rosbag2 folder is one log, not a directory of logs.
            this.names.add(new Name(n, Files.isDirectory(n) && !Recordings.isRecording(n) ? Kind.DIRECTORY
                    : !Files.exists(n) && isGlob(n) ? Kind.GLOB : Kind.FILE));
        }
    }

    /**
     * Whether events must say which log they belong to: more than one name, or a name that can stand for several
     * files. Decided from the names, not from what they match now, so that the output's shape does not change when
     * a second file appears.
     */
    public boolean several() {
        return names.size() > 1 || growing();
    }

    /**
     * Whether {@code file} was named as a file, rather than found under a directory or glob. A found file that holds
     * no record is another file beside the logs (notes, a core dump), not a log that failed.
     */
    public boolean named(Path file) {
        Path key = file.toAbsolutePath().normalize();
        return names.stream().anyMatch(n -> n.kind() == Kind.FILE && n.path().toAbsolutePath().normalize().equals(key));
    }

    /** Whether new files can appear under these names (a directory or a glob), so that they are looked for again. */
    public boolean growing() {
        return names.stream().anyMatch(n -> n.kind() != Kind.FILE);
    }

    /**
     * The files the names stand for now: files named as such whether or not they exist, plus what matches. A file with
     * several names (a {@code latest.log} link beside the file it points to, a hard link) is listed once, so that
     * one robot is not watched twice: by the name given as a file, else by a name that is not a symbolic link, else
     * by its first name.
     */
    public List<Path> find() throws IOException {
        Map<Path, Path> found = new LinkedHashMap<>();
        for (Name name : names) {
            for (Path p : expand(name)) {
                found.putIfAbsent(p.toAbsolutePath().normalize(), p);
            }
        }
        Map<Object, Path> byFile = new HashMap<>(); // a file's identity (device and inode) to the name it is kept by
        Map<Path, Object> ids = new HashMap<>();
        for (Path p : found.values()) {
            Object id = identity(p);
            if (id != null) {
                ids.put(p, id);
                byFile.merge(id, p, (kept, other) -> rank(other) < rank(kept) ? other : kept);
            }
        }
        // a name chosen at an earlier look stays chosen while it names the same file: a second name given to a
        // watched log later (a hard link) does not start a second watch of it
        byFile.replaceAll((id, p) -> {
            Path before = chosen.get(id);
            return before != null && id.equals(ids.get(before)) ? before : p;
        });
        chosen.clear();
        chosen.putAll(byFile);
        return found.values().stream().filter(p -> !ids.containsKey(p) || byFile.get(ids.get(p)).equals(p)).toList();
    }

    /** The identity of the file at {@code p}, links followed; null when there is none to be had. */
    private static Object identity(Path p) {
        try {
            return Files.readAttributes(p, BasicFileAttributes.class).fileKey();
        } catch (IOException | UnsupportedOperationException e) {
            return null; // not there (yet), or gone between the listing and now: it is its own
        }
    }

    /** Which of a file's names to follow it by: lower first. */
    private int rank(Path p) {
        return named(p) ? 0 : Files.isSymbolicLink(p) ? 2 : 1;
    }

    /**
     * For a single pass ({@code --no-follow}): every name must stand for a file now.
     *
     * @throws BadInputException naming the first name that stands for none
     */
    public void requireFiles() throws IOException, BadInputException {
        for (Name name : names) {
            if (expand(name).stream().noneMatch(Files::isRegularFile)) {
                throw new BadInputException(name.path() + switch (name.kind()) {
                    case GLOB -> ": no file matches";
                    case DIRECTORY -> ": is a directory with no log file (*.log, *.txt) in it";
                    case FILE -> ": no such file";
                });
            }
        }
    }

    /** What is still waited for, one phrase per name that stands for no file yet ({@code logs in DIR}, ...). */
    public List<String> missing() throws IOException {
        List<String> out = new ArrayList<>();
        for (Name name : names) {
            if (expand(name).stream().noneMatch(Files::exists)) {
                out.add(phrase(name));
            }
        }
        return out;
    }

    /** Every name as a phrase of what it stands for ({@code logs in DIR}, ...): what the live view waits on. */
    public List<String> described() {
        return names.stream().map(LogSources::phrase).toList();
    }

    private static String phrase(Name name) {
        return switch (name.kind()) {
            case GLOB -> "logs matching " + name.path();
            case DIRECTORY -> "logs in " + name.path();
            case FILE -> name.path().toString();
        };
    }

    /** The files one name stands for now (none for a directory that is gone). */
    private static List<Path> expand(Name name) throws IOException {
        return switch (name.kind()) {
            case GLOB -> glob(name.path());
            case DIRECTORY -> {
                try (Stream<Path> files = Files.list(name.path())) {
                    yield files.filter(p -> (Files.isRegularFile(p) && isLogName(p)) || Recordings.isRecording(p))
                            .sorted().toList();
                } catch (NoSuchFileException | NotDirectoryException gone) {
                    yield List.of(); // moved away or replaced: its logs are looked for again at the next rescan
                }
            }
            case FILE -> List.of(name.path());
        };
    }

    /** Whether a name is a glob rather than a file or directory. */
    public static boolean isGlob(Path name) {
        String s = name.toString();
        return s.chars().anyMatch(c -> GLOB_CHARS.indexOf(c) >= 0);
    }

    /**
     * The log files of a directory: the names the monitor's captures and yarplogger's files have (a directory's ROS 2
     * recordings are its logs too, see {@link Recordings#isRecording}).
     */
    static boolean isLogName(Path p) {
        String n = p.getFileName().toString();
        return n.endsWith(".log") || n.endsWith(".txt");
    }

    /**
     * A glob cut where its first pattern begins: walk {@code from} (its fixed leading directories, or here) to
     * {@code depth} and match each path from there against {@code rest}; {@code base} is what found paths are
     * resolved against (null for a relative glob with no fixed directory).
     */
    private record GlobRoot(Path base, Path from, Path rest, int depth) {

        static GlobRoot of(Path name) {
            int fixed = 0;
            while (fixed < name.getNameCount() - 1 && !isGlob(name.getName(fixed))) {
                fixed++;
            }
            Path root = name.getRoot();
            Path base = fixed == 0 ? root
                    : root == null ? name.subpath(0, fixed) : root.resolve(name.subpath(0, fixed));
            Path rest = name.subpath(fixed, name.getNameCount());
            int depth = rest.toString().contains("**") ? Integer.MAX_VALUE : rest.getNameCount();
            return new GlobRoot(base, base == null ? Path.of(".") : base, rest, depth);
        }
    }

    /** Files below the glob's fixed leading directories whose path from there matches the rest of the glob. */
    private static List<Path> glob(Path name) throws IOException {
        GlobRoot g = GlobRoot.of(name);
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
        List<Path> out = new ArrayList<>();
        try (Stream<Path> walk = Files.walk(g.from(), g.depth())) {
            walk.filter(Files::isRegularFile).forEach(p -> {
                Path relative = g.from().relativize(p);
                if (matcher.matches(relative)) {
                    out.add(g.base() == null ? relative : g.base().resolve(relative));
                }
            });
        } catch (UncheckedIOException e) {
            throw e.getCause(); // a directory that went away or cannot be read while walking
        }
        out.sort(null);
        return out;
    }

    /**
     * The directories in which a new file may be a new log: each named directory, and for a glob the last of its
     * fixed leading directories with every directory below it that the glob reaches (whose new entries may be new
     * directories holding logs). A directory that does not exist is listed as named. A file named as such is not
     * listed: its own directory is watched with it.
     */
    public List<Path> directories() throws IOException {
        List<Path> out = new ArrayList<>();
        for (Name name : names) {
            if (name.kind() == Kind.DIRECTORY) {
                out.add(name.path());
            } else if (name.kind() == Kind.GLOB) {
                GlobRoot g = GlobRoot.of(name.path());
                if (!Files.isDirectory(g.from())) {
                    out.add(g.from()); // cannot be watched yet: says that new logs must be looked for often
                    continue;
                }
                try (Stream<Path> walk = Files.walk(g.from(), g.depth() - 1)) {
                    walk.filter(Files::isDirectory).forEach(out::add);
                } catch (UncheckedIOException e) {
                    throw e.getCause();
                }
            }
        }
        return out;
    }
}
