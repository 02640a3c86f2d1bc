package dev.predmon.property;

import dev.predmon.parse.RecordKind;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Every kind of property on runs written by hand, with the verdict worked out by hand from the semantics: the line
 * of each violation, what violated it, and the pending obligations of runs that stop.
 */
class PropertyCheckerTest {

    private static final ValueReader LEVEL = new ValueReader("BatteryReader", "level", "/BatteryComponent",
            "/BatteryReaderBatteryLevelClient");

    static RecordMatch command(String protocol, String command) {
        return new RecordMatch(RecordKind.COMMAND, protocol, command, null, null, null, null);
    }

    static RecordMatch reply(String protocol, String command, String... values) {
        return new RecordMatch(RecordKind.REPLY, protocol, command, null, null, null, List.of(values));
    }

    static Event event(RecordMatch... any) {
        return new Event(List.of(any));
    }

    private static final Event GOTO = event(command("GoTo", "goTo"));
    private static final Event ARRIVED = event(reply("GoTo", "getStatus", "2"), command("GoTo", "halt"));

    private static Response navigation(Deadline within) {
        return new Response("nav", "a navigation ends in time", null, Scope.GLOBAL, GOTO, null, ARRIVED, null, within);
    }

    private static Verdict.Violated violated(Verdict v) {
        return assertInstanceOf(Verdict.Violated.class, v);
    }

    @Test
    void aFloorIsViolatedAtTheFirstReadingBelowIt() {
        Bound floor = new Bound("battery", "level >= 20", null, LEVEL, 20);
        Trace run = new Trace().level(25).level(21).level("NaN").level(19.5).level(10);
        Trace.Checked c = Trace.check(List.of(floor), run);
        Verdict.Violated v = violated(c.verdict(0));
        assertEquals(8, v.line(), "the reply of the fourth reading, 19.5");
        assertEquals(19.5, v.value());
        assertEquals(21.0, v.before(), "a reply that is no number reads nothing");
        assertEquals("19.5 below the floor 20", v.what());
        assertEquals(List.of("battery@8"), c.told(), "told once, at the first violation");
        assertEquals(Verdict.HOLDS, Trace.check(List.of(floor), new Trace().level(25).level(20).level(99)).verdict(0),
                "20 itself holds");
    }

    @Test
    void aCeilingIsViolatedAboveIt() {
        Bound ceiling = new Bound("hot", "at most 80", null, Scope.GLOBAL, LEVEL, Double.NEGATIVE_INFINITY, 80);
        assertEquals(Verdict.HOLDS, Trace.check(List.of(ceiling), new Trace().level(79).level(80)).verdict(0));
        Verdict.Violated v = violated(Trace.check(List.of(ceiling), new Trace().level(79).level(80.5)).verdict(0));
        assertEquals(4, v.line());
        assertEquals("80.5 above the ceiling 80", v.what());
        Bound both = new Bound("band", "20 to 80", null, Scope.GLOBAL, LEVEL, 20, 80);
        assertEquals(2, violated(Trace.check(List.of(both), new Trace().level(81)).verdict(0)).line());
        assertEquals(2, violated(Trace.check(List.of(both), new Trace().level(19)).verdict(0)).line());
    }

    @Test
    void anAbsentEventViolatesWhereItHappens() {
        Absence noAbort = new Absence("no-abort", "navigation never aborts", null, Scope.GLOBAL,
                event(reply("GoTo", "getStatus", "3")));
        Trace run = new Trace().goTo("kitchen").status("kitchen", 1).status("kitchen", 3).status("kitchen", 3);
        Trace.Checked c = Trace.check(List.of(noAbort), run);
        Verdict.Violated v = violated(c.verdict(0));
        assertEquals(6, v.line());
        assertEquals("GoTo/getStatus reply 3", v.what());
        assertEquals(List.of("no-abort@6"), c.told());
        assertEquals(Verdict.HOLDS, Trace.check(List.of(noAbort),
                new Trace().goTo("kitchen").status("kitchen", 1).status("kitchen", 2)).verdict(0));
    }

