package dev.predmon.model;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.files.AtomicFiles;
import dev.predmon.files.OutputFiles;
import dev.predmon.forecast.ForecastFile;
import dev.predmon.forecast.ForecastModel;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.automaton.transducer.CompactMealy;
import net.automatalib.serialization.dot.GraphDOT;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * Reads and writes a model directory: one Graphviz DOT file per machine, {@code index.json}, and
 * {@code abstraction.json}, the abstraction the models were learned with.
 *
 * <p>Writing never destroys a user's files: it replaces only a directory predmon wrote (or an empty one) and
 * refuses anything else before changing anything ({@link ModelDirectory}). It is atomic at the directory level:
 * everything goes to a sibling staging directory, which then replaces the old directory by two renames. A learn
 * that fails or is killed leaves the previous models in place; if it is killed between the two renames, the
 * previous models are in the set-aside sibling {@code <dir>.old-<pid>-<n>}, and {@link #read} takes them from
 * there. There is no moment without readable models: a set-aside directory is deleted only once new models are
 * in place, and staging directories of killed learns are removed by the next one. What can fail is checked first
 * (ownership, permissions), so a failed learn leaves exactly the previous state.
 */
public final class ModelStore {

    /** Name of the index file inside a model directory. */
    public static final String INDEX = ModelDirectory.INDEX;
    /**
     * Name of the file holding the abstraction the models were learned with (its SHA-256, without the safety
     * property's action, is the fingerprint).
     */
    public static final String ABSTRACTION = ModelDirectory.ABSTRACTION;

    /**
     * The writer of {@code index.json}, built on first use: only {@code learn} writes, and building a mapper is a
     * tenth of a second that the commands reading models ({@link IndexReader}) need not spend.
     */
    private static final class IndexWriter {
        static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);
    }

    private ModelStore() {
    }

    /** The DOT text of a machine, as written to disk (deterministic for a given machine). */
    public static String toDot(CompactMealy<String, String> machine, Alphabet<String> alphabet) {
        StringWriter out = new StringWriter();
        try {
            GraphDOT.write(machine, alphabet, out);
        } catch (IOException e) {
            throw new IllegalStateException("writing to a string cannot fail", e);
        }
        return out.toString();
    }

    /**
     * Checks, before learning starts, that {@link #write} may replace {@code models} with models learned from
     * {@code logs}: the directory is new, empty or predmon's own, everything needed is writable, and it is not the
     * log directory, inside it, or around it (replacing it would delete the logs, or learn them as a scenario).
     */
    public static void checkWritable(Path models, Path logs) throws BadInputException {
        ModelDirectory target = ModelDirectory.of(models);
        Path logsPath = OutputFiles.resolved(logs);
        Path modelsPath = target.path();
        if (modelsPath.equals(logsPath)) {
            throw new BadInputException(models + ": is the log directory --logs; choose another --models");
        }
        if (modelsPath.startsWith(logsPath)) {
            throw new BadInputException(models + ": is inside the log directory " + logs + "; choose --models outside it");
        }
        if (logsPath.startsWith(modelsPath)) {
            throw new BadInputException(models + ": holds the log directory " + logs + ", which learn would "
                    + "replace; choose another --models");
        }
        target.requireReplaceable();
    }

    /**
     * Replaces {@code dir} with the given machines, index and abstraction, atomically, if it is new, empty or a
     * model directory predmon wrote; else refuses and changes nothing.
     *
     * @param dots            DOT text by file name
     * @param abstractionJson the abstraction's canonical JSON, written as {@value #ABSTRACTION}
     * @return notes for the user (a set-aside directory that could not be removed), usually none
     */
    public static List<String> write(Path dir, ModelIndex index, Map<String, String> dots, String abstractionJson)
            throws IOException, BadInputException {
        return write(dir, index.with(null, learnId(index, dots)), dots, abstractionJson, step -> { });
    }

    /** As above, with the forecast's statistics, written as {@value ForecastFile#NAME} and listed in the index. */
    public static List<String> write(Path dir, ModelIndex index, Map<String, String> dots, String abstractionJson,
                                     ForecastModel forecast) throws IOException, BadInputException {
        return write(dir, index, dots, abstractionJson, forecast, step -> { });
    }

    /** As above; {@code step} is told each step before it is taken (see the stepped write without a forecast). */
    public static List<String> write(Path dir, ModelIndex index, Map<String, String> dots, String abstractionJson,
                                     ForecastModel forecast, Consumer<String> step)
            throws IOException, BadInputException {
        String id = learnId(index, dots);
        Map<String, String> files = new LinkedHashMap<>(dots);
        files.put(ForecastFile.NAME, ForecastFile.write(forecast, id));
        return write(dir, index.with(ForecastFile.NAME, id), files, abstractionJson, step);
    }

    /** The id that ties {@code index}, its DOT files and the forecast together ({@link LearnId}). */
    private static String learnId(ModelIndex index, Map<String, String> dots) {
        LearnId id = new LearnId(index.abstraction() == null ? null : index.abstraction().fingerprint());
        for (ModelIndex.Scenario s : index.scenarios()) {
            for (ModelIndex.Model m : s.models()) {
                id.add(m.file(), dots.getOrDefault(m.file(), "").getBytes(StandardCharsets.UTF_8));
            }
        }
        return id.value();
    }

    /**
     * As above; {@code step} is told each step just before it is taken: {@code write} (the files, into the staging
     * directory), {@code set-aside} (rename the previous models aside), {@code move-in} (rename the staging
     * directory into place), {@code clean-up} (delete the previous models), so that a test can kill a learn at each.
     */
    static List<String> write(Path dir, ModelIndex index, Map<String, String> dots, String abstractionJson,
                              Consumer<String> step) throws IOException, BadInputException {
        ModelDirectory d = ModelDirectory.of(dir);
        d.requireReplaceable();
        Path target = d.path();
        Files.createDirectories(d.parent());
        for (Path abandoned : d.siblings(ModelDirectory.Sibling.STAGING, true)) {
            ModelDirectory.delete(abandoned);
        }
        boolean hasModels = Files.isRegularFile(target.resolve(INDEX));
        if (hasModels) {
            // the models in place are the ones to keep: what earlier killed learns set aside is garbage
            for (Path abandoned : d.siblings(ModelDirectory.Sibling.SET_ASIDE, true)) {
                ModelDirectory.delete(abandoned);
            }
        }
        Path staging = d.createSibling(ModelDirectory.Sibling.STAGING);
        List<String> notes = new ArrayList<>();
        try {
            if (Files.isDirectory(target)) {
                ModelDirectory.copyPermissions(target, staging);
            }
            step.accept("write");
            Map<String, String> files = new LinkedHashMap<>(dots);
            files.put(ABSTRACTION, abstractionJson);
            files.put(INDEX, IndexWriter.JSON.writeValueAsString(index) + "\n");
            for (Map.Entry<String, String> e : files.entrySet()) {
                try {
                    AtomicFiles.create(staging.resolve(e.getKey()), e.getValue());
                } catch (IOException ex) {
                    // named as the user will look for it, not by the staging directory that is about to go
                    throw AtomicFiles.notWritten(dir.resolve(e.getKey()), ex, "the previous models are unchanged");
                }
            }
            Path aside = null;
            if (Files.exists(target)) {
                step.accept("set-aside");
                aside = d.sibling(ModelDirectory.Sibling.SET_ASIDE);
                Files.move(target, aside, StandardCopyOption.ATOMIC_MOVE);
            }
            step.accept("move-in");
            try {
                Files.move(staging, target, StandardCopyOption.ATOMIC_MOVE);
            } catch (IOException e) {
                if (aside != null) {
                    Files.move(aside, target, StandardCopyOption.ATOMIC_MOVE); // put the previous models back
                }
                throw e;
            }
            step.accept("clean-up");
            // The new models are in place: what is set aside (now, or by a learn killed between its renames) goes.
            List<Path> garbage = new ArrayList<>(d.siblings(ModelDirectory.Sibling.SET_ASIDE, true));
            if (aside != null) {
                garbage.add(aside);
            }
            for (Path p : garbage) {
                try {
                    ModelDirectory.delete(p);
                } catch (IOException e) {
                    notes.add(p + ": the previous models could not be removed (" + BadInputException.reason(e)
                            + "); the new ones are in place: remove it by hand");
                }
            }
        } finally {
            ModelDirectory.delete(staging);
        }
        return List.copyOf(notes);
    }

    /**
     * The abstraction file a model directory carries ({@value #ABSTRACTION}), if it has one: where {@link #read}
     * would read the models from.
     */
    public static Optional<Path> storedAbstraction(Path dir) {
        Path file = modelsAt(dir).resolve(ABSTRACTION);
        return Files.isRegularFile(file) ? Optional.of(file) : Optional.empty();
    }

    /** Where the models of {@code dir} are: {@code dir}, or what a learn killed between its renames set aside. */
    private static Path modelsAt(Path dir) {
        Path abs = dir.toAbsolutePath().normalize();
        if (Files.isRegularFile(dir.resolve(INDEX)) || abs.getParent() == null || abs.getFileName() == null) {
            return dir;
        }
        try {
            return ModelDirectory.lenient(dir).setAside().orElse(dir);
        } catch (IOException e) {
            return dir; // the parent cannot be listed: read reports the directory itself
        }
    }

    /**
     * Reads a model directory and checks it against the abstraction in use, and its index against its DOT files
     * ({@link ModelReader}).
     *
     * <p>A learn may replace the directory while it is read. Each file is read by its path, so a read that
     * straddles the replacement would take the index of one learn and DOT files of the other. Each read therefore
     * notes which directory it started in and, if that is no longer the directory there when it ends, is done again
     * (the learn id already refuses most mixtures; this makes the set read always the old one or the new one).
     */
    public static ModelSet read(Path dir, Abstraction abstraction) throws BadInputException {
        return read(dir, abstraction, step -> { });
    }

    /** As above; {@code step} is told {@code index} once the index is read, so that a test can replace the models then. */
    static ModelSet read(Path dir, Abstraction abstraction, Consumer<String> step) throws BadInputException {
        for (int attempt = 1; ; attempt++) {
            Path base = modelsAt(dir);
            Object before = identity(base);
            boolean last = attempt >= READ_ATTEMPTS;
            try {
                ModelSet set = ModelReader.read(dir, base, abstraction, step);
                if (last || unchanged(dir, base, before)) {
                    return set;
                }
            } catch (BadInputException e) {
                if (last || before == null || unchanged(dir, base, before)) {
                    throw e;
                }
            }
        }
    }

    /**
     * Reads of a directory that a learn replaces while it is read, before the last read's answer is given: each
     * learn replaces it once, so only learns that follow each other within a read's time can take them all.
     */
    private static final int READ_ATTEMPTS = 20;

    /**
     * Whether the models of {@code dir} are still in {@code base}, the same directory as before: learn moves whole
     * directories and changes none in place, except that it empties previous models set aside before it removes
     * them, once the new ones are in {@code dir}.
     */
    private static boolean unchanged(Path dir, Path base, Object before) {
        return Objects.equals(before, identity(base)) && modelsAt(dir).equals(base);
    }

    /**
     * Which directory {@code dir} is now, or null when there is none: its file key (an inode) with its last
     * modification, since a directory learn removed gives its inode back and the next learn's may get it again.
     */
    private static Object identity(Path dir) {
        try {
            BasicFileAttributes a = Files.readAttributes(dir, BasicFileAttributes.class);
            return List.of(a.fileKey() != null ? a.fileKey() : a.creationTime(), a.lastModifiedTime());
        } catch (IOException e) {
            return null;
        }
    }

    /**
     * {@code machine} as it reads back from its DOT file: the same machine, its states numbered as every command that
     * loads a model directory numbers them. Learning renumbers through this, so that statistics kept by state number
     * fit the machine in memory and on disk alike.
     */
    public static CompactMealy<String, String> canonical(CompactMealy<String, String> machine, Alphabet<String> alphabet) {
        try {
            return ModelReader.fromDot(Path.of("(learned machine)"), new ByteArrayInputStream(
                    toDot(machine, alphabet).getBytes(StandardCharsets.UTF_8)), alphabet);
        } catch (BadInputException | IOException e) {
            throw new IllegalStateException("a learned machine does not read back from its own DOT text", e);
        }
    }
}
