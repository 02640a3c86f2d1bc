package dev.predmon.property;

import dev.predmon.parse.RecordKind;
import org.junit.jupiter.api.Test;

import java.util.List;

import static dev.predmon.property.PropertyCheckerTest.command;
import static dev.predmon.property.PropertyCheckerTest.event;
import static dev.predmon.property.PropertyCheckerTest.reply;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

/**
 * No verdict without evidence: a property none of whose records occurred in the run (in its scope) reads
 * "no evidence", never "holds", kind by kind; a misspelt name therefore gives no evidence on every run.
 */
class EvidenceTest {

    private static final ValueReader LEVEL = new ValueReader("BatteryReader", "level", "/BatteryComponent",
            "/BatteryReaderBatteryLevelClient");

    /** A run whose battery falls to 0 after a navigation that aborts once, with a grasp that succeeds. */
    private static Trace drained() {
        return new Trace().tick().level(60).goTo("kitchen").status("kitchen", 1).tick().level(30).closeHand()
                .hasGrasped(true).tick().level(0).status("kitchen", 2);
    }

    private static Verdict verdict(Property p, Trace run) {
        return Trace.check(List.of(p), run).verdict(0);
    }

    @Test
    void aFloorOnAMisspeltCommandHasNoEvidenceOnARunWhoseBatteryReachesZero() {
        Bound typo = new Bound("battery", "level >= 50", null,
                new ValueReader("BatteryReader", "levle", "/BatteryComponent", "/BatteryReaderBatteryLevelClient"), 50);
        Verdict v = verdict(typo, drained());
        assertEquals(new Verdict.NoEvidence("no reading of BatteryReader/levle from /BatteryComponent to "
                + "/BatteryReaderBatteryLevelClient in the run"), v);
        assertEquals("no-evidence", v.id());
        assertEquals("violated", verdict(new Bound("battery", "level >= 50", null, LEVEL, 50), drained()).id(),
                "spelt right, the same floor is violated");
    }

    @Test
    void aFloorOnAMisspeltPortHasNoEvidence() {
        Bound typo = new Bound("battery", "level >= 50", null,
                new ValueReader("BatteryReader", "level", "", "/BatteryReaderBatteryLevelClinet"), 50);
        assertEquals("no reading of BatteryReader/level to /BatteryReaderBatteryLevelClinet in the run",
                assertInstanceOf(Verdict.NoEvidence.class, verdict(typo, drained())).why());
    }

    @Test
    void aBoundHoldsOnceItsValueWasReadAndNotBefore() {
        Bound floor = new Bound("battery", "level >= 20", null, LEVEL, 20);
        Trace run = new Trace().tick().goTo("kitchen");
        assertEquals("no-evidence", verdict(floor, run).id(), "no reading yet");
        assertEquals(Verdict.HOLDS, verdict(floor, run.level(80)));
    }

    /**
     * An absence holds when the message its event is a value of came without that value: the getStatus replies of
     * a navigation that never aborted. A run without any getStatus reply says nothing of aborts, and neither does a
     * misspelt command.
     */
    @Test
    void anAbsenceHoldsWhenItsMessageCameWithoutTheForbiddenValue() {
        Absence noAbort = new Absence("no-abort", "navigation never aborts", null, Scope.GLOBAL,
                event(reply("GoTo", "getStatus", "3")));
        assertEquals(Verdict.HOLDS, verdict(noAbort, drained()), "getStatus replied 1 and 2, never 3");
        assertEquals(new Verdict.NoEvidence("no GoTo/getStatus reply in the run"),
                verdict(noAbort, new Trace().tick().level(50).closeHand()), "no navigation at all");
        Absence typo = new Absence("no-abort", "navigation never aborts", null, Scope.GLOBAL,
                event(reply("GoTo", "getStatsu", "3")));
        assertEquals(new Verdict.NoEvidence("no GoTo/getStatsu reply in the run"), verdict(typo, drained()));
        assertEquals("violated", verdict(noAbort, drained().status("kitchen", 3)).id());
    }

    /**
     * An absence of a message that names no value (a command that must never be called) holds once its component
     * was heard from: that the command never came is the property holding, even when no log ever holds it.
     */
    @Test
    void anAbsenceOfAValuelessMessageHoldsOnceItsComponentWasHeardFrom() {
        Absence neverHalt = new Absence("no-halt", "the navigation is never halted", null, Scope.GLOBAL,
                event(command("GoTo", "halt")));
        assertEquals(Verdict.HOLDS, verdict(neverHalt, drained()), "GoTo was busy, and never halted");
        assertEquals(new Verdict.NoEvidence("no GoTo/any message in the run"),
                verdict(neverHalt, new Trace().tick().level(50)));
        assertEquals("violated", verdict(neverHalt, drained().halt("kitchen")).id());
    }

