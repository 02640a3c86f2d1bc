package dev.predmon.property;

import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

/**
 * The checker asked after every record, as the monitor asks it, with the answers worked out by hand: a bound's
 * violations and recoveries through a long violation, and which of several open obligations is the one pending as
 * their counts move.
 */
class RecordByRecordTest {

    private static final ValueReader LEVEL = new ValueReader("BatteryReader", "level", "/BatteryComponent",
            "/BatteryReaderBatteryLevelClient");

    @Test
    void aBoundViolatedAgainAfterItHeldIsToldAgainWithItsOwnReading() {
        Bound floor = new Bound("battery", "level >= 20", null, LEVEL, 20);
        // readings at lines 2, 4, 6, 8, 10: 25 holds, 15 violates, 10 is the same violation, 25 holds again, 12
        // violates again
        Trace run = new Trace().level(25).level(15).level(10).level(25).level(12);
        List<String> told = new ArrayList<>();
        PropertyChecker c = new PropertyChecker(List.of(floor), (i, p, v) -> told.add(p.id() + "@" + v.line()));
        List<String> made = new ArrayList<>();
        List<Long> again = new ArrayList<>();
        for (LogRecord r : run.records()) {
            c.accept(r);
            Verdict.Violated v = c.violatedAt(0);
            if (v != null) {
                made.add(v.line() + ": " + v.what() + ", before " + v.before());
            }
            if (c.holdsAgain(0)) {
                again.add(r.line());
            }
        }
        assertEquals(List.of("4: 15 below the floor 20, before 25.0", "10: 12 below the floor 20, before 25.0"), made,
                "the reading of 10 at line 6 continues the violation of line 4: nothing new is made there");
        assertEquals(List.of(8L), again);
        Verdict.Violated verdict = assertInstanceOf(Verdict.Violated.class, c.verdict(0));
        assertEquals(4, verdict.line(), "the run's verdict is its first violation");
        assertEquals("15 below the floor 20", verdict.what());
        assertEquals(List.of("battery@4"), told, "told once, at the first violation");
    }

    @Test
    void theObligationPendingFollowsTheCountsOfEachInstance() {
        Event close = new Event(List.of(new RecordMatch(RecordKind.COMMAND, "ArmService", "closeHand", null, null,
                null, null)));
        Event grasped = new Event(List.of(new RecordMatch(RecordKind.REPLY, "ArmService", "hasGrasped", null, null,
                null, List.of("1"))));
        Response grasp = new Response("grasp", "grasped within 3 attempts per arm", null, Scope.GLOBAL, close, null,
                grasped, null, new Deadline(3, Deadline.Unit.OCCURRENCES, close), Response.Per.CLIENT);
        // arm A's closeHand (lines 1, 2) opens its grasp; arm B's (3, 4) opens another, as near its deadline (one
        // attempt of three each): the earlier opened is the one pending; B's second attempt (5, 6) makes B's the
        // nearest, with two attempts
        Trace run = new Trace().call("/ArmA", "/ArmComponent", "ArmService", "closeHand", "", "27503")
                .call("/ArmB", "/ArmComponent", "ArmService", "closeHand", "", "27503")
                .call("/ArmB", "/ArmComponent", "ArmService", "closeHand", "", "27503")
                .call("/ArmA", "/ArmComponent", "ArmService", "hasGrasped", "", "1");
        PropertyChecker c = new PropertyChecker(List.of(grasp), (i, p, v) -> { });
        List<Long> lines = new ArrayList<>();
        List<Double> elapsed = new ArrayList<>();
        for (LogRecord r : run.records()) {
            c.accept(r);
            lines.add(c.pendingLine(0));
            elapsed.add(c.elapsed(0));
        }
        // A's grasp succeeds at line 8: B's, two attempts, is the one left
        assertEquals(List.of(1L, 1L, 1L, 1L, 3L, 3L, 3L, 3L), lines);
        assertEquals(List.of(1.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 2.0), elapsed);
        assertEquals(new Verdict.Pending(3, 1, 3, Deadline.Unit.OCCURRENCES), c.verdict(0));
    }
}
