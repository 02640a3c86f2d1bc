package dev.predmon.parse;

import com.code_intelligence.jazzer.junit.FuzzTest;
import dev.predmon.support.Choices;
import org.junit.jupiter.api.Tag;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Fuzzes the parser with garbage into which well-formed records are spliced at random line boundaries, and
 * checks the two promises of {@link LogParser}: nothing the input holds makes it throw, and every complete
 * record in the input is either emitted (with the right fields and line) or covered by a reported problem at
 * one of its lines. Bytes arrive in random chunks through the {@link LineSplitter}, as from a live file.
 *
 * <p>{@code mvn verify} runs the target on the inputs under
 * {@code src/test/resources/dev/predmon/parse/ParserFuzzTestInputs/} (Jazzer's regression mode);
 * {@link ParserRandomInputTest} runs the same check on 300 seeded random inputs. To fuzz for real, guided by coverage, for five minutes:
 * <pre>JAZZER_FUZZ=1 mvn test -Dtest=ParserFuzzTest#splicedRecordsAreParsedOrReported -Djazzer.max_duration=5m</pre>
 * A crashing input is written to that inputs directory, where it becomes a regression test.
 */
@Tag("fuzz")
class ParserFuzzTest {

    private static final String NAME = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_/.-";
    /** The kinds an intercepted record is written as, picked by index: named, not taken by place in the enum. */
    private static final List<RecordKind> KINDS = List.of(RecordKind.COMMAND, RecordKind.REPLY, RecordKind.TICK,
            RecordKind.UNKNOWN);
    /** Garbage leans to the parser's own vocabulary so that mutations reach its branches quickly. */
    private static final String[] VOCABULARY = {"Command intercepted:", "Reply intercepted:", "Message received:",
            "Tick intercepted:", "From : ", "To : ", "Protocol : ", "Command : ", "Arguments : ", "Reply : ",
            "<#STRING_START#>", "<#STRING_END#>", "NULL-DATA", "1", "71.818968", "\tDEBUG\t", " INFO ", "abc", "\r",
            "\n", "\uFEFF", "-3.5e2", "\u00e9\u2603", "\t"};

    @FuzzTest(maxDuration = "10s")
    void splicedRecordsAreParsedOrReported(byte[] input) {
        check(input);
    }

    /** A record spliced into the input: what the parser must emit, or report at one of its lines. */
    private record Spliced(LogRecord record, int lines) {
    }

    static void check(byte[] input) {
        Choices choices = new Choices(input);
        ByteArrayOutputStream log = new ByteArrayOutputStream();
        List<Spliced> spliced = new ArrayList<>();
        int segments = choices.in(0, 12);
        for (int s = 0; s < segments; s++) {
            int kind = choices.in(0, 3);
            if (kind == 0) {
                log.writeBytes(choices.bytes(120));
            } else if (kind == 1) {
                StringBuilder words = new StringBuilder();
                for (int w = choices.in(1, 6); w > 0; w--) {
                    words.append(VOCABULARY[choices.in(0, VOCABULARY.length - 1)]);
                }
                log.writeBytes(words.toString().getBytes(StandardCharsets.UTF_8));
            } else {
                byte[] sofar = log.toByteArray();
                if (sofar.length > 0 && sofar[sofar.length - 1] != '\n') {
                    log.write('\n');
                }
                long line = 1 + count(log.toByteArray(), (byte) '\n');
                spliced.add(writeRecord(choices, line, log));
            }
        }
        log.writeBytes(choices.rest());
        byte[] bytes = log.toByteArray();

        List<LogRecord> records = new ArrayList<>();
        List<ParseProblem> problems = new ArrayList<>();
        LogParser parser = new LogParser(records::add, problems::add);
        LineSplitter splitter = new LineSplitter(4096, parser.lineSink());
        Random chunks = new Random(bytes.length);
        for (int at = 0; at < bytes.length; ) {
            int n = Math.min(bytes.length - at, 1 + chunks.nextInt(97));
            splitter.feed(bytes, at, n);
            at += n;
        }
        splitter.finish();
        parser.endOfInput();

        for (Spliced s : spliced) {
            long first = s.record().line();
            long last = first + s.lines() - 1;
            boolean emitted = records.contains(s.record());
            boolean reported = problems.stream().anyMatch(p -> p.line() >= first && p.line() <= last);
            assertTrue(emitted || reported, () -> "record at line " + first + " neither emitted nor reported: "
                    + s.record() + "\nrecords: " + records + "\nproblems: " + problems);
        }
    }

    private static Spliced writeRecord(Choices c, long line, ByteArrayOutputStream log) {
        double time = c.in(-1_000_000, 2_000_000_000) / 1000.0;
        String timeText = String.format(Locale.ROOT, "%.6f", time);
        String sep = c.flip() ? "\t" : " ";
        String eol = c.flip() ? "\r\n" : "\n";
        String from = c.word(NAME, 12);
        String to = c.word(NAME, 12);
        String command = c.word(NAME, 8);
        String argument = c.flip() ? "" : c.word(NAME, 8);
        String text;
        LogRecord record;
        if (c.in(0, 3) > 0) {
            RecordKind kind = KINDS.get(c.in(0, KINDS.size() - 1));
            String protocol = c.word(NAME, 8);
            String reply = c.flip() ? "" : c.word(NAME, 8);
            String kindWord = kind.name().charAt(0) + kind.name().substring(1).toLowerCase(Locale.ROOT);
            text = timeText + sep + "DEBUG" + sep + kindWord + " intercepted:" + eol
                    + "  From      : " + from + eol + "  To        : " + to + eol + "  Protocol  : " + protocol + eol
                    + "  Command   : " + command + eol + "  Arguments : " + argument + eol + "  Reply     : " + reply + eol;
            record = new LogRecord(line, Double.parseDouble(timeText), "DEBUG", kind, from, to, protocol, command,
                    argument, reply);
        } else {
            text = timeText + sep + "DEBUG" + sep + "Message received:" + eol + "From : " + from + eol + "To : " + to
                    + eol + "Command  : " + command + eol + "Arguments: " + argument + eol;
            record = new LogRecord(line, Double.parseDouble(timeText), "DEBUG", RecordKind.COMMAND, from, to, "",
                    command, argument, "");
        }
        log.writeBytes(text.getBytes(StandardCharsets.UTF_8));
        return new Spliced(record, record.protocol().isEmpty() && record.kind() == RecordKind.COMMAND
                && text.contains("Message received") ? 5 : 7);
    }

    private static long count(byte[] bytes, byte b) {
        long n = 0;
        for (byte x : bytes) {
            if (x == b) {
                n++;
            }
        }
        return n;
    }
}
