package dev.predmon.abstraction.file;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.AbstractionException;
import dev.predmon.property.Absence;
import dev.predmon.property.Bound;
import dev.predmon.property.Deadline;
import dev.predmon.property.Property;
import dev.predmon.property.Response;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The {@code properties} list of an abstraction file: read, written back, and refused with the file and line. */
class PropertyFileTest {

    private static final String RULES = "\"rules\": [{\"protocol\": \"B\", \"command\": \"level\", \"input\": \"level_i\","
            + " \"replies\": [{\"any\": true, \"symbol\": \"o_level\"}]}]";

    @TempDir
    Path dir;

    private static String file(String properties) {
        return "{\"name\": \"mine\",\n" + RULES + ",\n\"properties\": " + properties + "\n}";
    }

    private static final String TWO = """
            [ { "id": "low", "name": "level >= 20", "kind": "bound", "action": "plug the robot in",
                "value": { "protocol": "B", "command": "level" }, "floor": 20 },
              { "id": "no-abort", "name": "never aborts", "kind": "absence",
                "event": [ { "kind": "reply", "command": "getStatus", "reply": "3" },
                           { "kind": "reply", "command": "getStatus", "reply": ["4", "5"] } ] } ]""";

    @Test
    void aListOfPropertiesIsReadInOrderAndWrittenBackToItself() throws Exception {
        Abstraction a = AbstractionFiles.fromJson("two.json", file(TWO));
        List<Property> p = a.properties();
        assertEquals(List.of("low", "no-abort"), p.stream().map(Property::id).toList());
        Bound low = assertInstanceOf(Bound.class, p.get(0));
        assertEquals(20.0, low.floor());
        assertEquals("plug the robot in", low.action());
        assertEquals(low, a.safety().orElseThrow(), "the first bound with a floor is the forecast's");
        assertEquals(2, assertInstanceOf(Absence.class, p.get(1)).event().alternatives().size());
        Abstraction again = AbstractionFiles.fromJson("again.json", a.canonicalJson());
        assertEquals(a.canonicalJson(), again.canonicalJson());
        assertEquals(a.properties(), again.properties());
        assertEquals(a.fingerprint(), again.fingerprint());
    }

    @Test
    void onlyTheForecastPropertyAndNoActionChangesTheFingerprint() throws Exception {
        String one = """
                [ { "id": "low", "name": "level >= 20", "kind": "bound",
                    "value": { "protocol": "B", "command": "level" }, "floor": 20 } ]""";
        Abstraction a = AbstractionFiles.fromJson("a.json", file(one));
        assertEquals(a.fingerprint(), AbstractionFiles.fromJson("b.json", file(TWO)).fingerprint(),
                "another property and an action change no learned model");
        assertTrue(!a.fingerprint().equals(AbstractionFiles.fromJson("c.json", file(one.replace("20", "25")))
                .fingerprint()), "the forecast's floor labels the runs");
        // the older form of the same property has the same fingerprint: models learned with it stay valid
        Abstraction older = AbstractionFiles.fromJson("d.json", "{\"name\": \"mine\",\n" + RULES
                + ",\n\"safety\": {\"name\": \"level >= 20\", \"protocol\": \"B\", \"command\": \"level\", \"below\": 20}}");
        assertEquals(a.fingerprint(), older.fingerprint());
        Bound safety = assertInstanceOf(Bound.class, older.properties().get(0));
        assertEquals("safety", safety.id());
        assertEquals(20.0, safety.floor());
    }

    @Test
    void theBuiltInsCarryTheSystemsProperties() {
        for (String name : List.of("thesis", "scope-fetch")) { // the R1 system's built-ins
            Abstraction a = AbstractionFiles.builtin(name).orElseThrow();
            assertEquals(List.of("battery", "charger-in-time", "no-abort", "navigation-in-time", "grasp-in-time"),
                    a.properties().stream().map(Property::id).toList(), name);
            Response nav = (Response) a.properties().get(3);
            assertEquals(new Deadline(400, Deadline.Unit.TICKS, null), nav.within());
            assertEquals(Response.Per.ARGUMENT, nav.per(), "one navigation per destination: a preempting goTo owes its"
                    + " own end");
            Response grasp = (Response) a.properties().get(4);
            assertEquals(8.0, grasp.within().amount());
            assertEquals(Deadline.Unit.OCCURRENCES, grasp.within().unit());
        }
    }

