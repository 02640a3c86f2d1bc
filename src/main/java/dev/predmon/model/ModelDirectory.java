package dev.predmon.model;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.BadInputException;
import dev.predmon.abstraction.file.LocatedJson;
import dev.predmon.files.OutputFiles;
import dev.predmon.forecast.ForecastFile;

import java.io.IOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ThreadLocalRandom;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * A model directory on disk and its siblings, and what predmon may do to them. A safety tool never destroys a
 * user's files, so learn replaces or deletes only what it wrote itself:
 * <ul>
 *   <li>the model directory, when it is empty or holds exactly a predmon {@code index.json}, the DOT files it
 *       lists and {@code abstraction.json} (anything else in it, a thesis or a Gazebo model, and it is refused);</li>
 *   <li>its staging directory {@code <dir>.new-<pid>-<n>} and the previous models set aside while the new ones
 *       move in, {@code <dir>.old-<pid>-<n>}: only once their process is gone and only when they hold nothing
 *       but files named as learn names them. A user's {@code models.old} backup never matches.</li>
 * </ul>
 */
final class ModelDirectory {

    /** Name of the index file inside a model directory. */
    static final String INDEX = "index.json";
    /**
     * The abstraction the models were learned with, byte for byte its canonical JSON (its SHA-256 without the safety
     * property's action = fingerprint).
     */
    static final String ABSTRACTION = "abstraction.json";

    /** Kinds of sibling directories learn makes. */
    enum Sibling {
        /** Where the new models are written before they move in. */
        STAGING("new"),
        /** Where the previous models wait, between the two renames, until the new ones are in place. */
        SET_ASIDE("old");

        final String infix;

        Sibling(String infix) {
            this.infix = infix;
        }
    }

    private final Path dir;
    private final Pattern siblingName;

    private ModelDirectory(Path dir) {
        this.dir = dir;
        this.siblingName = Pattern.compile(Pattern.quote(dir.getFileName().toString()) + "\\.(new|old)-(\\d{1,19})-(\\d{1,20})");
    }

    /**
     * The model directory {@code path} names: absolute and normalised; when it exists, its real path, so that a
     * symbolic link to a model directory is updated where it points.
     */
    static ModelDirectory of(Path path) throws BadInputException {
        Path abs = path.toAbsolutePath().normalize();
        if (abs.getParent() == null || abs.getFileName() == null) {
            throw new BadInputException(path + ": cannot be a model directory (it is a file system root)");
        }
        if (Files.exists(abs)) {
            try {
                return new ModelDirectory(abs.toRealPath());
            } catch (IOException e) {
                throw BadInputException.cannotRead(path, e);
            }
        }
        if (Files.exists(abs, LinkOption.NOFOLLOW_LINKS)) {
            throw new BadInputException(path + ": a symbolic link to nothing; point it at a directory or remove it");
        }
        return new ModelDirectory(abs);
    }

    /** For reading: the directory {@code path} names, whatever is there (a dangling link is read as missing). */
    static ModelDirectory lenient(Path path) {
        Path abs = path.toAbsolutePath().normalize();
        try {
            return new ModelDirectory(Files.exists(abs) ? abs.toRealPath() : abs);
        } catch (IOException e) {
            return new ModelDirectory(abs);
        }
    }

    Path path() {
        return dir;
    }

    Path parent() {
        return dir.getParent();
    }

    /**
     * Checks, before anything is changed, that learn may replace this directory and will be able to finish: it is
     * new, empty or predmon's own; the directory that will hold it and its siblings is writable; and an existing
     * one is writable too, since its files are removed once the new models are in place.
     */
    void requireReplaceable() throws BadInputException {
        if (Files.exists(dir)) {
            if (!Files.isDirectory(dir)) {
                throw new BadInputException(dir + ": not a directory; learn writes a model directory here only if "
                        + "it is new, empty or one learn wrote: choose another --models");
            }
            String foreign;
            try {
                foreign = foreignContent(dir);
            } catch (IOException e) {
                throw new BadInputException(dir + ": cannot list: " + BadInputException.reason(e), e);
            }
            if (foreign != null) {
                throw new BadInputException(dir + ": not a model directory learn wrote (" + foreign + "); learn "
                        + "replaces only its own: move those files away or choose another --models");
            }
            if (!Files.isWritable(dir)) {
                throw new BadInputException(dir + ": not writable, so its models could not be replaced; "
                        + "nothing was changed");
            }
        }
        OutputFiles.requireWritableDirectory(parent(), dir);
    }