    @Test
    void aResponseByEventWithinTicks() {
        Response nav = navigation(new Deadline(3, Deadline.Unit.TICKS, null));
        // tick 1 (line 1), goTo (2, 3): the trigger at tick 1, due by tick 4
        Trace start = new Trace().tick().goTo("kitchen");
        assertEquals(new Verdict.Pending(2, 1, 4, Deadline.Unit.TICKS), Trace.check(List.of(nav), start).verdict(0));
        Trace inTime = new Trace().tick().goTo("kitchen").ticks(3).halt("kitchen");
        assertEquals(Verdict.HOLDS, Trace.check(List.of(nav), inTime).verdict(0), "halted during tick 4: in time");
        // the fourth tick after the trigger is tick 5, line 7: the deadline passed there, the halt after it is late
        Trace late = new Trace().tick().goTo("kitchen").ticks(4).halt("kitchen");
        Trace.Checked c = Trace.check(List.of(nav), late);
        Verdict.Violated v = violated(c.verdict(0));
        assertEquals(7, v.line());
        assertEquals("no getStatus 2 or halt in 3 ticks since goTo at line 2",
                v.what());
        assertEquals(List.of("nav@7"), c.told());
    }

    @Test
    void theEarliestUnansweredTriggerIsTheOneDue() {
        Response nav = navigation(new Deadline(3, Deadline.Unit.TICKS, null));
        // a second goTo (lines 5, 6) while the first is owed does not move the deadline: tick 4 is line 9
        Trace run = new Trace().tick().goTo("kitchen").tick().goTo("user").ticks(3);
        assertEquals(9, violated(Trace.check(List.of(nav), run).verdict(0)).line());
        // once answered, the next trigger opens a new obligation
        Trace twice = new Trace().tick().goTo("kitchen").tick().halt("kitchen").goTo("user").ticks(3);
        assertEquals(new Verdict.Pending(7, 2, 5, Deadline.Unit.TICKS), Trace.check(List.of(nav), twice).verdict(0));
    }

    private static Response perNavigation(Deadline within) {
        return new Response("nav", "a navigation ends in time", null, Scope.GLOBAL, GOTO, null, ARRIVED, null, within,
                Response.Per.CLIENT);
    }

    @Test
    void aNavigationThatPreemptsAnotherOwesItsOwnEnd() {
        Response nav = perNavigation(new Deadline(3, Deadline.Unit.TICKS, null));
        // tick 1 (line 1), goTo kitchen (2, 3), tick 2 (4), goTo charging_station (5, 6) while the kitchen one is
        // owed, then the halt of the kitchen one (7, 8): the way to the station is still owed, since tick 2, due by
        // tick 5; ticks 3, 4, 5 are lines 9, 10, 11, and tick 6, line 12, is past it
        Trace preempted = new Trace().tick().goTo("kitchen").tick().goTo("charging_station").halt("kitchen").ticks(4);
        Trace.Checked c = Trace.check(List.of(nav), preempted);
        Verdict.Violated v = violated(c.verdict(0));
        assertEquals(12, v.line());
        assertEquals("no getStatus 2 or halt in 3 ticks since goTo at line 5", v.what());
        assertEquals(List.of("nav@12"), c.told());
        // the same with the kitchen one just discharged (its getStatus 2, lines 4 and 5) before the goTo to the
        // station: tick 2 is line 6, the goTo lines 7 and 8, due by tick 5; its getStatus 1 lines 9 and 10, ticks 3
        // to 6 lines 11 to 14
        Trace after = new Trace().tick().goTo("kitchen").status("kitchen", 2).tick().goTo("charging_station")
                .status("charging_station", 1).ticks(4);
        assertEquals(14, violated(Trace.check(List.of(nav), after).verdict(0)).line());
        // without 'per' the halt of the kitchen one answers every goTo before it: the stuck way is never owed
        assertEquals(Verdict.HOLDS, Trace.check(List.of(navigation(new Deadline(3, Deadline.Unit.TICKS, null))),
                preempted).verdict(0), "the uncorrelated property, as the MTL formula reads it");
        // each answered by its own end: both navigations end in time
        Trace both = new Trace().tick().goTo("kitchen").tick().goTo("charging_station").halt("kitchen").tick()
                .status("charging_station", 2).ticks(4);
        assertEquals(Verdict.HOLDS, Trace.check(List.of(nav), both).verdict(0));
    }

