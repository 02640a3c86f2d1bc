package dev.predmon.parse;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import java.nio.charset.StandardCharsets;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** Property: however the bytes of a log arrive, the records and problems are those of the whole log. */
class ChunkedInputTest {

    private static final String BROKEN = """
            3.0 DEBUG Command intercepted:
              From : /a
              Command : x
            abc DEBUG Reply intercepted:
            9.0 DEBUG Message received:
            From : /s
            To : /c
            Reply    : getStatus
            Arguments: kitchen 2
            9.5 DEBUG Reply intercepted:
              From : /s
            """;

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20})
    void randomChunksParseLikeTheWhole(long seed) {
        String log = SampleLogs.mixed(30, seed) + "1.0 INFO caf\u00e9 \u2603\n" + BROKEN;
        byte[] bytes = log.getBytes(StandardCharsets.UTF_8);

        Collected whole = new Collected();
        LineSplitter all = new LineSplitter(LineSplitter.DEFAULT_MAX_LINE_BYTES, whole.parser.lineSink());
        all.feed(bytes, 0, bytes.length);
        all.finish();
        whole.parser.endOfInput();

        Collected chunked = new Collected();
        LineSplitter pieces = new LineSplitter(LineSplitter.DEFAULT_MAX_LINE_BYTES, chunked.parser.lineSink());
        Random random = new Random(seed);
        for (int at = 0; at < bytes.length; ) {
            int n = Math.min(bytes.length - at, random.nextInt(64));
            pieces.feed(bytes, at, n);
            at += n;
        }
        pieces.finish();
        chunked.parser.endOfInput();

        assertEquals(31, whole.records.size());
        assertEquals(3, whole.problems.size());
        assertEquals(whole.records, chunked.records);
        assertEquals(whole.problems, chunked.problems);
    }
}
