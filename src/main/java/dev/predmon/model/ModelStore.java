package dev.predmon.model;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.alphabet.Alphabets;
import net.automatalib.automaton.transducer.CompactMealy;
import net.automatalib.serialization.InputModelData;
import net.automatalib.serialization.dot.DOTParsers;
import net.automatalib.serialization.dot.GraphDOT;
import net.automatalib.util.automaton.copy.AutomatonCopyMethod;
import net.automatalib.util.automaton.copy.AutomatonLowLevelCopy;

import java.io.IOException;
import java.io.InputStream;
import java.io.StringWriter;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

/**
 * Reads and writes a model directory: one Graphviz DOT file per machine and {@code index.json}.
 *
 * <p>Writing is atomic at the directory level: everything goes to a sibling staging directory, which then
 * replaces the old directory by two renames. A learn that fails or is killed leaves the previous models in
 * place; if it is killed between the two renames, the previous models are in {@code <dir>.old}, and
 * {@link #read} takes them from there. There is no moment without readable models: {@code .old} is deleted
 * only once the new models are in place, and staging directories of killed learns are removed by the next one.
 */
public final class ModelStore {

    /** Name of the index file inside a model directory. */
    public static final String INDEX = "index.json";
    /** Infix of staging directories: {@code <dir>.new-<pid>-<random>}. */
    private static final String STAGING = ".new-";

    private static final ObjectMapper JSON = new ObjectMapper()
            .enable(SerializationFeature.INDENT_OUTPUT)
            .enable(DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES);

    private ModelStore() {
    }

