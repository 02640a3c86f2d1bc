package dev.predmon.abstraction.file;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.AbstractionException;
import dev.predmon.property.Bound;
import dev.predmon.property.Deadline;
import dev.predmon.property.Property;
import dev.predmon.property.Response;
import dev.predmon.ros2.TopicRule;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The {@code ros2} section of an abstraction file, and the built-in {@code nav2}. */
class Ros2SectionTest {

    private static final String RULES = """
            "rules": [ { "protocol": "battery", "command": "percentage", "input": "battery_i",
                         "replies": [ { "range": { "below": 20 }, "symbol": "o_low" },
                                      { "range": { "atLeast": 20 }, "symbol": "o_ok" } ] } ]""";

    private static String file(String ros2) {
        return "{ \"name\": \"mine\",\n  \"ros2\": " + ros2 + ",\n" + RULES + " }";
    }

    private static String error(String ros2) {
        return assertThrows(AbstractionException.class, () -> AbstractionFiles.fromJson("mine.json", file(ros2)))
                .getMessage();
    }

    @Test
    void aRuleReadsWithItsDefaults() throws AbstractionException {
        Abstraction a = AbstractionFiles.fromJson("mine.json", file("""
                [ { "topic": "/battery_state", "field": "percentage", "protocol": "battery", "command": "percentage",
                    "scale": "fraction" } ]"""));
        assertEquals(List.of(new TopicRule("/battery_state", null, "percentage", null, "battery", "percentage",
                TopicRule.Scale.FRACTION, null, null, false)), a.topicRules());
        assertTrue(a.canonicalJson().contains("\"ros2\":[{\"command\":\"percentage\""), a.canonicalJson());
        Abstraction again = AbstractionFiles.fromJson("again.json", a.canonicalJson());
        assertEquals(a.topicRules(), again.topicRules(), "the canonical form reads back to itself");
        assertEquals(a.fingerprint(), again.fingerprint());
    }

    @Test
    void theSectionIsPartOfTheFingerprintAndAFileWithoutOneKeepsItsOwn() throws AbstractionException {
        Abstraction fraction = AbstractionFiles.fromJson("a.json", file("""
                [ { "topic": "/b", "field": "p", "protocol": "battery", "command": "percentage", "scale": "fraction" } ]"""));
        Abstraction percent = AbstractionFiles.fromJson("b.json", file("""
                [ { "topic": "/b", "field": "p", "protocol": "battery", "command": "percentage", "scale": "percent" } ]"""));
        Abstraction none = AbstractionFiles.fromJson("c.json", "{ \"name\": \"mine\",\n" + RULES + " }");
        assertNotEquals(fraction.fingerprint(), percent.fingerprint(), "another scale gives other traces");
        assertNotEquals(fraction.fingerprint(), none.fingerprint());
        assertTrue(none.topicRules().isEmpty());
    }

    @Test
    void eachMistakeIsOneLineWithItsPlace() {
        assertEquals("mine.json:2:3: ros2: expected a non-empty list of topic rules, such as {\"topic\":"
                + " \"/battery_state\", \"field\": \"percentage\", \"protocol\": \"battery\", \"command\":"
                + " \"percentage\", \"scale\": \"auto\"}", error("[]"));
        assertEquals("mine.json:2:12: ros2[0]: missing required key 'field'",
                error("[{\"topic\": \"/b\", \"protocol\": \"p\", \"command\": \"c\"}]"));
        assertEquals("mine.json:2:13: ros2[0].topic: a topic starts with / (or * for any characters), got 'b'",
                error("[{\"topic\": \"b\", \"field\": \"x\", \"protocol\": \"p\", \"command\": \"c\"}]"));
        assertTrue(error("[{\"topic\": \"/b\", \"field\": \"a[].b[].c\", \"protocol\": \"p\", \"command\": \"c\"}]")
                .contains("ros2[0].field: 'a[].b[].c' has more than one []"));
        assertTrue(error("[{\"topic\": \"/b\", \"field\": \"a[].s\", \"key\": \"name\", \"protocol\": \"p\","
                + " \"command\": \"c\"}]").contains("ros2[0].key: the key must go through the same list as the field"
                + " (a[]), got 'name'"));
        assertTrue(error("[{\"topic\": \"/b\", \"field\": \"x\", \"protocol\": \"p\", \"command\": \"c\","
                + " \"scale\": \"tenths\"}]").contains("ros2[0].scale: scale 'tenths' is not one of as-is, fraction,"
                + " percent, auto"));
        assertTrue(error("[{\"topic\": \"/b\", \"field\": \"x\", \"protocol\": \"p\", \"command\": \"c\","
                + " \"scale\": \"auto\", \"names\": {\"1\": \"on\"}}]").contains("ros2[0].names: a value rule"));
        assertTrue(error("[{\"topic\": \"/b\", \"field\": \"x\", \"protocol\": \"p q\", \"command\": \"c\"}]")
                .contains("ros2[0].protocol: 'protocol' must be one word"));
        assertTrue(error("[{\"topic\": \"/b\", \"field\": \"x\", \"protocol\": \"p\", \"command\": \"c\","
                + " \"colour\": 1}]").contains("ros2[0].colour: unknown key 'colour'"));
    }

    @Test
    void nav2MapsTheStandardTopicsAndCarriesItsFourProperties() {
        Abstraction nav2 = AbstractionFiles.builtin("nav2").orElseThrow();
        assertEquals(List.of("/battery_state", "/navigate_to_pose/_action/status", "/dock_robot/_action/status",
                "/behavior_tree_log", "/rosout", "/diagnostics"), nav2.topicRules().stream().map(TopicRule::topic)
                .toList());
        assertEquals(List.of("battery", "no-abort", "navigation-in-time", "dock-in-time"),
                nav2.properties().stream().map(Property::id).toList());
        Bound battery = nav2.safety().orElseThrow();
        assertEquals(20.0, battery.floor());
        assertEquals(new Deadline(600, Deadline.Unit.SECONDS, null), ((Response) nav2.properties().get(2)).within());
        assertEquals(new Deadline(30, Deadline.Unit.SECONDS, null), ((Response) nav2.properties().get(3)).within());
        assertEquals(TopicRule.Scale.AUTO, nav2.topicRules().get(0).scale());
    }
}