    private String refused(String properties) throws Exception {
        Path f = Files.writeString(dir.resolve("bad.json"), file(properties));
        AbstractionException e = assertThrows(AbstractionException.class, () -> AbstractionFiles.load(f));
        assertTrue(e.getMessage().startsWith(f + ":"), e.getMessage());
        assertEquals(-1, e.getMessage().indexOf('\n'), "one line: " + e.getMessage());
        return e.getMessage().substring(f.toString().length());
    }

    @Test
    void aBadPropertyIsOneLineWithItsLineAndWhatWasExpected() throws Exception {
        assertEquals(":3:1: properties: expected a list of properties, each an object with id, name and kind",
                refused("{\"id\": \"x\"}"));
        assertTrue(refused("[{\"id\": \"x\", \"name\": \"x\", \"kind\": \"eventually\"}]").matches(":3:\\d+:"
                + " properties\\[0]\\.kind: kind 'eventually' is not one of \\[absence, bound, precedence, response]"));
        String twice = refused(TWO.replace("no-abort", "low"));
        assertTrue(twice.matches(":5:\\d+: properties\\[1]\\.id: id 'low' is also the id of properties\\[0]; each"
                + " property needs its own"), twice);
        assertTrue(refused("[{\"id\": \"Bad Id\", \"name\": \"x\", \"kind\": \"absence\", \"event\": {\"command\": \"c\"}}]")
                .contains("properties[0].id: id 'Bad Id' must be 1 to 40 of [a-z0-9_-]"));
        String within = refused("""
                [ { "id": "n", "name": "n", "kind": "response", "trigger": { "command": "goTo" },
                    "response": { "command": "halt" }, "within": { "minutes": 3 } } ]""");
        assertTrue(within.matches(":4:\\d+: properties\\[0]\\.within\\.minutes: unknown key 'minutes' \\(allowed: occurrences,"
                + " of, seconds, ticks\\)"), within);
        assertTrue(refused("[{\"id\": \"b\", \"name\": \"b\", \"kind\": \"bound\", \"value\": {\"protocol\": \"B\","
                + " \"command\": \"level\"}}]").endsWith("properties[0]: a bound needs a 'floor' (the least value that"
                + " holds) or a 'ceiling' (the greatest)"));
        String per = refused("""
                [ { "id": "n", "name": "n", "kind": "response", "trigger": { "command": "goTo" },
                    "response": { "command": "halt" }, "per": "destination", "within": { "ticks": 3 } } ]""");
        assertTrue(per.endsWith("properties[0].per: expected \"client\" (the client's port) or \"argument\" (the"
                + " first argument), got \"destination\""), per);
        String perCondition = refused("""
                [ { "id": "n", "name": "n", "kind": "response", "trigger": { "value": { "protocol": "B", "command": "level" },
                    "below": 30 }, "response": { "command": "goTo" }, "per": "client", "within": { "ticks": 3 } } ]""");
        assertTrue(perCondition.contains("'per' tells the instances of a trigger event apart"), perCondition);
        assertTrue(refused("[{\"id\": \"e\", \"name\": \"e\", \"kind\": \"absence\", \"event\": {}}]")
                .contains("properties[0].event: an event needs at least one of"));
    }

    @Test
    void theOlderSafetyObjectBesideAListIsRefused() throws Exception {
        Path f = Files.writeString(dir.resolve("both.json"), "{\"name\": \"mine\",\n" + RULES + ",\n\"properties\": "
                + TWO + ",\n\"safety\": {\"name\": \"s\", \"protocol\": \"B\", \"command\": \"level\", \"below\": 20}}");
        AbstractionException e = assertThrows(AbstractionException.class, () -> AbstractionFiles.load(f));
        assertTrue(e.getMessage().matches(".*both\\.json:8:\\d+: safety: 'safety' is the older form of one bound"
                + " property: give it in 'properties' instead, with an id"), e.getMessage());
    }
}
