package dev.predmon.property;

import dev.predmon.parse.RecordKind;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Set;

import static dev.predmon.property.PropertyCheckerTest.command;
import static dev.predmon.property.PropertyCheckerTest.event;
import static dev.predmon.property.PropertyCheckerTest.reply;
import static org.junit.jupiter.api.Assertions.assertEquals;

/** The names of properties that no log holds, each at its key with the nearest names that occur. */
class UnseenNamesTest {

    /** A navigation to the kitchen that succeeds, a battery reading, a grasp that fails. */
    private static Vocabulary seen() {
        Vocabulary v = new Vocabulary();
        new Trace().tick().level(60).goTo("kitchen").status("kitchen", 1).status("kitchen", 2).closeHand()
                .hasGrasped(false).records().forEach(v::accept);
        return v;
    }

    private static List<String> problems(Property... properties) {
        return UnseenNames.check(List.of(properties), seen()).stream().map(UnseenNames.Problem::describe).toList();
    }

    private static Response grasp(String attempt, String success) {
        return new Response("grasp", "a grasp succeeds within 8 attempts", null, Scope.GLOBAL,
                event(command("ArmService", attempt)), null, event(reply("ArmService", "hasGrasped", success)), null,
                new Deadline(8, Deadline.Unit.OCCURRENCES, event(command("ArmService", attempt))));
    }

    @Test
    void namesSpeltRightAreNoProblem() {
        assertEquals(List.of(), problems(new Bound("battery", "level >= 20", null, new ValueReader("BatteryReader",
                "level", "/BatteryComponent", ""), 20), grasp("closeHand", "0")));
    }

    /** A misspelt command used twice in one property (its trigger and the event it counts) is one line. */
    @Test
    void aMisspeltCommandIsOneLineAtItsFirstKey() {
        assertEquals(List.of("properties[0].trigger.command (grasp): 'closehand' occurs in no log (nearest that "
                + "occur: closeHand)"), problems(grasp("closehand", "0")));
    }

    /** A response's reply that never came is named, with the replies that did (no grasp succeeded in these logs). */
    @Test
    void aReplyThatNeverCameIsNamedWithThoseThatDid() {
        assertEquals(List.of("properties[0].response.reply (grasp): '1' occurs in no log (those that occur: 0)"),
                problems(grasp("closeHand", "1")));
    }

    /** An absence's value that never came is the absence holding; its misspelt command is a typo. */
    @Test
    void anAbsenceIsCheckedToItsMessage() {
        Absence noAbort = new Absence("no-abort", "navigation never aborts", null, Scope.GLOBAL,
                event(reply("GoTo", "getStatus", "3")));
        assertEquals(List.of(), problems(noAbort), "no getStatus replied 3: that is the property holding");
        Absence typo = new Absence("no-abort", "navigation never aborts", null, Scope.GLOBAL,
                event(reply("GoTo", "getStatsu", "3")));
        assertEquals(List.of("properties[0].event.command (no-abort): 'getStatsu' occurs in no log (nearest that "
                + "occur: getStatus)"), problems(typo));
    }

    /**
     * Of alternatives, one whose names occur but that never came is no problem (the event came as the other); a
     * misspelt one is, at its index.
     */
    @Test
    void alternativesAreCheckedOneByOneAndNamedByTheirIndex() {
        Response ends = new Response("nav", "a navigation ends in time", null, Scope.GLOBAL,
                event(command("GoTo", "goTo")), null, event(reply("GoTo", "getStatus", "4"), reply("GoTo",
                "getStatus", "2")), null, new Deadline(400, Deadline.Unit.TICKS, null));
        assertEquals(List.of(), problems(ends), "getStatus never replied 4, but replied 2");
        Response typo = new Response("nav", "a navigation ends in time", null, Scope.GLOBAL,
                event(command("GoTo", "goTo")), null, event(reply("GoTo", "getStatus", "4"), reply("GoTo",
                "getStatsu", "2")), null, new Deadline(400, Deadline.Unit.TICKS, null));
        assertEquals(List.of("properties[0].response[1].command (nav): 'getStatsu' occurs in no log (nearest that "
                + "occur: getStatus)"), problems(typo));
        Response never = new Response("nav", "a navigation ends in time", null, Scope.GLOBAL,
                event(command("GoTo", "goTo")), null, event(reply("GoTo", "getStatus", "4"), reply("GoTo",
                "getStatus", "5")), null, new Deadline(400, Deadline.Unit.TICKS, null));
        assertEquals(List.of("properties[0].response (nav): no record is any of GoTo/getStatus reply 4 or "
                + "GoTo/getStatus reply 5, though each name occurs"), problems(never));
    }

    @Test
    void aPortIsMatchedAsAPatternAndNamedWithTheNearestPort() {
        Bound typo = new Bound("battery", "level >= 20", null, new ValueReader("BatteryReader", "level", "",
                "/BatteryReaderBatteryLevelClinet"), 20);
        assertEquals(List.of("properties[0].value.to (battery): '/BatteryReaderBatteryLevelClinet' occurs in no log "
                + "(nearest that occur: /BatteryReaderBatteryLevelClient)"), problems(typo));
        Absence anyClient = new Absence("x", "x", null, Scope.GLOBAL, event(new RecordMatch(RecordKind.COMMAND,
                "GoTo", "goTo", "/GoToGoToClient/*", null, null, null)));
        assertEquals(List.of(), problems(anyClient), "the pattern matches /GoToGoToClient/kitchen");
    }

    /** Names that each occur, but never in one record; a value that is never a number. */
    @Test
    void namesThatNeverComeTogetherAndAValueThatIsNoNumber() {
        Precedence p = new Precedence("p", "p", null, Scope.GLOBAL, event(new RecordMatch(RecordKind.REPLY,
                "ArmService", "level", null, null, null, null)), event(command("GoTo", "goTo")));
        assertEquals(List.of("properties[0].first (p): no record matches ArmService/level reply: each name occurs, "
                + "never together"), problems(p));
        Bound words = new Bound("b", "b", null, new ValueReader("ArmService", "hasGrasped", "", ""), 0);
        assertEquals(List.of(), problems(words), "0 is a number");
        Bound status = new Bound("s", "s", null, new ValueReader("GoTo", "goTo", "", ""), 0);
        assertEquals(List.of("properties[0].value (s): no reply of GoTo/goTo reply is a number (replies that occur: "
                + "kitchen)"), problems(status));
    }

    @Test
    void theNearestNamesAreWithinAThirdOfTheLengthNearestFirst() {
        assertEquals(List.of("getStatus", "getState"), UnseenNames.nearest("getStatsu", Set.of("getState",
                "getStatus", "goTo", "halt")));
        assertEquals(List.of(), UnseenNames.nearest("emergencyStop", Set.of("goTo", "halt", "getStatus")));
    }
}