    /** The Mealy input alphabet for an abstraction: its Mealy inputs plus {@code Delta}, sorted. */
    public static Alphabet<String> alphabetOf(Abstraction abstraction) {
        List<String> symbols = new ArrayList<>(abstraction.mealyInputAlphabet());
        symbols.add(dev.predmon.mealy.MealyMapping.DELTA);
        symbols.sort(Comparator.naturalOrder());
        return Alphabets.fromList(symbols);
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
     * Replaces {@code dir} with the given machines and index, atomically.
     *
     * @param dots DOT text by file name
     */
    public static void write(Path dir, ModelIndex index, Map<String, String> dots) throws IOException {
        Path target = dir.toAbsolutePath().normalize();
        Path parent = target.getParent();
        Files.createDirectories(parent);
        String stagingPrefix = target.getFileName() + STAGING;
        deleteAbandonedStaging(parent, stagingPrefix);
        Path staging = Files.createTempDirectory(parent, stagingPrefix + ProcessHandle.current().pid() + "-");
        try {
            for (Map.Entry<String, String> e : dots.entrySet()) {
                writeDurably(staging.resolve(e.getKey()), e.getValue());
            }
            writeDurably(staging.resolve(INDEX), JSON.writeValueAsString(index) + "\n");
            Path old = oldOf(target);
            if (Files.exists(target)) {
                deleteTree(old); // the previous models are in target, so an older .old is garbage
                Files.move(target, old, StandardCopyOption.ATOMIC_MOVE);
            }
            // Otherwise .old may hold the only readable models (a learn killed between the renames): it must
            // survive until the new models are in place.
            Files.move(staging, target, StandardCopyOption.ATOMIC_MOVE);
            deleteTree(old);
        } finally {
            deleteTree(staging);
        }
    }

    /** Reads a model directory and checks it against the abstraction in use. */
    public static ModelSet read(Path dir, Abstraction abstraction) throws BadInputException {
        Path base = dir;
        if (!Files.isRegularFile(dir.resolve(INDEX)) && Files.isRegularFile(oldOf(dir).resolve(INDEX))) {
            base = oldOf(dir); // a learn was killed between its two renames: the previous models are here
        }
        Path indexFile = base.resolve(INDEX);
        if (!Files.isDirectory(base)) {
            throw new BadInputException(dir + ": no model directory; run 'predmon learn' first");
        }
        ModelIndex index;
        try {
            index = JSON.readValue(indexFile.toFile(), ModelIndex.class);
        } catch (NoSuchFileException | java.io.FileNotFoundException e) {
            throw new BadInputException(indexFile + ": missing; run 'predmon learn' first");
        } catch (JsonProcessingException e) {
            throw new BadInputException(indexFile + ":" + e.getLocation().getLineNr() + ": not a predmon model index: "
                    + e.getOriginalMessage());
        } catch (IOException e) {
            throw new BadInputException(indexFile + ": cannot read: " + e.getMessage());
        }
        if (index.format() != ModelIndex.FORMAT || index.abstraction() == null || index.scenarios() == null
                || index.alphabet() == null) {
            throw new BadInputException(indexFile + ": not a predmon model index of format " + ModelIndex.FORMAT);
        }
        if (!abstraction.fingerprint().equals(index.abstraction().fingerprint())) {
            throw new BadInputException(indexFile + ": models were learned with abstraction '"
                    + index.abstraction().name() + "' (" + shortFp(index.abstraction().fingerprint())
                    + "), not the one in use, '" + abstraction.name() + "' (" + shortFp(abstraction.fingerprint())
                    + "); relearn, or pass the abstraction they were learned with");
        }
        Alphabet<String> alphabet = alphabetOf(abstraction);
        if (!index.alphabet().equals(new ArrayList<>(alphabet))) {
            throw new BadInputException(indexFile + ": its alphabet does not match the abstraction's inputs");
        }
        List<LearnedModel> models = new ArrayList<>();
        for (ModelIndex.Scenario s : index.scenarios()) {
            for (ModelIndex.Model m : s.models()) {
                String id = m.file().endsWith(".dot") ? m.file().substring(0, m.file().length() - 4) : m.file();
                models.add(new LearnedModel(id, s.name(), s.faulty(), readDot(base.resolve(m.file()), alphabet),
                        alphabet));
            }
        }
        return new ModelSet(base, index, List.copyOf(models));
    }

    /** Parses one DOT file into a machine over the full {@code alphabet}. */
    static CompactMealy<String, String> readDot(Path file, Alphabet<String> alphabet) throws BadInputException {
        InputModelData<String, CompactMealy<String, String>> data;
        try (InputStream in = Files.newInputStream(file)) {
            data = DOTParsers.mealy().readModel(in);
        } catch (NoSuchFileException e) {
            throw new BadInputException(file + ": missing (listed in " + INDEX + ")");
        } catch (IOException | RuntimeException e) {
            throw new BadInputException(file + ": not a Mealy machine in DOT (edges labelled 'input / output'): "
                    + firstLine(e.getMessage()));
        }
        for (String symbol : data.alphabet) {
            if (symbol == null) { // AutomataLib reads an edge label without " / " as a null input
                throw new BadInputException(file + ": not a Mealy machine in DOT: an edge label is not 'input / output'");
            }
            if (!alphabet.containsSymbol(symbol)) {
                throw new BadInputException(file + ": input '" + symbol
                        + "' is not in the abstraction's alphabet; relearn with the abstraction in use");
            }
        }
        if (data.model.getInitialState() == null) {
            throw new BadInputException(file + ": has no initial state");
        }
        CompactMealy<String, String> full = new CompactMealy<>(alphabet);
        AutomatonLowLevelCopy.copy(AutomatonCopyMethod.BFS, data.model, data.alphabet, full);
        return full;
    }

    /**
     * Deletes staging directories of learns that were killed while writing: those whose owning process (the pid
     * in their name) is gone. A staging directory named without a pid (older versions) goes once it is an hour
     * old. A learn still running keeps its own.
     */
    private static void deleteAbandonedStaging(Path parent, String prefix) throws IOException {
        List<Path> candidates;
        try (Stream<Path> s = Files.list(parent)) {
            candidates = s.filter(p -> p.getFileName().toString().startsWith(prefix) && Files.isDirectory(p)).toList();
        }
        for (Path p : candidates) {
            String rest = p.getFileName().toString().substring(prefix.length());
            int dash = rest.indexOf('-');
            boolean abandoned;
            if (dash > 0 && dash <= 18 && rest.substring(0, dash).chars().allMatch(Character::isDigit)) {
                abandoned = ProcessHandle.of(Long.parseLong(rest.substring(0, dash))).map(h -> !h.isAlive()).orElse(true);
            } else {
                abandoned = Files.getLastModifiedTime(p).toInstant()
                        .isBefore(java.time.Instant.now().minus(java.time.Duration.ofHours(1)));
            }
            if (abandoned) {
                deleteTree(p);
            }
        }
    }

    private static String shortFp(String fp) {
        return fp == null ? "none" : fp.substring(0, Math.min(12, fp.length()));
    }

    private static String firstLine(String s) {
        if (s == null) {
            return "unreadable";
        }
        int nl = s.indexOf('\n');
        return nl < 0 ? s : s.substring(0, nl);
    }

    private static Path oldOf(Path dir) {
        Path abs = dir.toAbsolutePath().normalize();
        return abs.resolveSibling(abs.getFileName() + ".old");
    }

    private static void writeDurably(Path file, String text) throws IOException {
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE)) {
            ch.write(java.nio.ByteBuffer.wrap(text.getBytes(StandardCharsets.UTF_8)));
            ch.force(true);
        }
    }

    private static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir)) {
            return;
        }
        try (Stream<Path> walk = Files.walk(dir)) {
            for (Path p : walk.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        }
    }
}
