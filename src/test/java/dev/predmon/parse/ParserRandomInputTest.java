package dev.predmon.parse;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import java.util.Random;
import java.util.stream.LongStream;

/**
 * The property of {@link ParserFuzzTest} on 300 seeded random inputs, in the default test run: the fuzz target
 * itself runs in a JVM of its own (Jazzer's agent slows every test loaded after it), on its saved inputs only.
 */
class ParserRandomInputTest {

    static LongStream seeds() {
        return LongStream.rangeClosed(1, 300);
    }

    @ParameterizedTest
    @MethodSource("seeds")
    void seeded(long seed) {
        Random random = new Random(seed);
        byte[] input = new byte[random.nextInt(2048)];
        random.nextBytes(input);
        ParserFuzzTest.check(input);
    }
}
