package dev.predmon.model;

import dev.predmon.BadInputException;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.forecast.ForecastFile;
import dev.predmon.forecast.ForecastModel;
import dev.predmon.forecast.PropertyParts;
import dev.predmon.mealy.MealyAlphabet;
import net.automatalib.alphabet.Alphabet;
import net.automatalib.automaton.CompactTransition;
import net.automatalib.automaton.transducer.CompactMealy;
import net.automatalib.serialization.InputModelData;
import net.automatalib.serialization.dot.DOTParsers;
import net.automatalib.util.automaton.copy.AutomatonCopyMethod;
import net.automatalib.util.automaton.copy.AutomatonLowLevelCopy;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Consumer;
import java.util.regex.Pattern;

/**
 * Reads a model directory and checks that it is one: its {@code index.json} and its DOT files must agree with each
 * other and with the abstraction in use, or the models would judge a robot by something nobody learned. The index
 * must list at least one model, each scenario once, each model a distinct DOT file of the directory, and as its
 * forecast only the file learn writes; each DOT file must have the states the index gives it and use only the
 * abstraction's inputs and outputs. Each disagreement is one line naming the file.
 */
final class ModelReader {

    /** A model file as learn names it: a plain name in the directory, ending in {@code .dot}. */
    static final Pattern DOT_NAME = Pattern.compile("[^/\\\\.][^/\\\\]*\\.dot");

    private final Path indexFile;
    private final Alphabet<String> alphabet;
    private final Set<String> outputs;

    private ModelReader(Path indexFile, Abstraction abstraction) {
        this.indexFile = indexFile;
        this.alphabet = MealyAlphabet.inputs(abstraction);
        this.outputs = MealyAlphabet.outputs(abstraction);
    }

    /**
     * Reads the model directory {@code base} ({@code dir} as the user named it) against {@code abstraction};
     * {@code step} is told {@code index} once the index is read.
     */
    static ModelSet read(Path dir, Path base, Abstraction abstraction, Consumer<String> step)
            throws BadInputException {
        Path indexFile = base.resolve(ModelStore.INDEX);
        if (!Files.isDirectory(base)) {
            throw new BadInputException(dir + ": no model directory; run 'predmon learn' first");
        }
        ModelIndex index = IndexReader.read(indexFile);
        step.accept("index");
        if (index.format() != ModelIndex.FORMAT || index.abstraction() == null || index.scenarios() == null
                || index.alphabet() == null || !complete(index.scenarios())) {
            throw new BadInputException(indexFile + ": not a predmon model index of format " + ModelIndex.FORMAT);
        }
        if (!abstraction.fingerprint().equals(index.abstraction().fingerprint())) {
            Path stored = Files.isRegularFile(base.resolve(ModelStore.ABSTRACTION))
                    ? base.resolve(ModelStore.ABSTRACTION) : null;
            throw new BadInputException(indexFile + ": " + AbstractionMismatch.describe(index.abstraction(),
                    abstraction, stored));
        }
        ModelReader reader = new ModelReader(indexFile, abstraction);
        if (!index.alphabet().equals(new ArrayList<>(reader.alphabet))) {
            throw new BadInputException(indexFile + ": its alphabet does not match the abstraction's inputs");
        }
        reader.checkEntries(index.scenarios());
        if (index.learnId() == null) {
            throw new BadInputException(indexFile + ": has no learn id to tie its files together (it was written by an "
                    + "earlier predmon); run 'predmon learn' again");
        }
        LearnId learnId = new LearnId(index.abstraction().fingerprint());
        List<LearnedModel> models = new ArrayList<>();
        for (ModelIndex.Scenario s : index.scenarios()) {
            for (ModelIndex.Model m : s.models()) {
                String id = m.file().substring(0, m.file().length() - ".dot".length());
                models.add(new LearnedModel(id, s.name(), s.faulty(), reader.readDot(base.resolve(m.file()),
                        m.states(), learnId), reader.alphabet));
            }
        }
        if (!learnId.value().equals(index.learnId())) {
            throw new BadInputException(indexFile + ": its DOT files are not the ones it was written with (they are "
                    + "of another learn); the directory mixes files of different learns: relearn");
        }
        ForecastModel forecast = reader.forecast(base, index);
        if (forecast != null) {
            ForecastCheck.check(base.resolve(ForecastFile.NAME), indexFile, forecast, models, abstraction);
            forecast = PropertyParts.named(forecast, abstraction);
        }
        return new ModelSet(base, index, List.copyOf(models), forecast);
    }

    /** The forecast the index lists, or null when it lists none (a directory learned before forecasts were). */
    private ForecastModel forecast(Path base, ModelIndex index) throws BadInputException {
        if (index.forecast() == null) {
            return null;
        }
        if (!index.forecast().equals(ForecastFile.NAME)) {
            // the one name learn writes: any other would read (and trust) a file learn never wrote
            throw new BadInputException(indexFile + ": forecast '" + index.forecast() + "' is not "
                    + ForecastFile.NAME + ", the file learn writes; relearn");
        }
        Path file = base.resolve(index.forecast());
        try {
            return ForecastFile.read(Files.readString(file, StandardCharsets.UTF_8), index.learnId());
        } catch (NoSuchFileException e) {
            throw new BadInputException(file + ": missing (listed in " + indexFile.getFileName()
                    + "); run 'predmon learn' again");
        } catch (IOException e) {
            throw BadInputException.cannotRead(file, e);
        } catch (IllegalArgumentException e) {
            throw new BadInputException(file + ": not a predmon forecast: " + e.getMessage());
        }
    }