    @Test
    void perInstanceTheEarliestUnansweredTriggerIsStillTheOneDue() {
        Response nav = perNavigation(new Deadline(3, Deadline.Unit.TICKS, null));
        // a goTo to the kitchen again (lines 5, 6: a retry) does not move the kitchen's deadline: tick 5 is line 9
        Trace retried = new Trace().tick().goTo("kitchen").tick().goTo("kitchen").ticks(3);
        assertEquals(9, violated(Trace.check(List.of(nav), retried).verdict(0)).line());
        // the obligation pending is the one nearest its deadline: the kitchen's, from line 2 (tick 1, due by 4)
        Trace two = new Trace().tick().goTo("kitchen").tick().goTo("charging_station");
        Trace.Checked c = Trace.check(List.of(nav), two);
        assertEquals(new Verdict.Pending(2, 1, 4, Deadline.Unit.TICKS), c.verdict(0));
        assertEquals(1, c.checker().elapsed(0), "tick 2, one tick after the kitchen's goTo");
        assertEquals(2, c.checker().pendingLine(0));
        // once the kitchen's ends, the station's is the one pending: since tick 2, line 5
        Trace.Checked halted = Trace.check(List.of(nav), new Trace().tick().goTo("kitchen").tick()
                .goTo("charging_station").halt("kitchen").tick());
        assertEquals(new Verdict.Pending(5, 2, 5, Deadline.Unit.TICKS), halted.verdict(0));
        assertEquals(5, halted.checker().pendingLine(0));
        assertEquals(1, halted.checker().elapsed(0));
    }

    @Test
    void aResponseWithinSeconds() {
        Response nav = navigation(new Deadline(60, Deadline.Unit.SECONDS, null));
        Trace inTime = new Trace().at(100).goTo("kitchen").at(159.9).status("kitchen", 1).at(160).halt("kitchen");
        assertEquals(Verdict.HOLDS, Trace.check(List.of(nav), inTime).verdict(0), "at t=160 exactly: in time");
        Trace late = new Trace().at(100).goTo("kitchen").at(160.5).status("kitchen", 1).halt("kitchen");
        assertEquals(3, violated(Trace.check(List.of(nav), late).verdict(0)).line(), "the first record after t=160");
        Trace open = new Trace().at(100).goTo("kitchen").at(150).status("kitchen", 1);
        assertEquals(new Verdict.Pending(1, 100, 160, Deadline.Unit.SECONDS),
                Trace.check(List.of(nav), open).verdict(0));
    }

    @Test
    void aResponseWithinAttempts() {
        Event close = event(command("ArmService", "closeHand"));
        Response grasp = new Response("grasp", "grasped within 2 attempts", null, Scope.GLOBAL, close, null,
                event(reply("ArmService", "hasGrasped", "1", "27503")), null,
                new Deadline(2, Deadline.Unit.OCCURRENCES, close));
        assertEquals(new Verdict.Pending(1, 1, 2, Deadline.Unit.OCCURRENCES),
                Trace.check(List.of(grasp), new Trace().closeHand().hasGrasped(false)).verdict(0));
        Trace second = new Trace().closeHand().hasGrasped(false).closeHand().hasGrasped(true);
        assertEquals(Verdict.HOLDS, Trace.check(List.of(grasp), second).verdict(0));
        // the third attempt, line 9, is one too many
        Trace third = new Trace().closeHand().hasGrasped(false).closeHand().hasGrasped(false).closeHand()
                .hasGrasped(true);
        Verdict.Violated v = violated(Trace.check(List.of(grasp), third).verdict(0));
        assertEquals(9, v.line());
        // after a success the next closeHand is a new grasp's first attempt
        Trace next = new Trace().closeHand().hasGrasped(true).closeHand().hasGrasped(false).closeHand();
        assertEquals(new Verdict.Pending(5, 1, 2, Deadline.Unit.OCCURRENCES),
                Trace.check(List.of(grasp), next).verdict(0));
    }