    /**
     * What in {@code dir} predmon did not write, in a few words, or null when everything in it is its own (an
     * empty directory has nothing to lose).
     */
    static String foreignContent(Path dir) throws IOException {
        List<Path> entries;
        try (Stream<Path> s = Files.list(dir)) {
            entries = s.sorted().toList();
        }
        if (entries.isEmpty()) {
            return null;
        }
        Set<String> own = ownFiles(dir);
        List<String> foreign = new ArrayList<>();
        for (Path p : entries) {
            String name = p.getFileName().toString();
            boolean plainFile = Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS);
            if (own == null || !own.contains(name) || !plainFile) {
                foreign.add(Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS) ? name + "/" : name);
            }
        }
        if (foreign.isEmpty()) {
            return null;
        }
        String listed = String.join(", ", foreign.subList(0, Math.min(3, foreign.size())))
                + (foreign.size() > 3 ? " and " + (foreign.size() - 3) + " more" : "");
        return own == null ? "no predmon " + INDEX + "; it holds " + listed : "it also holds " + listed;
    }

    /** The files a predmon index says are its own, or null when {@code dir} has no readable predmon index. */
    private static Set<String> ownFiles(Path dir) {
        Path index = dir.resolve(INDEX);
        if (!Files.isRegularFile(index, LinkOption.NOFOLLOW_LINKS)) {
            return null;
        }
        JsonNode root;
        try {
            root = LocatedJson.readValue(index.toFile()).root();
        } catch (IOException e) {
            return null;
        }
        if (root == null || root.path("format").asInt(-1) != ModelIndex.FORMAT || !root.path("scenarios").isArray()
                || !root.path("abstraction").isObject()) {
            return null;
        }
        Set<String> own = new HashSet<>(Set.of(INDEX, ABSTRACTION));
        if (ForecastFile.NAME.equals(root.path("forecast").asText(""))) {
            own.add(ForecastFile.NAME);
        }
        for (JsonNode scenario : root.get("scenarios")) {
            for (JsonNode model : scenario.path("models")) {
                String file = model.path("file").asText("");
                // Only a DOT file can be a model learn wrote: an index may name anything (notes.txt, a thesis),
                // and whatever counted as its own here would be deleted with the previous models.
                if (ModelReader.DOT_NAME.matcher(file).matches()) {
                    own.add(file);
                }
            }
        }
        return own;
    }

    /** A new sibling directory of the given kind, named with this process's pid; with the user's umask. */
    Path createSibling(Sibling kind) throws IOException {
        while (true) {
            Path p = sibling(kind);
            try {
                return Files.createDirectory(p);
            } catch (FileAlreadyExistsException e) {
                // another name
            }
        }
    }

    /** A fresh name for a sibling of this process (not created). */
    Path sibling(Sibling kind) {
        long n = ThreadLocalRandom.current().nextLong(Long.MAX_VALUE);
        return parent().resolve(dir.getFileName() + "." + kind.infix + "-" + ProcessHandle.current().pid() + "-" + n);
    }

    /**
     * The previous models set aside by a learn that was killed between its two renames, if this directory has no
     * models of its own: then they are the models to read.
     */
    Optional<Path> setAside() throws IOException {
        List<Path> found = new ArrayList<>();
        for (Path p : siblings(Sibling.SET_ASIDE, false)) {
            if (Files.isRegularFile(p.resolve(INDEX))) {
                found.add(p);
            }
        }
        found.sort(Comparator.comparing((Path p) -> {
            try {
                return Files.getLastModifiedTime(p);
            } catch (IOException e) {
                return FileTime.fromMillis(0);
            }
        }).reversed());
        return found.stream().findFirst();
    }

    /**
     * Siblings of the given kind that learn made: named as it names them and holding nothing but files named as it
     * names its files. With {@code abandonedOnly}, only those whose process is gone.
     */
    List<Path> siblings(Sibling kind, boolean abandonedOnly) throws IOException {
        if (!Files.isDirectory(parent())) {
            return List.of();
        }
        List<Path> out = new ArrayList<>();
        try (Stream<Path> s = Files.list(parent())) {
            for (Path p : s.sorted().toList()) {
                Matcher m = siblingName.matcher(p.getFileName().toString());
                if (!m.matches() || !m.group(1).equals(kind.infix) || !Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS)) {
                    continue;
                }
                if (abandonedOnly && processAlive(m.group(2))) {
                    continue;
                }
                if (holdsOnlyModelFiles(p)) {
                    out.add(p);
                }
            }
        }
        return out;
    }

    private static boolean processAlive(String pid) {
        try {
            return ProcessHandle.of(Long.parseLong(pid)).map(ProcessHandle::isAlive).orElse(false);
        } catch (NumberFormatException e) {
            return false;
        }
    }

    private static boolean holdsOnlyModelFiles(Path p) throws IOException {
        try (Stream<Path> s = Files.list(p)) {
            return s.allMatch(f -> {
                String name = f.getFileName().toString();
                return Files.isRegularFile(f, LinkOption.NOFOLLOW_LINKS)
                        && (name.equals(INDEX) || name.equals(ABSTRACTION) || name.equals(ForecastFile.NAME)
                        || name.endsWith(".dot"));
            });
        }
    }

    /** Copies the permissions of an existing model directory onto its replacement, where the file system has them. */
    static void copyPermissions(Path from, Path to) throws IOException {
        try {
            Files.setPosixFilePermissions(to, Files.getPosixFilePermissions(from));
        } catch (UnsupportedOperationException e) {
            // not a POSIX file system: the replacement keeps the defaults
        }
    }

    /** Deletes a directory learn made and the files in it (never a subdirectory: learn makes none). */
    static void delete(Path p) throws IOException {
        if (!Files.exists(p, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        try (Stream<Path> s = Files.list(p)) {
            for (Path f : s.toList()) {
                Files.deleteIfExists(f);
            }
        }
        Files.deleteIfExists(p);
    }
}
