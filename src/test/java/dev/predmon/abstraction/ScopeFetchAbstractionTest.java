package dev.predmon.abstraction;

import dev.predmon.abstraction.file.AbstractionFiles;
import org.junit.jupiter.api.Test;

import static dev.predmon.abstraction.AbstractionTest.command;
import static dev.predmon.abstraction.AbstractionTest.mapped;
import static dev.predmon.abstraction.AbstractionTest.reply;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The built-in {@code scope-fetch} abstraction on messages as the real monitor prints them, and the format
 * extensions it needs: rules keyed on a client port, a warning policy, a run rule.
 */
class ScopeFetchAbstractionTest {

    private static final Abstraction S = AbstractionFiles.builtin("scope-fetch").orElseThrow();

    @Test
    void hasGraspedIsTwoMessagesToldApartByTheClient() {
        assertEquals("isFetched_i", mapped(S, command("/ArmServiceIsFetchedClient", "/ArmComponent", "ArmService",
                "hasGrasped", "")).symbol());
        assertEquals("o_isFetched_false", mapped(S, reply("/ArmComponent", "/ArmServiceIsFetchedClient", "ArmService",
                "hasGrasped", "", "1818845542")).symbol());
        assertEquals("hasGrasped_i", mapped(S, command("/ArmServiceFetchClient", "/ArmComponent", "ArmService",
                "hasGrasped", "")).symbol());
        assertEquals("o_hasGrasped_true", mapped(S, reply("/ArmComponent", "/ArmServiceFetchClient", "ArmService",
                "hasGrasped", "", "1")).symbol());
    }

    @Test
    void goToTakesItsLocationFromTheReplyOrThePortAndPosesAreLeftOut() {
        assertEquals("goTo_us_i", mapped(S, command("/GoToGoToClient/user", "/GoToComponent", "GoTo", "goTo", "")).symbol());
        assertEquals("o_goto_ch", mapped(S, reply("/GoToComponent", "/GoToGoToClient/charging_station", "GoTo", "goTo",
                "", "charging_station")).symbol());
        assertInstanceOf(Classification.Dropped.class, S.classify(reply("/GoToComponent", "/GoToIsAtClient/user",
                "GoTo", "getCurrentPose", "", "-6.000000;0.000000")));
        assertInstanceOf(Classification.Dropped.class, S.classify(command("/IsAtUser/BT_rpc/client",
                "/IsAtUser/BT_rpc/server", "Skill_request", "request_ack", "")));
    }

    @Test
    void bandsFollowTheTreesThresholdAndWarningsAreConfirmed() {
        String level = "/BatteryReaderBatteryLevelClient";
        assertEquals("o_level_high", mapped(S, reply("/BatteryComponent", level, "BatteryReader", "level", "", "64.1")).symbol());
        assertEquals("o_level_medium_two", mapped(S, reply("/BatteryComponent", level, "BatteryReader", "level", "", "29.8")).symbol());
        assertEquals("o_level_medium_one", mapped(S, reply("/BatteryComponent", level, "BatteryReader", "level", "", "20.0")).symbol());
        assertEquals("o_level_low", mapped(S, reply("/BatteryComponent", level, "BatteryReader", "level", "", "19.99")).symbol());
        assertEquals(1, S.confirm());
        assertEquals(0, AbstractionFiles.defaults().confirm());
        assertEquals(RunRule.DEFAULT, S.runs());
    }

    private static String with(String rules) {
        return "{\"name\": \"x\", \"rules\": [" + rules + "]}";
    }

    private static final String HAS_GRASPED = "{\"protocol\": \"ArmService\", \"command\": \"hasGrasped\", %s"
            + "\"input\": \"%s\", \"replies\": [{\"any\": true, \"symbol\": \"o_%s\"}]}";

    @Test
    void aClientRuleShadowedByAnEarlierOneIsRejected() throws Exception {
        String specific = String.format(HAS_GRASPED, "\"client\": \"*IsFetched*\",", "a_i", "a");
        String any = String.format(HAS_GRASPED, "", "b_i", "b");
        AbstractionFiles.fromJson("ok.json", with(specific + "," + any)); // specific first, then the rest: fine
        AbstractionException e = assertThrows(AbstractionException.class,
                () -> AbstractionFiles.fromJson("bad.json", with(any + "," + specific)));
        assertTrue(e.getMessage().contains("would never be used"), e.getMessage());
        AbstractionException twice = assertThrows(AbstractionException.class,
                () -> AbstractionFiles.fromJson("bad.json", with(specific + "," + specific.replace("a_i", "c_i").replace("o_a", "o_c"))));
        assertTrue(twice.getMessage().contains("from client *IsFetched*"), twice.getMessage());
    }

    @Test
    void warningAndRunsAreValidated() {
        String rule = String.format(HAS_GRASPED, "", "a_i", "a");
        AbstractionException confirm = assertThrows(AbstractionException.class, () -> AbstractionFiles.fromJson("w.json",
                "{\"name\": \"x\", \"rules\": [" + rule + "], \"warning\": {\"confirm\": -1}}"));
        assertTrue(confirm.getMessage().contains("warning.confirm: confirm must be at least 0"), confirm.getMessage());
        AbstractionException silence = assertThrows(AbstractionException.class, () -> AbstractionFiles.fromJson("r.json",
                "{\"name\": \"x\", \"rules\": [" + rule + "], \"runs\": {\"silence\": -5}}"));
        assertTrue(silence.getMessage().contains("runs.silence: silence must be"), silence.getMessage());
    }
}