    /** SCOPE's DestinationMonitor: once the level is below 30, the destination must be the charger within 2 ticks. */
    @Test
    void aResponseToAConditionWithALastingResponse() {
        Response charger = new Response("charger", "to the charger in time", null, Scope.GLOBAL, null,
                new Condition(LEVEL, Condition.Op.BELOW, 30),
                event(new RecordMatch(RecordKind.COMMAND, "GoTo", "goTo", null, null, List.of("charging_station"),
                        null)), GOTO, new Deadline(2, Deadline.Unit.TICKS, null));
        // level 35 (lines 2, 3), level 29 (4, 5): the trigger at line 5, tick 1, due by tick 3
        Trace inTime = new Trace().tick().level(35).level(29).ticks(2).goTo("charging_station");
        assertEquals(Verdict.HOLDS, Trace.check(List.of(charger), inTime).verdict(0));
        Trace late = new Trace().tick().level(35).level(29).ticks(3).goTo("charging_station");
        assertEquals(8, violated(Trace.check(List.of(charger), late).verdict(0)).line(), "tick 4");
        // already heading to the charger when the level falls below 30: nothing is owed
        Trace heading = new Trace().tick().level(35).goTo("charging_station").level(29).level(25).ticks(10);
        assertEquals(Verdict.HOLDS, Trace.check(List.of(charger), heading).verdict(0));
        // a goTo elsewhere while below 30 (line 8, tick 1) owes the charger again, due by tick 3: tick 4 is line 12
        Trace away = new Trace().tick().level(35).goTo("charging_station").level(29).goTo("kitchen").ticks(3);
        Verdict.Violated v = violated(Trace.check(List.of(charger), away).verdict(0));
        assertEquals(12, v.line());
        assertEquals("no goTo charging_station in 2 ticks since BatteryReader/level < 30 at line 8",
                v.what());
    }

    @Test
    void aConditionTriggersWhenItBecomesTrue() {
        Response charger = new Response("charger", "to the charger in time", null, Scope.GLOBAL, null,
                new Condition(LEVEL, Condition.Op.BELOW, 30),
                event(new RecordMatch(RecordKind.COMMAND, "GoTo", "goTo", null, null, List.of("charging_station"),
                        null)), null, new Deadline(2, Deadline.Unit.TICKS, null));
        // answered once; the level staying below 30 owes nothing more
        Trace run = new Trace().tick().level(29).goTo("charging_station").level(28).ticks(5).level(27).ticks(5);
        assertEquals(Verdict.HOLDS, Trace.check(List.of(charger), run).verdict(0));
        // above 30 again (line 7), then below (line 9): owed again from tick 1
        Trace again = new Trace().tick().level(29).goTo("charging_station").level(31).level(29);
        assertEquals(new Verdict.Pending(9, 1, 3, Deadline.Unit.TICKS), Trace.check(List.of(charger), again)
                .verdict(0));
    }

    @Test
    void precedenceIsViolatedByTheLaterEventComingFirst() {
        Precedence p = new Precedence("goto-first", "no status before a goTo", null, Scope.GLOBAL, GOTO,
                event(command("GoTo", "getStatus")));
        Verdict.Violated v = violated(Trace.check(List.of(p), new Trace().status("kitchen", 1).goTo("kitchen"))
                .verdict(0));
        assertEquals(1, v.line());
        assertEquals("GoTo/getStatus command before any GoTo/goTo command", v.what());
        assertEquals(Verdict.HOLDS, Trace.check(List.of(p), new Trace().goTo("kitchen").status("kitchen", 1))
                .verdict(0));
    }

    @Test
    void aScopeChecksOnlyBetweenItsEvents() {
        Scope navigating = new Scope(GOTO, event(command("GoTo", "halt")));
        Absence noAbort = new Absence("no-abort", "never aborts while navigating", null, navigating,
                event(reply("GoTo", "getStatus", "3")));
        assertEquals(Verdict.HOLDS, Trace.check(List.of(noAbort),
                new Trace().status("kitchen", 3).goTo("kitchen").status("kitchen", 1).halt("kitchen")
                        .status("kitchen", 3)).verdict(0), "both aborts lie outside the scope");
        Verdict.Violated v = violated(Trace.check(List.of(noAbort),
                new Trace().goTo("kitchen").status("kitchen", 1).halt("kitchen").goTo("user").status("user", 3))
                .verdict(0));
        assertEquals(10, v.line(), "in the second segment");
    }

