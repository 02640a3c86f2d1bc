package dev.predmon.abstraction.file;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import java.util.Random;
import java.util.stream.LongStream;

/**
 * The property of {@link AbstractionFuzzTest} on 200 seeded random inputs, in the default test run: the fuzz target
 * itself runs in a JVM of its own (Jazzer's agent slows every test loaded after it), on its saved inputs only.
 */
class AbstractionRandomInputTest {

    static LongStream seeds() {
        return LongStream.rangeClosed(1, 200);
    }

    @ParameterizedTest
    @MethodSource("seeds")
    void seeded(long seed) {
        Random random = new Random(seed);
        byte[] input = new byte[random.nextInt(256)];
        random.nextBytes(input);
        AbstractionFuzzTest.check(input);
    }
}
