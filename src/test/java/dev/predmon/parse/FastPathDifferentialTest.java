package dev.predmon.parse;

import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;
import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * The parser reads most lines straight from bytes (a fast path for well-formed ASCII field lines and headers) and
 * everything else as strings. Both must give exactly the same records and problems: the same text is fed once as
 * strings ({@link LogParser#acceptLine(String)}, the general path only) and once as bytes (the fast path where it
 * applies), for every simulated layout and for thousands of seeded mutations of them.
 */
class FastPathDifferentialTest {

    private record Outcome(List<LogRecord> records, List<ParseProblem> problems) {
    }

    private static Outcome viaStrings(String text) {
        Outcome o = new Outcome(new ArrayList<>(), new ArrayList<>());
        LogParser p = new LogParser(o.records()::add, o.problems()::add);
        for (String line : text.split("\n", -1)) {
            p.acceptLine(line.endsWith("\r") ? line.substring(0, line.length() - 1) : line);
        }
        p.endOfInput();
        return o;
    }

    private static Outcome viaBytes(String text) {
        Outcome o = new Outcome(new ArrayList<>(), new ArrayList<>());
        LogParser p = new LogParser(o.records()::add, o.problems()::add);
        LineSink sink = p.lineSink();
        for (String line : text.split("\n", -1)) {
            byte[] b = line.getBytes(StandardCharsets.UTF_8);
            int len = b.length > 0 && b[b.length - 1] == '\r' ? b.length - 1 : b.length;
            byte[] padded = new byte[len + 6]; // offset 3: the fast path must honour offsets
            System.arraycopy(b, 0, padded, 3, len);
            sink.line(padded, 3, len);
        }
        p.endOfInput();
        return o;
    }

    private static List<String> layouts() {
        List<String> texts = new ArrayList<>();
        SimOptions plain = SimOptions.defaults();
        for (Scenario s : Scenario.values()) {
            var run = Simulator.run(s, 5, plain);
            texts.add(LogWriter.toText(run, plain));
            texts.add(LogWriter.toText(run, plain.withRawLines(true).withSpaces(true)));
            texts.add(LogWriter.toText(run, plain.withLateReplies(0.4).withVocab(true).withCrlf(true)));
            texts.add(LogWriter.toText(Simulator.run(s, 5, plain.withEpoch(true)), plain.withEpoch(true)));
        }
        return texts;
    }

    @Test
    void everyLayoutParsesTheSameBothWays() {
        for (String text : layouts()) {
            Outcome s = viaStrings(text);
            assertEquals(s, viaBytes(text));
        }
    }

    /** Byte flips, deleted and inserted characters, cut lines: whatever the general path makes of it, so must the fast one. */
    @Test
    void mutatedLogsParseTheSameBothWays() {
        String base = layouts().get(0);
        String[] lines = base.split("\n", -1);
        String alphabet = " \t:<>#_-.0123456789aeiAEIRCTDGNOUV\u00e9\u0000";
        for (int seed = 0; seed < 3000; seed++) {
            Random rnd = new Random(seed);
            int from = rnd.nextInt(Math.max(1, lines.length - 60));
            StringBuilder sb = new StringBuilder();
            for (int i = from; i < Math.min(lines.length, from + 60); i++) {
                StringBuilder line = new StringBuilder(lines[i]);
                if (rnd.nextInt(4) == 0 && line.length() > 0) {
                    int at = rnd.nextInt(line.length());
                    switch (rnd.nextInt(3)) {
                        case 0 -> line.setCharAt(at, alphabet.charAt(rnd.nextInt(alphabet.length())));
                        case 1 -> line.deleteCharAt(at);
                        default -> line.insert(at, alphabet.charAt(rnd.nextInt(alphabet.length())));
                    }
                }
                if (rnd.nextInt(40) == 0) {
                    line.setLength(rnd.nextInt(line.length() + 1));
                }
                sb.append(line).append('\n');
            }
            String text = sb.toString();
            assertEquals(viaStrings(text), viaBytes(text), "seed " + seed);
        }
    }
}
