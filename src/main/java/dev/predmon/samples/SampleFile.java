package dev.predmon.samples;

import dev.predmon.BadInputException;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.mealy.MealyTrace;
import net.automatalib.word.Word;
import net.automatalib.word.WordBuilder;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The Mealy samples that {@code learn} gives LearnLib, as plain text for other learners (AALpy, flexfringe).
 *
 * <p>Format (UTF-8, {@code \n}): lines starting with {@code #} are comments; a header names the scenario
 * ({@code # scenario: NAME}), whether it is faulty ({@code # faulty: true|false}) and, before each group of
 * traces learned together as one machine, {@code # machine: ID}. Every other non-empty line is one trace: its
 * Mealy steps separated by single spaces, each step {@code input/output}. Symbols never contain spaces or
 * {@code /} (the abstraction's symbols are identifiers), so a step splits at its only {@code /}. Example:
 * {@code goTo_kitchen/OK Delta/running isAt_kitchen/OK Delta/false}.
 */
public final class SampleFile {

    /** How every sample file begins: {@code export-samples} replaces an existing file only when it begins so. */
    public static final String SIGNATURE = "# predmon Mealy samples";

    private SampleFile() {
    }

    /** The file's text for a learned scenario: every sample of every machine, in the order learned. */
    public static String text(LearnedScenario s) {
        StringBuilder sb = new StringBuilder();
        sb.append(SIGNATURE).append(": one trace per line, steps input/output separated by spaces\n")
                .append("# scenario: ").append(s.spec().name()).append('\n')
                .append("# faulty: ").append(s.spec().faulty()).append('\n');
        for (LearnedScenario.Machine m : s.machines()) {
            sb.append("# machine: ").append(m.id()).append(" (").append(m.samples().size()).append(" traces)\n");
            for (MealyTrace t : m.samples()) {
                sb.append(line(t)).append('\n');
            }
        }
        return sb.toString();
    }

    /** One trace as a line. */
    public static String line(MealyTrace t) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < t.length(); i++) {
            String in = t.inputs().getSymbol(i);
            String out = t.outputs().getSymbol(i);
            if (in.contains("/") || in.contains(" ") || out.contains("/") || out.contains(" ")) {
                throw new IllegalArgumentException("symbol with '/' or space cannot be exported: " + in + "/" + out);
            }
            sb.append(i == 0 ? "" : " ").append(in).append('/').append(out);
        }
        return sb.toString();
    }

    /** Reads the traces of a sample file back. */
    public static List<MealyTrace> read(Path file) throws IOException, BadInputException {
        List<MealyTrace> traces = new ArrayList<>();
        List<String> lines = Files.readAllLines(file);
        for (int n = 0; n < lines.size(); n++) {
            String l = lines.get(n).strip();
            if (l.isEmpty() || l.startsWith("#")) {
                continue;
            }
            WordBuilder<String> in = new WordBuilder<>();
            WordBuilder<String> out = new WordBuilder<>();
            for (String step : l.split(" ", -1)) {
                int slash = step.indexOf('/');
                if (slash <= 0 || slash == step.length() - 1 || step.indexOf('/', slash + 1) >= 0) {
                    throw new BadInputException(file + ":" + (n + 1) + ": expected input/output, got '" + step + "'");
                }
                in.append(step.substring(0, slash));
                out.append(step.substring(slash + 1));
            }
            Word<String> inputs = in.toWord();
            traces.add(new MealyTrace(inputs, out.toWord(), file + ":" + (n + 1)));
        }
        return traces;
    }
}