    /** Whether every scenario lists its models and every model its file (null ones were a crash, not a message). */
    private static boolean complete(List<ModelIndex.Scenario> scenarios) {
        for (ModelIndex.Scenario s : scenarios) {
            if (s == null || s.name() == null || s.models() == null
                    || s.models().stream().anyMatch(m -> m == null || m.file() == null)) {
                return false;
            }
        }
        return true;
    }

    /** At least one model; each scenario once; each model a DOT file of the directory, listed once. */
    private void checkEntries(List<ModelIndex.Scenario> scenarios) throws BadInputException {
        if (scenarios.stream().allMatch(s -> s.models().isEmpty())) {
            // Without a model every log would be "no model matches" (exit 5), a verdict about the robot.
            throw new BadInputException(indexFile + ": no models (it lists no scenario with a machine); run "
                    + "'predmon learn' on logs of at least one scenario");
        }
        Set<String> names = new HashSet<>();
        Set<String> files = new HashSet<>();
        for (ModelIndex.Scenario s : scenarios) {
            if (!ModelIndex.SCENARIO_NAME.matcher(s.name()).matches()) {
                // learn names scenarios so; any other name (a control character, a bidirectional override) would
                // reach a terminal, a hook's environment and the live page as it is
                throw new BadInputException(indexFile + ": scenario name '" + s.name() + "' is not one learn "
                        + "writes (letters, digits, '_', '-' and '.'); relearn");
            }
            if (!names.add(s.name())) {
                throw new BadInputException(indexFile + ": scenario '" + s.name() + "' is listed twice; "
                        + "each scenario has one entry: relearn");
            }
            if (s.models().isEmpty()) {
                throw new BadInputException(indexFile + ": scenario '" + s.name() + "' lists no models; relearn");
            }
            for (ModelIndex.Model m : s.models()) {
                if (!DOT_NAME.matcher(m.file()).matches()) {
                    throw new BadInputException(indexFile + ": scenario '" + s.name() + "': model file '" + m.file()
                            + "' is not the name of a DOT file in the model directory (NAME.dot)");
                }
                if (!files.add(m.file())) {
                    throw new BadInputException(indexFile + ": model file '" + m.file() + "' is listed twice; "
                            + "each model has a file of its own: relearn");
                }
            }
        }
    }

    /** Parses one DOT file into a machine over the full alphabet, checked against its entry in the index. */
    private CompactMealy<String, String> readDot(Path file, int states, LearnId learnId) throws BadInputException {
        InputModelData<String, CompactMealy<String, String>> data;
        try {
            byte[] bytes = Files.readAllBytes(file);
            learnId.add(file.getFileName().toString(), bytes);
            data = parse(file, new ByteArrayInputStream(bytes), alphabet);
        } catch (NoSuchFileException e) {
            throw new BadInputException(file + ": missing (listed in " + indexFile.getFileName() + ")");
        } catch (IOException e) {
            throw BadInputException.cannotRead(file, e);
        }
        CompactMealy<String, String> model = data.model;
        if (model.size() != states) {
            throw new BadInputException(file + ": has " + model.size() + " states, but " + indexFile.getFileName()
                    + " says " + states + "; the directory mixes files of different learns: relearn");
        }
        for (Integer state : model.getStates()) {
            for (String input : data.alphabet) {
                CompactTransition<String> t = model.getTransition(state, input);
                String output = t == null ? null : model.getTransitionOutput(t);
                if (t != null && !outputs.contains(output)) {
                    throw new BadInputException(file + ": output '" + output + "' (after input '" + input
                            + "') is not one of the abstraction's outputs; relearn with the abstraction in use");
                }
            }
        }
        return full(data, alphabet);
    }

    /** Parses DOT text into a machine over the full {@code alphabet}, as every command that loads models does. */
    static CompactMealy<String, String> fromDot(Path file, InputStream in, Alphabet<String> alphabet)
            throws BadInputException, IOException {
        return full(parse(file, in, alphabet), alphabet);
    }

    /** The machine of DOT text, its inputs checked against {@code alphabet}; {@code file} names it in messages. */
    private static InputModelData<String, CompactMealy<String, String>> parse(Path file, InputStream in,
                                                                            Alphabet<String> alphabet)
            throws BadInputException, IOException {
        InputModelData<String, CompactMealy<String, String>> data;
        try {
            data = DOTParsers.mealy().readModel(in);
        } catch (RuntimeException e) {
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
        return data;
    }

    /** The machine copied breadth first onto the full alphabet: every command numbers its states the same way. */
    private static CompactMealy<String, String> full(InputModelData<String, CompactMealy<String, String>> data,
                                                     Alphabet<String> alphabet) {
        CompactMealy<String, String> full = new CompactMealy<>(alphabet);
        AutomatonLowLevelCopy.copy(AutomatonCopyMethod.BFS, data.model, data.alphabet, full);
        return full;
    }

    private static String firstLine(String s) {
        if (s == null) {
            return "unreadable";
        }
        int nl = s.indexOf('\n');
        return nl < 0 ? s : s.substring(0, nl);
    }
}
