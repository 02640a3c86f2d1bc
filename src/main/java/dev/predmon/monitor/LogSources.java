package dev.predmon.monitor;

import dev.predmon.BadInputException;
import dev.predmon.ros2.Recordings;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
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
    /** The files the latest look listed, by absolute normal path, with their identities then. */
    private final Map<Path, Object> listed = new HashMap<>();
    /** How the looks list directories: without a stat for a file {@link #listed} as a log already. */
    private final Listing listing = new Listing(listed);

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
     * by its first name. A directory's log listed by the last look is not looked at again ({@link Listing}).
     */
    public synchronized List<Path> find() throws IOException {
        return look(new ArrayList<>(), true).stream().map(Listing.Entry::path).toList();
    }

    /**
     * As {@link #find()}, only the files the last look did not list (all of them at the first look): what a fleet
     * already following the others has to add. A file the fleet let go of is listed again once {@link #forget}ten.
     */
    public synchronized List<Path> findNew() throws IOException {
        List<Path> fresh = new ArrayList<>();
        look(fresh, false);
        return fresh;
    }

    /** {@code file} is no longer followed: when it is there again, {@link #findNew()} lists it. */
    public synchronized void forget(Path file) {
        listed.remove(file.toAbsolutePath().normalize());
    }

    /** Stats made by the looks so far: a look at logs listed by the last one makes none for them. */
    synchronized long stats() {
        return listing.stats();
    }

    /**
     * The files the names stand for now, in order if {@code ordered}; those the last look did not list also go to
     * {@code fresh}.
     */
    private List<Listing.Entry> look(List<Path> fresh, boolean ordered) throws IOException {
        List<List<Listing.Entry>> expanded = new ArrayList<>();
        for (Name name : names) {
            expanded.add(expand(name, listing));
        }
        if (expanded.size() == 1 && expanded.get(0).size() == listed.size()
                && expanded.get(0).stream().allMatch(Listing.Entry::remembered)) {
            // one directory holding just the files of the last look: it chose among them then, and none is fresh
            return ordered ? sorted(expanded.get(0)) : expanded.get(0);
        }
        Map<Path, Listing.Entry> found = new LinkedHashMap<>();
        for (List<Listing.Entry> files : expanded) {
            for (Listing.Entry e : sorted(files)) {
                found.putIfAbsent(e.key(), e);
            }
        }
        List<Listing.Entry> all = new ArrayList<>(found.values());
        Map<Object, Path> byFile = byFile(all);
        // a name chosen at an earlier look stays chosen while it names the same file: a second name given to a
        // watched log later (a hard link) does not start a second watch of it
        Map<Path, Object> ids = new HashMap<>();
        all.forEach(e -> ids.put(e.path(), e.id()));
        byFile.replaceAll((id, p) -> {
            Path before = chosen.get(id);
            return before != null && id.equals(ids.get(before)) ? before : p;
        });
        chosen.clear();
        chosen.putAll(byFile);
        List<Listing.Entry> out = all.stream().filter(e -> e.id() == null || byFile.get(e.id()).equals(e.path()))
                .toList();
        out.stream().filter(e -> !listed.containsKey(e.key())).forEach(e -> fresh.add(e.path()));
        listed.clear();
        out.stream().filter(e -> e.id() != null).forEach(e -> listed.put(e.key(), e.id()));
        return out;
    }

    private static List<Listing.Entry> sorted(List<Listing.Entry> files) {
        List<Listing.Entry> out = new ArrayList<>(files);
        Listing.sort(out);
        return out;
    }

    /**
     * The name each file is kept by, by its identity. An identity the last look had is taken as it is unless another
     * file has it now: then both are read again, as one of them may have been renamed since (a rotation).
     */
    private Map<Object, Path> byFile(List<Listing.Entry> all) {
        while (true) {
            Map<Object, Path> byFile = new HashMap<>();
            Map<Object, Integer> first = new HashMap<>();
            boolean refreshed = false;
            for (int i = 0; i < all.size(); i++) {
                Listing.Entry e = all.get(i);
                if (e.id() == null) {
                    continue;
                }
                Integer other = first.putIfAbsent(e.id(), i);
                if (other != null) {
                    for (int k : new int[] {other, i}) {
                        if (all.get(k).remembered()) {
                            all.set(k, all.get(k).refreshed(listing));
                            refreshed = true;
                        }
                    }
                }
                byFile.merge(e.id(), e.path(), (kept, p) -> rank(p) < rank(kept) ? p : kept);
            }
            if (!refreshed) {
                return byFile;
            }
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

    /** The files one name stands for now (none for a directory that is gone), each looked at. */
    private static List<Path> expand(Name name) throws IOException {
        return expand(name, new Listing(Map.of())).stream().map(Listing.Entry::path).toList();
    }

    /** The files one name stands for now (none for a directory that is gone), looked at through {@code listing}. */
    private static List<Listing.Entry> expand(Name name, Listing listing) throws IOException {
        return switch (name.kind()) {
            case GLOB -> listing.glob(name.path(), GlobRoot.of(name.path()));
            case DIRECTORY -> listing.directory(name.path());
            case FILE -> List.of(listing.file(name.path()));
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
        return isLogName(p.getFileName().toString());
    }

    static boolean isLogName(String name) {
        return name.endsWith(".log") || name.endsWith(".txt");
    }

    /**
     * A glob cut where its first pattern begins: walk {@code from} (its fixed leading directories, or here) to
     * {@code depth} and match each path from there against {@code rest}; {@code base} is what found paths are
     * resolved against (null for a relative glob with no fixed directory).
     */
    record GlobRoot(Path base, Path from, Path rest, int depth) {

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
