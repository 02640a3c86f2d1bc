package dev.predmon.abstraction;

import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import dev.predmon.property.Bound;
import dev.predmon.property.Scope;
import dev.predmon.property.UnderWay;
import dev.predmon.property.ValueReader;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The default abstraction against the thesis's Tables 4.1/4.2 and the Section 5.2 bands. */
public class AbstractionTest {

    private static final Abstraction A = AbstractionFiles.defaults();

    public static LogRecord command(String from, String to, String protocol, String command, String arguments) {
        return new LogRecord(1, 0.0, "DEBUG", RecordKind.COMMAND, from, to, protocol, command, arguments, "");
    }

    public static LogRecord reply(String from, String to, String protocol, String command, String arguments, String reply) {
        return new LogRecord(1, 0.0, "DEBUG", RecordKind.REPLY, from, to, protocol, command, arguments, reply);
    }

    public static AbstractEvent mapped(Abstraction a, LogRecord r) {
        Classification c = a.classify(r);
        return assertInstanceOf(Classification.Mapped.class, c, () -> r + " -> " + c).event();
    }

    static String symbol(LogRecord r) {
        return mapped(A, r).symbol();
    }

    /** Table 4.1, row by row: From, To, Protocol, Command, Arguments -> symbol. */
    @ParameterizedTest
    @CsvSource({
            "/GoToGoToClient/kitchen, /GoToComponent, GoTo, goTo, kitchen, goTo_ki_i",
            "/GoToGoToClient/kitchen, /GoToComponent, GoTo, getStatus, kitchen, getStatus_ki_i",
            "/GoToIsAtClient/kitchen, /GoToComponent, GoTo, isAtLocation, kitchen, isAt_ki_i",
            "/GoToGoToClient/kitchen, /GoToComponent, GoTo, halt, kitchen, halt_ki_i",
            "/BatteryReaderBatteryLevelClient, /BatteryComponent, BatteryReader, level, '', level_i",
            "/BatteryReaderBatteryNotChargingClient, /BatteryComponent, BatteryReader, charging_status, '', batteryStatus_i",
            "/GoToGoToClient/charging_station, /GoToComponent, GoTo, goTo, charging_station, goTo_ch_i",
            "/GoToGoToClient/charging_station, /GoToComponent, GoTo, getStatus, charging_station, getStatus_ch_i",
            "/GoToIsAtClient/charging_station, /GoToComponent, GoTo, isAtLocation, charging_station, isAt_ch_i",
            "/GoToGoToClient/charging_station, /GoToComponent, GoTo, halt, charging_station, halt_ch_i",
    })
    void table41Inputs(String from, String to, String protocol, String cmd, String args, String expected) {
        AbstractEvent e = mapped(A, command(from, to, protocol, cmd, args));
        assertEquals(expected, e.symbol());
        assertEquals(Direction.INPUT, e.direction());
        assertEquals(new Channel(from, to, protocol, cmd), e.channel());
    }

    /** Table 4.2, row by row: From, To, Protocol, Command, Arguments, Reply -> symbol. */
    @ParameterizedTest
    @CsvSource({
            "/GoToComponent, /GoToGoToClient/kitchen, GoTo, goTo, '', kitchen, o_goto_ki",
            "/GoToComponent, /GoToGoToClient/kitchen, GoTo, getStatus, kitchen, 1, o_getStatus_ki_run",
            "/GoToComponent, /GoToGoToClient/kitchen, GoTo, getStatus, kitchen, 2, o_getStatus_ki_suc",
            "/GoToComponent, /GoToGoToClient/kitchen, GoTo, getStatus, kitchen, 3, o_getStatus_ki_ab",
            "/GoToComponent, /GoToIsAtClient/kitchen, GoTo, isAtLocation, kitchen, 0, o_isAt_ki_false",
            "/GoToComponent, /GoToIsAtClient/kitchen, GoTo, isAtLocation, kitchen, 1, o_isAt_ki_true",
            "/GoToComponent, /GoToGoToClient/kitchen, GoTo, halt, kitchen, '', o_halt_ki",
            "/BatteryComponent, /BatteryReaderBatteryNotChargingClient, BatteryReader, charging_status, '', 0, o_batteryStatus_false",
            "/BatteryComponent, /BatteryReaderBatteryNotChargingClient, BatteryReader, charging_status, '', 1, o_batteryStatus_true",
            "/GoToComponent, /GoToGoToClient/charging_station, GoTo, goTo, '', charging_station, o_goto_ch",
            "/GoToComponent, /GoToGoToClient/charging_station, GoTo, getStatus, charging_station, 1, o_getStatus_ch_run",
            "/GoToComponent, /GoToGoToClient/charging_station, GoTo, getStatus, charging_station, 2, o_getStatus_ch_suc",
            "/GoToComponent, /GoToGoToClient/charging_station, GoTo, getStatus, charging_station, 3, o_getStatus_ch_ab",
            "/GoToComponent, /GoToIsAtClient/charging_station, GoTo, isAtLocation, charging_station, 0, o_isAt_ch_false",
            "/GoToComponent, /GoToIsAtClient/charging_station, GoTo, isAtLocation, charging_station, 1, o_isAt_ch_true",
            "/GoToComponent, /GoToGoToClient/charging_station, GoTo, halt, charging_station, '', o_halt_ch",
            // getStatus NOT_STARTED, not in the table but printed by the component
            "/GoToComponent, /GoToGoToClient/kitchen, GoTo, getStatus, kitchen, 0, o_getStatus_ki_idle",
            // the later monitor prints YARP vocabs for isAtLocation
            "/GoToComponent, /GoToIsAtClient/kitchen, GoTo, isAtLocation, kitchen, 27503, o_isAt_ki_true",
            "/GoToComponent, /GoToIsAtClient/kitchen, GoTo, isAtLocation, kitchen, 1818845542, o_isAt_ki_false",
    })
    void table42Outputs(String from, String to, String protocol, String cmd, String args, String value, String expected) {
        LogRecord r = reply(from, to, protocol, cmd, args, value);
        AbstractEvent e = mapped(A, r);
        assertEquals(expected, e.symbol());
        assertEquals(Direction.OUTPUT, e.direction());
        assertEquals(new Channel(to, from, protocol, cmd), e.channel(), "a reply's channel is seen from the client");
    }

