package dev.predmon.monitor;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.IntStream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The backstop's slices: every log of a round is looked at exactly once in {@code count} calls, in slices that differ
 * in size by at most one, and a log added in the middle of a round waits for the next (it was polled when added).
 */
class SlicesTest {

    @Test
    void aRoundOfTwentySlicesTakesEachOfTenThousandLogsOnceInSlicesOfFiveHundred() {
        List<Integer> logs = IntStream.range(0, 10_000).boxed().toList();
        Slices<Integer> slices = new Slices<>(20);
        List<Integer> seen = new ArrayList<>();
        for (int i = 0; i < 20; i++) {
            List<Integer> slice = slices.next(logs);
            assertEquals(500, slice.size());
            seen.addAll(slice);
        }
        assertEquals(logs, seen);
        assertEquals(logs.subList(0, 500), slices.next(logs)); // the next round begins again
    }

    @Test
    void fewerLogsThanSlicesAreEachTakenOncePerRound() {
        Slices<String> slices = new Slices<>(20);
        List<String> seen = new ArrayList<>();
        for (int i = 0; i < 20; i++) {
            List<String> slice = slices.next(List.of("a", "b", "c"));
            assertTrue(slice.size() <= 1, slice.toString());
            seen.addAll(slice);
        }
        assertEquals(List.of("a", "b", "c"), seen);
    }

    @Test
    void aLogAddedDuringARoundIsTakenFromTheNextRound() {
        Slices<String> slices = new Slices<>(2);
        assertEquals(List.of("a"), slices.next(List.of("a", "b")));
        assertEquals(List.of("b"), slices.next(List.of("a", "b", "c")));
        assertEquals(List.of("a"), slices.next(List.of("a", "b", "c")));
        assertEquals(List.of("b", "c"), slices.next(List.of("a", "b", "c")));
    }

    @Test
    void aLogForgottenDuringARoundIsNeitherGivenNorHeldAndTheOthersKeepTheirSlices() {
        Slices<String> slices = new Slices<>(2);
        List<String> logs = List.of("a", "b", "c", "d");
        assertEquals(List.of("a", "b"), slices.next(logs));
        slices.forget("c");
        slices.forget("x"); // never there
        assertEquals(List.of("d"), slices.next(List.of("a", "b", "d")));
        assertEquals(List.of("a"), slices.next(List.of("a", "b", "d"))); // a new round: 3 logs in slices of 1 and 2
    }
}
