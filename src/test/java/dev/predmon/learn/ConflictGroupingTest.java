package dev.predmon.learn;

import dev.predmon.mealy.MealyTrace;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

class ConflictGroupingTest {

    @Test
    void conflictIsFoundAtTheFirstDifferingOutputAfterEqualInputs() {
        Conflict c = Conflict.between(ThesisExamples.chars("x", "abab", "0000"), ThesisExamples.chars("y", "abab", "0001"));
        assertEquals(3, c.position());
        assertEquals("0", c.firstOutput());
        assertEquals("1", c.secondOutput());
        assertEquals(4, c.prefix().length());
    }

    @Test
    void differentInputsBeforeAnyDifferentOutputAreNoConflict() {
        assertNull(Conflict.between(ThesisExamples.chars("x", "abab", "0000"), ThesisExamples.chars("y", "abba", "0011")));
        assertNull(Conflict.between(ThesisExamples.chars("x", "ab", "00"), ThesisExamples.chars("y", "abab", "0011")));
    }

    @Test
    void consistentRunsStayInOneGroup() {
        List<MealyTrace> runs = List.of(ThesisExamples.chars("1", "ab", "00"), ThesisExamples.chars("2", "abb", "001"),
                ThesisExamples.chars("3", "ba", "11"));
        ConflictGrouping.Result r = ConflictGrouping.group(runs);
        assertEquals(1, r.groups().size());
        assertEquals(0, r.splits().size());
    }

    /** Two drain rates: after the same inputs some runs answer 0, others 1. Two groups suffice. */
    @Test
    void twoWayDisagreementGivesTwoGroupsWithTheReason() {
        List<MealyTrace> runs = List.of(ThesisExamples.chars("r1", "aab", "000"), ThesisExamples.chars("r2", "aab", "001"),
                ThesisExamples.chars("r3", "aaba", "0000"), ThesisExamples.chars("r4", "aabb", "0011"),
                ThesisExamples.chars("r5", "b", "1"));
        ConflictGrouping.Result r = ConflictGrouping.group(runs);
        assertEquals(2, r.groups().size());
        assertEquals(1, r.splits().size());
        for (List<MealyTrace> g : r.groups()) {
            for (MealyTrace a : g) {
                for (MealyTrace b : g) {
                    assertNull(Conflict.between(a, b), a.source() + " with " + b.source());
                }
            }
        }
        assertEquals(runs.size(), r.groups().stream().mapToInt(List::size).sum());
    }

    /** An odd cycle of conflicts needs three groups; greedy in file order would also give three, DSatur must not give more. */
    @Test
    void threeMutuallyConflictingRunsNeedThreeGroups() {
        List<MealyTrace> runs = List.of(ThesisExamples.chars("r1", "a", "0"), ThesisExamples.chars("r2", "a", "1"),
                ThesisExamples.chars("r3", "a", "2"));
        assertEquals(3, ConflictGrouping.group(runs).groups().size());
    }

    /** A bipartite conflict graph (a path r1-r2-r3-r4) in an order that fools naive greedy colouring. */
    @Test
    void bipartiteConflictsNeedOnlyTwoGroups() {
        // r1 conflicts r2 at 'a'; r2 conflicts r3 at 'b'; r3 conflicts r4 at 'c'; r1 and r4 agree.
        List<MealyTrace> runs = List.of(ThesisExamples.chars("r1", "ab", "00"), ThesisExamples.chars("r4", "c", "1"),
                ThesisExamples.chars("r2", "abc", "100"), ThesisExamples.chars("r3", "bc", "10"),
                ThesisExamples.chars("r5", "cb", "01"));
        assertEquals(2, ConflictGrouping.group(runs).groups().size());
    }
}