    @Test
    void aResponseWhoseTriggerNeverCameHasNoEvidence() {
        Deadline eight = new Deadline(8, Deadline.Unit.OCCURRENCES, event(command("ArmService", "closehand")));
        Response typo = new Response("grasp-in-time", "a grasp succeeds within 8 attempts", null, Scope.GLOBAL,
                event(command("ArmService", "closehand")), null, event(reply("ArmService", "hasGrasped", "1")), null,
                eight);
        assertEquals(new Verdict.NoEvidence("no ArmService/closehand command (its trigger) in the run"),
                verdict(typo, drained()));
        Response right = new Response("grasp-in-time", "a grasp succeeds within 8 attempts", null, Scope.GLOBAL,
                event(command("ArmService", "closeHand")), null, event(reply("ArmService", "hasGrasped", "1")), null,
                new Deadline(8, Deadline.Unit.OCCURRENCES, event(command("ArmService", "closeHand"))));
        assertEquals(Verdict.HOLDS, verdict(right, drained()), "tried once, grasped");
    }

    /** A trigger that is a condition has evidence from any reading of its value, true or not. */
    @Test
    void aConditionTriggerHasEvidenceFromAnyReadingOfItsValue() {
        Response charger = new Response("charger", "to the charger in time", null, Scope.GLOBAL, null,
                new Condition(LEVEL, Condition.Op.BELOW, 30), event(command("GoTo", "goTo")), null,
                new Deadline(2, Deadline.Unit.TICKS, null));
        assertEquals(Verdict.HOLDS, verdict(charger, new Trace().tick().level(80).tick()), "80 is not below 30");
        assertEquals(new Verdict.NoEvidence("no reading of BatteryReader/level from /BatteryComponent to "
                        + "/BatteryReaderBatteryLevelClient (its trigger's value) in the run"),
                verdict(charger, new Trace().tick().goTo("kitchen").tick()));
    }

    @Test
    void aPrecedenceHasEvidenceFromItsThenMessage() {
        Precedence p = new Precedence("goto-after-level", "a navigation only after a battery reading", null,
                Scope.GLOBAL, event(new RecordMatch(RecordKind.REPLY, "BatteryReader", "level", null, null, null,
                null)), event(command("GoTo", "goTo")));
        assertEquals(Verdict.HOLDS, verdict(p, drained()));
        assertEquals(new Verdict.NoEvidence("no GoTo/any message in the run"),
                verdict(p, new Trace().tick().level(40)), "no navigation: nothing came before or after anything");
    }

    /** A scoped property needs its evidence within its scope; a scope that never opened is said so. */
    @Test
    void aScopedPropertyNeedsEvidenceWithinItsScope() {
        Scope navigating = new Scope(event(command("GoTo", "goTo")), event(command("GoTo", "halt")));
        Bound floor = new Bound("battery", "level >= 20 while navigating", null, navigating, LEVEL, 20,
                Double.POSITIVE_INFINITY);
        assertEquals(new Verdict.NoEvidence("its scope never opened: no GoTo/goTo command"),
                verdict(floor, new Trace().tick().level(10)), "10 outside the scope is no evidence");
        assertEquals(new Verdict.NoEvidence("no reading of BatteryReader/level from /BatteryComponent to "
                        + "/BatteryReaderBatteryLevelClient within its scope"),
                verdict(floor, new Trace().tick().level(50).goTo("kitchen").halt("kitchen").level(50)));
        assertEquals(Verdict.HOLDS, verdict(floor, new Trace().goTo("kitchen").level(50).halt("kitchen")));
    }

    /** Evidence is per run: a new run has none until it shows some. */
    @Test
    void evidenceStartsOverWithEachRun() {
        Bound floor = new Bound("battery", "level >= 20", null, LEVEL, 20);
        PropertyChecker c = new PropertyChecker(List.of(floor), (i, p, v) -> { });
        new Trace().tick().level(80).records().forEach(c::accept);
        assertEquals(Verdict.HOLDS, c.verdict(0));
        c.reset();
        new Trace().tick().goTo("kitchen").records().forEach(c::accept);
        assertEquals("no-evidence", c.verdict(0).id());
    }
}
