package dev.predmon.parse;

import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The monitor's console output redirected to a file, as the real recordings show it, in a hand-written fixture
 * ({@code console-capture.txt}): colour codes around the level, no time stamps (the clock is the tick), YARP's
 * own lines and other programs' lines between records, a header whose escape characters were lost after another
 * program's text, a broken record, and a capture stopped in the middle of a record and of a line.
 */
class ConsoleLayoutTest {

    private static final Path FIXTURE;

    static {
        try {
            FIXTURE = Path.of(ConsoleLayoutTest.class.getResource("console-capture.txt").toURI());
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    private static LogRecord rec(long line, double tick, RecordKind kind, String from, String to, String protocol,
                                 String command, String arguments, String reply) {
        return new LogRecord(line, tick, "DEBUG", kind, from, to, protocol, command, arguments, reply, Clock.TICKS);
    }

    @Test
    void consoleCaptureIsReadWithTheTickAsClock() throws IOException {
        List<LogRecord> records = new ArrayList<>();
        List<ParseProblem> problems = new ArrayList<>();
        long n = LogReader.read(FIXTURE, records::add, problems::add);
        String battery = "/BatteryReaderBatteryLevelClient";
        assertEquals(List.of(
                rec(4, 1, RecordKind.TICK, "/tick/monitor", "/monitor", "Tick", "", "1", ""),
                rec(11, 1, RecordKind.COMMAND, battery, "/BatteryComponent", "BatteryReader", "level", "", ""),
                rec(19, 1, RecordKind.REPLY, "/BatteryComponent", battery, "BatteryReader", "level", "",
                        "99.8499999999992837729"),
                rec(26, 1, RecordKind.COMMAND, "/GoToGoToClient/kitchen", "/GoToComponent", "GoTo", "goTo", "", ""),
                rec(34, 1, RecordKind.REPLY, "/GoToComponent", "/GoToGoToClient/kitchen", "GoTo", "goTo", "", "kitchen"),
                rec(41, 2, RecordKind.TICK, "/tick/monitor", "/monitor", "Tick", "", "2", ""),
                rec(48, 2, RecordKind.COMMAND, battery, "/BatteryComponent", "BatteryReader", "level", "", ""),
                rec(61, 2, RecordKind.REPLY, "/BatteryComponent", battery, "BatteryReader", "level", "",
                        "19.4000000000000003553"),
                rec(68, 3, RecordKind.TICK, "/tick/monitor", "/monitor", "Tick", "", "3", "")), records);
        assertEquals(records.size(), n);
        assertEquals(List.of(
                new ParseProblem(58, ParseProblem.Severity.ERROR,
                        "expected 'Protocol :' line of the record started at line 55, got 'Command : level'"),
                new ParseProblem(75, ParseProblem.Severity.WARNING,
                        "log ends in the middle of a record started at line 75: missing 'Reply :'")), problems);
    }

    @Test
    void aCaptureCutInTheMiddleOfItsLastFieldLineStillCountsTheRecordTheLineCompletes() throws IOException {
        // The capture stopped after "  Reply     : 1" without its newline: the record is complete, as a reader of
        // the file sees it, and counts.
        String text = Files.readString(FIXTURE);
        String cut = text.substring(0, text.lastIndexOf("  Arguments : kitchen\n")) + "  Arguments : kitchen\n  Reply     : 1";
        Collected c = Collected.parse(cut);
        assertEquals(10, c.records.size());
        assertEquals("1", c.records.get(9).reply());
        assertEquals(1, c.problems.size());
    }

    @Test
    void oneHeaderDecidesTheLayoutAndLaterColumnHeadersAreNotRecords() {
        Collected c = Collected.parse("""
                [DEBUG] Tick intercepted:
                  From      : /tick/monitor
                  To        : /monitor
                  Protocol  : Tick
                  Command   :
                  Arguments : 7
                  Reply     :
                1.5 DEBUG Command intercepted:
                """);
        assertEquals(List.of(rec(1, 7, RecordKind.TICK, "/tick/monitor", "/monitor", "Tick", "", "7", "")), c.records);
        assertEquals(Clock.TICKS, c.parser.clock());
        assertEquals(1, c.problems.size());
        assertTrue(c.problems.get(0).message().startsWith("malformed record header: expected '[DEBUG] Command intercepted:'"),
                c.problems.get(0).message());
    }

    @Test
    void olderMessageReceivedShapeInAConsoleCapture() {
        Collected c = Collected.parse("""
                [DEBUG] Message received:
                From : /BatteryComponent
                To : /BatteryReaderBatteryLevelClient
                Reply : level
                Arguments: 42.0
                """);
        assertEquals(List.of(rec(1, 0, RecordKind.REPLY, "/BatteryComponent", "/BatteryReaderBatteryLevelClient", "",
                "level", "", "42.0")), c.records);
    }
}
