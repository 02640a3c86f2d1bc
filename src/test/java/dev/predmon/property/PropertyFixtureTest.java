package dev.predmon.property;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.parse.LogReader;
import dev.predmon.parse.LogRecord;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

/**
 * Every kind on small recordings written in the SCOPE monitor's console format (no time stamps, coloured headers,
 * interleaved INFO lines, a record cut off at the end), read by the log parser: the built-in {@code scope-fetch}
 * properties, and a file of one property of each kind with short deadlines. Lines were read off the fixtures.
 */
class PropertyFixtureTest {

    private static final Path DIR = Path.of("src/test/resources/property");

    /** Each property's id to its verdict at the end of {@code fixture}. */
    private static Map<String, Verdict> verdicts(Abstraction a, String fixture) throws Exception {
        PropertyChecker c = new PropertyChecker(a.properties(), (i, p, v) -> { });
        List<LogRecord> records = new ArrayList<>();
        LogReader.read(DIR.resolve(fixture), records::add, problem -> { });
        records.forEach(c::accept);
        Map<String, Verdict> byId = new LinkedHashMap<>();
        c.verdicts().forEach(pv -> byId.put(pv.property().id(), pv.verdict()));
        return byId;
    }

    private static Abstraction scopeFetch() {
        return AbstractionFiles.builtin("scope-fetch").orElseThrow();
    }

    private static Verdict.Violated violated(Verdict v) {
        return assertInstanceOf(Verdict.Violated.class, v);
    }

    @Test
    void anAbortViolatesNoAbortWhileTheNavigationIsStillOwed() throws Exception {
        Map<String, Verdict> v = verdicts(scopeFetch(), "navigation-aborts.txt");
        assertEquals(157, violated(v.get("no-abort")).line(), "the getStatus reply 3");
        assertEquals(new Verdict.Pending(24, 1, 401, Deadline.Unit.TICKS), v.get("navigation-in-time"),
                "the goTo at tick 1 is due by tick 401; the log stops at tick 6");
        for (String id : List.of("battery", "charger-in-time")) {
            assertEquals(Verdict.HOLDS, v.get(id), id);
        }
        assertEquals(new Verdict.NoEvidence("no ArmService/closeHand command (its trigger) in the run"),
                v.get("grasp-in-time"), "no grasp was tried: nothing to say of grasping in time");
    }

    @Test
    void theNinthGraspAttemptViolatesGraspInTime() throws Exception {
        Map<String, Verdict> v = verdicts(scopeFetch(), "grasp-fails.txt");
        Verdict.Violated grasp = violated(v.get("grasp-in-time"));
        assertEquals(319, grasp.line(), "the ninth closeHand command");
        assertEquals(Verdict.HOLDS, v.get("battery"));
    }

    @Test
    void aLateTurnToTheChargerAndTheBatteryFloor() throws Exception {
        Map<String, Verdict> v = verdicts(scopeFetch(), "late-charger.txt");
        // 29.9 at line 101 (tick 3) while heading to the kitchen: due by tick 13, tick 14 is line 472
        assertEquals(472, violated(v.get("charger-in-time")).line());
        Verdict.Violated battery = violated(v.get("battery"));
        assertEquals(521, battery.line());
        assertEquals(19.5, battery.value());
        assertEquals(20.1, battery.before());
        // the kitchen navigation was halted at tick 15; the charger's goTo is owed from tick 15
        assertEquals(Verdict.Pending.class, v.get("navigation-in-time").getClass());
        assertEquals(15, ((Verdict.Pending) v.get("navigation-in-time")).since());
        assertEquals(Verdict.HOLDS, v.get("no-abort"));
    }

    /** One property of each kind with short deadlines, on a navigation that does not arrive. */
    @Test
    void everyKindOnAStuckNavigation() throws Exception {
        String properties = """
                [ { "id": "status-after-goto", "name": "no status before a goTo", "kind": "precedence",
                    "first": { "kind": "command", "protocol": "GoTo", "command": "goTo" },
                    "then": { "kind": "command", "protocol": "GoTo", "command": "getStatus" } },
                  { "id": "full", "name": "level at most 100", "kind": "bound", "ceiling": 100,
                    "value": { "protocol": "BatteryReader", "command": "level" } },
                  { "id": "started", "name": "a navigation has started", "kind": "absence",
                    "scope": { "from": { "kind": "command", "protocol": "GoTo", "command": "goTo" },
                               "until": { "kind": "command", "protocol": "GoTo", "command": "halt" } },
                    "event": { "kind": "reply", "protocol": "GoTo", "command": "getStatus", "reply": "0" } },
                  { "id": "nav-5", "name": "a navigation ends within 5 ticks", "kind": "response",
                    "trigger": { "kind": "command", "protocol": "GoTo", "command": "goTo" },
                    "response": [ { "kind": "reply", "protocol": "GoTo", "command": "getStatus", "reply": "2" },
                                  { "kind": "command", "protocol": "GoTo", "command": "halt" } ],
                    "within": { "ticks": 5 } },
                  { "id": "nav-20", "name": "a navigation ends within 20 ticks", "kind": "response",
                    "trigger": { "kind": "command", "protocol": "GoTo", "command": "goTo" },
                    "response": { "kind": "command", "protocol": "GoTo", "command": "halt" },
                    "within": { "ticks": 20 } } ]""";
        ObjectMapper json = new ObjectMapper();
        ObjectNode file = (ObjectNode) json.readTree(AbstractionFiles.builtinJson("scope-fetch").orElseThrow());
        file.set("properties", json.readTree(properties));
        Map<String, Verdict> v = verdicts(AbstractionFiles.fromJson("stuck.json", json.writeValueAsString(file)),
                "navigation-stuck.txt");
        assertEquals("GoTo/getStatus command before any GoTo/goTo command",
                violated(v.get("status-after-goto")).what());
        assertEquals(24, violated(v.get("status-after-goto")).line());
        assertEquals(17, violated(v.get("full")).line(), "100.5");
        // the NOT_STARTED at line 31 comes before any goTo; the one at 318 inside the goTo user's segment
        assertEquals(318, violated(v.get("started")).line());
        // goTo kitchen at tick 2 (line 45), due by tick 7: tick 8 is line 234, before the halt at 269
        assertEquals(234, violated(v.get("nav-5")).line());
        // goTo kitchen halted in time; goTo user at tick 9 (line 290) owed when the log stops, cut mid-record
        assertEquals(new Verdict.Pending(290, 9, 29, Deadline.Unit.TICKS), v.get("nav-20"));
    }
}