    @Test
    void aResponseOwedWhenItsScopeEndsIsViolatedThereAndPendingWhenTheRunStops() {
        Scope navigating = new Scope(GOTO, event(command("GoTo", "halt")));
        Response arrives = new Response("arrives", "a running navigation succeeds", null, navigating,
                event(reply("GoTo", "getStatus", "1")), null, event(reply("GoTo", "getStatus", "2")), null,
                new Deadline(100, Deadline.Unit.TICKS, null));
        Verdict.Violated v = violated(Trace.check(List.of(arrives),
                new Trace().goTo("kitchen").status("kitchen", 1).halt("kitchen")).verdict(0));
        assertEquals(5, v.line(), "the halt ended the segment with the success owed");
        assertEquals(Verdict.HOLDS, Trace.check(List.of(arrives),
                new Trace().goTo("kitchen").status("kitchen", 1).status("kitchen", 2).halt("kitchen")).verdict(0));
        assertEquals(new Verdict.Pending(4, 0, 100, Deadline.Unit.TICKS), Trace.check(List.of(arrives),
                new Trace().goTo("kitchen").status("kitchen", 1)).verdict(0), "the run stopped inside the segment");
    }

    @Test
    void aNewRunStartsEveryPropertyOver() {
        Bound floor = new Bound("battery", "level >= 20", null, LEVEL, 20);
        Response nav = navigation(new Deadline(1, Deadline.Unit.TICKS, null));
        PropertyChecker c = new PropertyChecker(List.of(floor, nav), (i, p, v) -> { });
        new Trace().tick().goTo("kitchen").level(10).ticks(2).records().forEach(c::accept);
        assertInstanceOf(Verdict.Violated.class, c.verdict(0));
        assertInstanceOf(Verdict.Violated.class, c.verdict(1));
        c.reset();
        assertEquals(List.of("no-evidence", "no-evidence"), c.verdicts().stream()
                .map(pv -> pv.verdict().id()).toList(), "a new run has shown nothing yet");
        // ticks count from the new run's start
        new Trace().tick().goTo("kitchen").records().forEach(c::accept);
        assertEquals(new Verdict.Pending(2, 1, 2, Deadline.Unit.TICKS), c.verdict(1));
        assertTrue(Double.isNaN(c.reading(0)), "the last record was no reading");
    }

    /**
     * A value read by a scoped bound and by a condition is read once per record and shared: the condition sees every
     * reading, the bound only those in its scope, and {@code value} (what the forecast follows) every reading whatever
     * the scope, while {@code reading} is the bound's own, NaN outside its scope.
     */
    @Test
    void aValueSharedByAScopedBoundAndAConditionKeepsEachAnswer() {
        Scope navigating = new Scope(GOTO, event(command("GoTo", "halt")));
        Bound floor = new Bound("battery", "level >= 20 while navigating", null, navigating, LEVEL, 20,
                Double.POSITIVE_INFINITY);
        Response charger = new Response("charger", "to the charger in time", null, Scope.GLOBAL, null,
                new Condition(LEVEL, Condition.Op.BELOW, 30),
                event(new RecordMatch(RecordKind.COMMAND, "GoTo", "goTo", null, null, List.of("charging_station"),
                        null)), null, new Deadline(2, Deadline.Unit.TICKS, null));
        PropertyChecker c = new PropertyChecker(List.of(floor, charger), (i, p, v) -> { });
        new Trace().tick().level(15).records().forEach(c::accept);
        assertEquals(15.0, c.value(0), "read outside the bound's scope");
        assertTrue(Double.isNaN(c.reading(0)), "the bound itself did not read it: its scope is closed");
        assertTrue(Double.isNaN(c.value(1)), "a response has no value of its own");
        assertEquals(new Verdict.NoEvidence("its scope never opened: no GoTo/goTo command"), c.verdict(0),
                "15 outside the scope violates nothing, and is no evidence either");
        assertEquals(new Verdict.Pending(3, 1, 3, Deadline.Unit.TICKS), c.verdict(1),
                "the condition read the same 15");
        new Trace().goTo("kitchen").records().forEach(c::accept);
        assertTrue(Double.isNaN(c.value(0)), "a command carries no value");
        c.accept(new Trace().level(12).records().get(1));
        assertEquals(12.0, c.value(0));
        assertEquals(12.0, c.reading(0), "inside the scope the bound reads it too");
        assertEquals("12 below the floor 20", violated(c.verdict(0)).what());
    }
}
