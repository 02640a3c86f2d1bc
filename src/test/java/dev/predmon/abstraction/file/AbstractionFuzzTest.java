package dev.predmon.abstraction.file;

import com.code_intelligence.jazzer.junit.FuzzTest;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.AbstractionException;
import dev.predmon.parse.LogRecord;
import dev.predmon.support.Choices;
import dev.predmon.support.HandRuns;
import org.junit.jupiter.api.Tag;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;

/**
 * Fuzzes {@link AbstractionFiles#fromJson} with mutations of the default abstraction file (deleted ranges, inserted
 * JSON tokens, swapped numbers, copied spans) and with raw bytes: the only exception that may escape is
 * {@link AbstractionException}, its message one line; an abstraction that loads classifies every record of the
 * hand-written runs without throwing.
 *
 * <p>Longer, coverage-guided:
 * <pre>JAZZER_FUZZ=1 mvn test -Dtest=AbstractionFuzzTest#mutatedAbstractionsLoadOrFailInOneLine -Djazzer.max_duration=5m</pre>
 */
@Tag("fuzz")
class AbstractionFuzzTest {

    private static final String DEFAULT = readDefault();
    private static final List<LogRecord> RECORDS = concat(HandRuns.recharge().list(), HandRuns.depleted().list());
    private static final String[] TOKENS = {"{", "}", "[", "]", ",", ":", "\"", "null", "true", "false", "0", "-1",
            "1e999", "-0.0", "20.0", "NaN", "\"x\"", "\"{loc}\"", "\"o_\"", "\"Delta\"", "\"rules\"", "\"bands\"",
            "\"equals\"", "\"any\"", "\"symbol\"", "\"input\"", "\\u0000", "\u00e9", "\n", "//", "/*"};

    @FuzzTest(maxDuration = "10s")
    void mutatedAbstractionsLoadOrFailInOneLine(byte[] input) {
        check(input);
    }

    static void check(byte[] input) {
        Choices c = new Choices(input);
        String json = c.flip() ? mutate(c) : new String(c.rest(), StandardCharsets.UTF_8);
        Abstraction a;
        try {
            a = AbstractionFiles.fromJson("fuzz.json", json);
        } catch (AbstractionException e) {
            assertNotNull(e.getMessage());
            assertFalse(e.getMessage().contains("\n"), e.getMessage());
            assertEquals(true, e.getMessage().startsWith("fuzz.json"), e.getMessage());
            return;
        }
        for (LogRecord r : RECORDS) {
            assertNotNull(a.classify(r));
        }
        assertNotNull(a.fingerprint());
        assertNotNull(a.inputAlphabet());
        a.safety().ifPresent(s -> RECORDS.forEach(s::valueOf));
    }

    private static String mutate(Choices c) {
        StringBuilder s = new StringBuilder(DEFAULT);
        for (int n = c.in(1, 6); n > 0; n--) {
            int at = c.in(0, s.length());
            switch (c.in(0, 3)) {
                case 0 -> s.delete(at, Math.min(s.length(), at + c.in(1, 40)));
                case 1 -> s.insert(at, TOKENS[c.in(0, TOKENS.length - 1)]);
                case 2 -> {
                    // Another number where a number is: overlapping or gapped bands, odd thresholds.
                    int digit = indexOfDigit(s, at);
                    if (digit >= 0) {
                        s.replace(digit, digit + 1, Integer.toString(c.in(0, 99)));
                    }
                }
                default -> {
                    int from = c.in(0, s.length());
                    int to = Math.min(s.length(), from + c.in(1, 200));
                    s.insert(at, s.substring(from, to));
                }
            }
        }
        return s.toString();
    }

    private static int indexOfDigit(CharSequence s, int from) {
        for (int i = from; i < s.length(); i++) {
            if (Character.isDigit(s.charAt(i))) {
                return i;
            }
        }
        return -1;
    }

    private static String readDefault() {
        try (InputStream in = Abstraction.class.getResourceAsStream("default-abstraction.json")) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static List<LogRecord> concat(List<LogRecord> a, List<LogRecord> b) {
        return Stream.concat(a.stream(), b.stream()).toList();
    }
}