    /**
     * Every boundary of the Section 5.2 bands. Upper-inclusive, except that 20.0 is medium_one so that
     * o_level_low is exactly the safety violation {@code level < 20.0}.
     */
    @ParameterizedTest
    @CsvSource({
            "-1.0, o_level_zero", "0, o_level_zero", "0.0, o_level_zero",
            "0.0001, o_level_low", "19.999999, o_level_low",
            "20.0, o_level_medium_one", "20, o_level_medium_one", "25.0, o_level_medium_one",
            "25.0001, o_level_medium_two", "30, o_level_medium_two", "30.0000001, o_level_medium_three",
            "35, o_level_medium_three", "35.5, o_level_medium_four", "40, o_level_medium_four",
            "40.01, o_level_medium_five", "45, o_level_medium_five", "45.0, o_level_medium_five",
            "45.0001, o_level_medium_six", "50, o_level_medium_six", "50.0, o_level_medium_six",
            "50.0000001, o_level_high", "97.316999999987189085, o_level_high", "100.0, o_level_high",
    })
    void levelBands(String value, String expected) {
        LogRecord r = reply("/BatteryComponent", "/BatteryReaderBatteryLevelClient", "BatteryReader", "level", "", value);
        assertEquals(expected, symbol(r));
        Bound safety = A.safety().orElseThrow();
        assertEquals(expected.equals("o_level_low") || expected.equals("o_level_zero"),
                safety.violatedBy(safety.valueOf(r)), "o_level_low/zero must coincide with the safety violation");
    }

    @Test
    void nonNumericLevelIsUnmapped() {
        for (String v : List.of("", "high", "NaN", "Infinity", "1d")) {
            Classification c = A.classify(reply("/BatteryComponent", "/BatteryReaderBatteryLevelClient",
                    "BatteryReader", "level", "", v));
            assertUnmapped(new UnmappedMessage("BatteryReader", "level", UnmappedMessage.Kind.REPLY, v),
                    "BatteryReader/level reply '" + v + "'", c);
        }
    }

    @Test
    void skillRequestsTicksAndUnknownAreDropped() {
        assertInstanceOf(Classification.Dropped.class, A.classify(reply("/GoToDestination/BT_rpc/server",
                "/GoToDestination/BT_rpc/client", "Skill_request", "request_ack", "", "1")));
        assertInstanceOf(Classification.Dropped.class, A.classify(command("/GoToDestination/BT_rpc/client",
                "/GoToDestination/BT_rpc/server", "Skill_request", "request_ack", "")));
        assertInstanceOf(Classification.Dropped.class, A.classify(command("/tick/monitor", "/GoToDestination/BT_rpc/server",
                "", "tick", "")));
        assertInstanceOf(Classification.Dropped.class, A.classify(new LogRecord(1, 0, "DEBUG", RecordKind.TICK,
                "/x", "/y", "GoTo", "goTo", "kitchen", "")));
        assertInstanceOf(Classification.Dropped.class, A.classify(new LogRecord(1, 0, "DEBUG", RecordKind.UNKNOWN,
                "/x", "/y", "GoTo", "goTo", "kitchen", "")));
    }

    @Test
    void unknownTrafficIsUnmappedWithAReadableKey() {
        assertUnmapped(new UnmappedMessage("GoTo", "teleport", UnmappedMessage.Kind.COMMAND, ""),
                "GoTo/teleport command",
                A.classify(command("/GoToGoToClient/kitchen", "/GoToComponent", "GoTo", "teleport", "kitchen")));
        assertUnmapped(new UnmappedMessage("GoTo", "teleport", UnmappedMessage.Kind.REPLY, "5"),
                "GoTo/teleport reply '5'",
                A.classify(reply("/GoToComponent", "/GoToGoToClient/kitchen", "GoTo", "teleport", "kitchen", "5")));
        assertUnmapped(new UnmappedMessage("GoTo", "getStatus", UnmappedMessage.Kind.REPLY, "7"),
                "GoTo/getStatus reply '7'",
                A.classify(reply("/GoToComponent", "/GoToGoToClient/kitchen", "GoTo", "getStatus", "kitchen", "7")));
        assertUnmapped(new UnmappedMessage("GoTo", "goTo", UnmappedMessage.Kind.COMMAND_LOCATION, "bedroom"),
                "GoTo/goTo command about unknown location 'bedroom'",
                A.classify(command("/GoToGoToClient/bedroom", "/GoToComponent", "GoTo", "goTo", "bedroom")));
    }

    @Test
    void locationFallsBackToReplyThenClientPort() {
        // goTo reply: arguments empty, destination in the reply
        assertEquals("o_goto_ch", symbol(reply("/GoToComponent", "/GoToGoToClient/x", "GoTo", "goTo", "", "charging_station")));
        // halt reply: no arguments, no reply, location only in the client port
        assertEquals("o_halt_ki", symbol(reply("/GoToComponent", "/GoToGoToClient/kitchen", "GoTo", "halt", "", "")));
        assertEquals("halt_ch_i", symbol(command("/GoToGoToClient/charging_station", "/GoToComponent", "GoTo", "halt", "")));
    }

    @Test
    void olderFormatWithoutProtocolMapsByCommand() {
        assertEquals("getStatus_ki_i", symbol(command("/GoToGoToClient/kitchen", "/GoToComponent", "", "getStatus", "kitchen")));
        assertEquals("o_level_high", symbol(reply("/BatteryComponent", "/BatteryReaderBatteryLevelClient", "", "level", "", "97.3")));
        assertEquals("isAt_ch_i", symbol(command("/GoToIsAtClient/charging_station", "/GoToComponent", "", "isAtLocation",
                "charging_station extra")));
        assertUnmapped(new UnmappedMessage("", "teleport", UnmappedMessage.Kind.COMMAND, ""), "teleport command",
                A.classify(command("/GoToGoToClient/kitchen", "/GoToComponent", "", "teleport", "kitchen")));
    }

    @Test
    void alphabetsAreSortedCompleteAndSafe() {
        List<String> in = A.inputAlphabet();
        List<String> out = A.outputAlphabet();
        assertEquals(new ArrayList<>(in.stream().sorted().distinct().toList()), in);
        assertEquals(new ArrayList<>(out.stream().sorted().distinct().toList()), out);
        assertEquals(List.of("batteryStatus_i", "getStatus_ch_i", "getStatus_ki_i", "goTo_ch_i", "goTo_ki_i",
                "halt_ch_i", "halt_ki_i", "isAt_ch_i", "isAt_ki_i", "level_i"), in);
        assertEquals(2 + 2 * (1 + 4 + 2 + 1) + 9, out.size());
        assertTrue(out.contains("o_level_medium_six") && out.contains("o_getStatus_ch_idle"));
        for (String s : out) {
            assertTrue(s.matches("[A-Za-z0-9_]+"), s);
            assertFalse(s.contains("/"), s);
        }
    }

    @Test
    void safetyNameAndFingerprint() throws AbstractionException {
        assertEquals(new Bound("battery", "battery level >= 20% (thesis 3.3.1)", "send the robot to the charging station",
                Scope.GLOBAL, new ValueReader("BatteryReader", "level", "/BatteryComponent",
                "/BatteryReaderBatteryLevelClient"), 20.0, Double.POSITIVE_INFINITY,
                List.of(new UnderWay(null, "GoTo", "goTo", "charging_station"),
                        new UnderWay("GoToChargingStation", null, null, null))), A.safety().orElseThrow());
        assertEquals("thesis-tables-4.1-4.2-bands-5.2", A.name());
        assertTrue(A.fingerprint().matches("[0-9a-f]{64}"));
        // Same content in another key order and layout: same canonical form and fingerprint.
        Abstraction again = AbstractionFiles.fromJson("again.json", A.canonicalJson());
        assertEquals(A.canonicalJson(), again.canonicalJson());
        assertEquals(A.fingerprint(), again.fingerprint());
        String reordered = """
                {"rules": [{"replies": [{"symbol": "o_x", "any": true}], "input": "x_i", "command": "x", "protocol": "P"}],
                 "name": "n"}""";
        String ordered = """
                {"name": "n", "rules": [{"protocol": "P", "command": "x", "input": "x_i",
                 "replies": [{"any": true, "symbol": "o_x"}]}]}""";
        assertEquals(AbstractionFiles.fromJson("a", reordered).fingerprint(), AbstractionFiles.fromJson("b", ordered).fingerprint());
        assertNotEquals(A.fingerprint(), AbstractionFiles.fromJson("b", ordered).fingerprint());
        assertTrue(A.canonicalJson().indexOf("\"drop\"") < A.canonicalJson().indexOf("\"name\""));
    }

    /** {@code c} is the unmapped message {@code expected}, whose written form is {@code text}. */
    private static void assertUnmapped(UnmappedMessage expected, String text, Classification c) {
        assertEquals(new Classification.Unmapped(expected), c);
        assertEquals(text, expected.text());
    }
}
