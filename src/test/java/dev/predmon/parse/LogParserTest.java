package dev.predmon.parse;

import dev.predmon.parse.ParseProblem.Severity;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Random;

import static dev.predmon.parse.Collected.parse;
import static dev.predmon.parse.Collected.record;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class LogParserTest {

    private static final String GOTO_COMMAND = """
            71.818968\tDEBUG\tCommand intercepted:
              From      : /GoToGoToClient/kitchen
              To        : /GoToComponent
              Protocol  : GoTo
              Command   : goTo
              Arguments : kitchen
              Reply     :\s
            """;
    private static final LogRecord GOTO_COMMAND_RECORD = record(1, 71.818968, RecordKind.COMMAND,
            "/GoToGoToClient/kitchen", "/GoToComponent", "GoTo", "goTo", "kitchen", "");

    @Test
    void tabSeparatedColumns() {
        Collected c = parse(GOTO_COMMAND);
        assertEquals(List.of(GOTO_COMMAND_RECORD), c.records);
        assertEquals(List.of(), c.problems);
    }

    @Test
    void spaceSeparatedColumns() {
        Collected c = parse(GOTO_COMMAND.replace('\t', ' ').replace("DEBUG ", "DEBUG    "));
        assertEquals(List.of(GOTO_COMMAND_RECORD), c.records);
        assertEquals(List.of(), c.problems);
    }

    @Test
    void epochTimeAndReply() {
        Collected c = parse("""
                1606737474.123456 DEBUG Reply intercepted:
                  From      : /BatteryComponent
                  To        : /BatteryReaderBatteryLevelClient
                  Protocol  : BatteryReader
                  Command   : level
                  Arguments :\s
                  Reply     : 97.316999999987189085
                """);
        assertEquals(List.of(record(1, 1606737474.123456, RecordKind.REPLY, "/BatteryComponent",
                "/BatteryReaderBatteryLevelClient", "BatteryReader", "level", "", "97.316999999987189085")), c.records);
        assertEquals(List.of(), c.problems);
    }

    @Test
    void crlfLineEndings() {
        Collected c = parse(GOTO_COMMAND.replace("\n", "\r\n"));
        assertEquals(List.of(GOTO_COMMAND_RECORD), c.records);
        assertEquals(List.of(), c.problems);
    }

    @Test
    void anySpacingAroundLabelsAndColons() {
        Collected c = parse("""
                71.818968 DEBUG Command intercepted:
                From: /GoToGoToClient/kitchen
                      To :/GoToComponent  \s
                \tProtocol\t:\tGoTo
                Command    :    goTo
                Arguments:kitchen
                Reply:
                """);
        assertEquals(List.of(GOTO_COMMAND_RECORD), c.records);
        assertEquals(List.of(), c.problems);
    }

    @Test
    void emptyArgumentsAndReplyWithAndWithoutTrailingSpace() {
        Collected c = parse("""
                5.0 DEBUG Command intercepted:
                  From : /a
                  To : /b
                  Protocol : GoTo
                  Command : halt
                  Arguments :\s
                  Reply :
                6.0 DEBUG Reply intercepted:
                  From : /b
                  To : /a
                  Protocol : GoTo
                  Command : halt
                  Arguments:
                  Reply :\s\s\s
                """);
        assertEquals(List.of(
                record(1, 5.0, RecordKind.COMMAND, "/a", "/b", "GoTo", "halt", "", ""),
                record(8, 6.0, RecordKind.REPLY, "/b", "/a", "GoTo", "halt", "", "")), c.records);
        assertEquals(List.of(), c.problems);
    }

    @Test
    void tickAndUnknownKinds() {
        Collected c = parse("""
                1.5 DEBUG Tick intercepted:
                  From : /tick/monitor
                  To : /x
                  Protocol : Skill_request
                  Command : request_tick
                  Arguments :
                  Reply :
                2.5 DEBUG Unknown intercepted:
                  From : /p
                  To : /q
                  Protocol :
                  Command :
                  Arguments :
                  Reply :
                """);
        assertEquals(List.of(
                record(1, 1.5, RecordKind.TICK, "/tick/monitor", "/x", "Skill_request", "request_tick", "", ""),
                record(8, 2.5, RecordKind.UNKNOWN, "/p", "/q", "", "", "", "")), c.records);
    }

    @Test
    void otherLevelsOnRecordHeadersAreAccepted() {
        Collected c = parse(GOTO_COMMAND.replace("DEBUG", "INFO"));
        assertEquals(List.of(new LogRecord(1, 71.818968, "INFO", RecordKind.COMMAND, "/GoToGoToClient/kitchen",
                "/GoToComponent", "GoTo", "goTo", "kitchen", "")), c.records);
    }

    @Test
    void rawBottlesAndOtherComponentsLinesAreSkipped() {
        Collected c = parse("""
                1606737474.123456 INFO "/GoToGoToClient/kitchen" "/GoToComponent" "command" "GoTo" (goTo) (kitchen) ()
                1606737474.123456 DEBUG Command intercepted:
                  From      : /GoToGoToClient/kitchen
                  To        : /GoToComponent
                  Protocol  : GoTo
                  Command   : goTo
                  Arguments : kitchen
                  Reply     :\s
                1606737474.2 WARNING goTo called with destination kitchen
                12.5\tINFO\tsomething else: with a colon
                1606737474.3 INFO "/GoToComponent" "/GoToGoToClient/kitchen" "reply" "GoTo" (goTo) (kitchen) ()
                1606737474.3 DEBUG Reply intercepted:
                  From      : /GoToComponent
                  To        : /GoToGoToClient/kitchen
                  Protocol  : GoTo
                  Command   : goTo
                  Arguments : kitchen
                  Reply     :\s
                """);
        assertEquals(List.of(
                record(2, 1606737474.123456, RecordKind.COMMAND, "/GoToGoToClient/kitchen", "/GoToComponent", "GoTo",
                        "goTo", "kitchen", ""),
                record(12, 1606737474.3, RecordKind.REPLY, "/GoToComponent", "/GoToGoToClient/kitchen", "GoTo",
                        "goTo", "kitchen", "")), c.records);
        assertEquals(List.of(), c.problems);
    }

    @Test
    void olderFormatIsNormalisedToTheCurrentShape() {
        Collected c = parse("""
                10.0 DEBUG Message received:
                From : /GoToGoToClient/kitchen
                To : /GoToComponent
                Command  : goTo
                Arguments: kitchen
                11.0 DEBUG Message received:
                From : /GoToComponent
                To : /GoToGoToClient/kitchen
                Reply    : getStatus
                Arguments: kitchen 1
                12.0 DEBUG Message received:
                From : /BatteryComponent
                To : /BatteryReaderBatteryLevelClient
                Reply    : level
                Arguments: 97.5
                13.0 DEBUG Message received:
                From : /tick/monitor
                To : /x
                Tick     : tick
                Arguments: a  b
                14.0 DEBUG Message received:
                From : /GoToComponent
                To : /GoToGoToClient/kitchen
                Reply    : halt
                Arguments:
                15.0 DEBUG Message received:
                From : /s
                To : /c
                Reply    : m
                Arguments: x y z
                """);
        assertEquals(List.of(
                record(1, 10.0, RecordKind.COMMAND, "/GoToGoToClient/kitchen", "/GoToComponent", "", "goTo", "kitchen", ""),
                record(6, 11.0, RecordKind.REPLY, "/GoToComponent", "/GoToGoToClient/kitchen", "", "getStatus", "kitchen", "1"),
                record(11, 12.0, RecordKind.REPLY, "/BatteryComponent", "/BatteryReaderBatteryLevelClient", "", "level", "", "97.5"),
                record(16, 13.0, RecordKind.TICK, "/tick/monitor", "/x", "", "tick", "a  b", ""),
                record(21, 14.0, RecordKind.REPLY, "/GoToComponent", "/GoToGoToClient/kitchen", "", "halt", "", ""),
                record(26, 15.0, RecordKind.REPLY, "/s", "/c", "", "m", "x y", "z")), c.records);
        assertEquals(List.of(), c.problems);
    }

    @Test
    void logEndingMidRecordWarnsOnceAndKeepsEarlierRecords() {
        Collected c = parse(GOTO_COMMAND + """
                72.0 DEBUG Reply intercepted:
                  From      : /GoToComponent
                  To        : /GoToGoToClient/kitchen
                  Protocol  : GoTo
                """);
        assertEquals(List.of(GOTO_COMMAND_RECORD), c.records);
        assertEquals(List.of(new ParseProblem(8, Severity.WARNING,
                "log ends in the middle of a record started at line 8: missing 'Command :'")), c.problems);
        c.parser.endOfInput();
        assertEquals(1, c.problems.size(), "reported once");
    }

    @Test
    void missingFieldIsReportedAndTheNextRecordParses() {
        Collected c = parse("""
                1.0 DEBUG Command intercepted:
                  From : /a
                  To : /b
                  Command : getStatus
                  Arguments : kitchen
                  Reply :
                2.0 DEBUG Command intercepted:
                  From : /a
                  To : /b
                  Protocol : GoTo
                  Command : getStatus
                  Arguments : kitchen
                  Reply :
                """);
        assertEquals(List.of(record(7, 2.0, RecordKind.COMMAND, "/a", "/b", "GoTo", "getStatus", "kitchen", "")),
                c.records);
        assertEquals(List.of(new ParseProblem(4, Severity.ERROR,
                "expected 'Protocol :' line of the record started at line 1, got 'Command : getStatus'")), c.problems);
    }

    @Test
    void newHeaderBeforeRecordIsCompleteDropsTheFirst() {
        Collected c = parse("""
                1.0 DEBUG Command intercepted:
                  From : /a
                  To : /b
                2.0 DEBUG Command intercepted:
                  From : /a
                  To : /b
                  Protocol : GoTo
                  Command : halt
                  Arguments : kitchen
                  Reply :
                """);
        assertEquals(List.of(record(4, 2.0, RecordKind.COMMAND, "/a", "/b", "GoTo", "halt", "kitchen", "")), c.records);
        assertEquals(List.of(new ParseProblem(4, Severity.ERROR,
                "expected 'Protocol :' line of the record started at line 1, got '2.0 DEBUG Command intercepted:'")),
                c.problems);
    }

    @Test
    void nonNumericTimeIsReported() {
        Collected c = parse("abc DEBUG Command intercepted:\n  From : /a\n  To : /b\n" + GOTO_COMMAND);
        assertEquals(List.of(new LogRecord(4, 71.818968, "DEBUG", RecordKind.COMMAND, "/GoToGoToClient/kitchen",
                "/GoToComponent", "GoTo", "goTo", "kitchen", "")), c.records);
        assertEquals(1, c.problems.size());
        assertEquals(1, c.problems.get(0).line());
        assertEquals(Severity.ERROR, c.problems.get(0).severity());
        assertTrue(c.problems.get(0).message().contains("'abc'"), c.problems.get(0).message());
    }

    @Test
    void headerWithoutTimeAndLevelIsReported() {
        Collected c = parse("Command intercepted:\n" + GOTO_COMMAND);
        assertEquals(1, c.records.size());
        assertEquals(List.of(new ParseProblem(1, Severity.ERROR,
                "malformed record header: expected '<time> <LEVEL> Command intercepted:', got 'Command intercepted:'")),
                c.problems);
    }

    @Test
    void duplicatedFieldIsReported() {
        Collected c = parse("""
                1.0 DEBUG Command intercepted:
                  From : /a
                  To : /b
                  To : /b
                  Protocol : GoTo
                  Command : halt
                  Arguments :
                  Reply :
                """ + GOTO_COMMAND);
        assertEquals(List.of(record(9, 71.818968, RecordKind.COMMAND, "/GoToGoToClient/kitchen", "/GoToComponent",
                "GoTo", "goTo", "kitchen", "")), c.records);
        assertEquals(List.of(new ParseProblem(4, Severity.ERROR,
                "expected 'Protocol :' line of the record started at line 1, got 'To : /b'")), c.problems);
    }

    @Test
    void outOfOrderFieldIsReported() {
        Collected c = parse("""
                1.0 DEBUG Command intercepted:
                  To : /b
                  From : /a
                  Protocol : GoTo
                  Command : halt
                  Arguments :
                  Reply :
                """ + GOTO_COMMAND);
        assertEquals(1, c.records.size());
        assertEquals(8, c.records.get(0).line());
        assertEquals(List.of(new ParseProblem(2, Severity.ERROR,
                "expected 'From :' line of the record started at line 1, got 'To : /b'")), c.problems);
    }

    @Test
    void unknownLabelIsReported() {
        Collected c = parse("""
                1.0 DEBUG Command intercepted:
                  From : /a
                  To : /b
                  Colour : blue
                  Protocol : GoTo
                """ + GOTO_COMMAND);
        assertEquals(1, c.records.size());
        assertEquals(List.of(new ParseProblem(4, Severity.ERROR,
                "expected 'Protocol :' line of the record started at line 1, got 'Colour : blue'")), c.problems);
    }

    @Test
    void olderFormatWithBadKindLabelIsReported() {
        Collected c = parse("""
                1.0 DEBUG Message received:
                From : /a
                To : /b
                Protocol : GoTo
                """);
        assertEquals(List.of(), c.records);
        assertEquals(List.of(new ParseProblem(4, Severity.ERROR,
                "expected 'Command :', 'Reply :' or 'Tick :' line of the record started at line 1, got 'Protocol : GoTo'")),
                c.problems);
    }

    @Test
    void negativeTimeIsANumber() {
        Collected c = parse(GOTO_COMMAND.replace("71.818968", "-3.5"));
        assertEquals(-3.5, c.records.get(0).time());
    }

    @Test
    void garbageAndBinaryNeverThrowAndYieldNothing() {
        StringBuilder garbage = new StringBuilder();
        Random random = new Random(42);
        for (int i = 0; i < 20_000; i++) {
            int c = random.nextInt(5) == 0 ? "\n\r\t :<>#".charAt(random.nextInt(8)) : random.nextInt(0x3000);
            garbage.append((char) c);
        }
        garbage.append("\n\uFFFD\uFFFD\u0000\u0001 DEBUG Reply intercepted:\n:::\n");
        Collected c = parse(garbage.toString());
        assertEquals(List.of(), c.records);
        assertTrue(c.problems.stream().allMatch(p -> p.line() >= 1));
    }

    @Test
    void veryLongLineInsideARecordBreaksIt() {
        String longValue = "x".repeat(2_000_000);
        Collected c = parse("1.0 DEBUG Command intercepted:\n" + longValue + "\n" + GOTO_COMMAND);
        assertEquals(1, c.records.size());
        assertEquals(1, c.problems.size());
        assertTrue(c.problems.get(0).message().length() < 200, "the message quotes a bounded part of the line");
    }

    @Test
    void emptyInputYieldsNothing() {
        Collected c = parse("");
        assertEquals(List.of(), c.records);
        assertEquals(List.of(), c.problems);
        assertEquals(0, c.parser.lineNumber());
    }

    @Test
    void resetRestartsLineNumbersAndForgetsTheRecordInProgress() {
        Collected c = new Collected();
        c.parser.acceptLine("1.0 DEBUG Command intercepted:");
        c.parser.acceptLine("  From : /a");
        c.parser.reset();
        GOTO_COMMAND.lines().forEach(c.parser::acceptLine);
        c.parser.endOfInput();
        assertEquals(List.of(GOTO_COMMAND_RECORD), c.records);
        assertEquals(List.of(), c.problems);
        assertEquals(7, c.parser.lineNumber());
    }

    /**
     * YARP's own lines about the monitor's port before the first record, as the monitor prints them when it starts
     * (colour codes, YARP 3's two forms, YARP 2's prefix), are counted; another program's ports, other programs' lines
     * and the records are not.
     */
    @Test
    void yarpsStartUpLinesAreCountedBeforeTheFirstRecord() {
        LogParser parser = new LogParser(r -> { }, p -> { });
        for (String line : new String[] {
            "Detected ABI qt5_12-x86_64, using ABI qt5_12-x86_64.",
            "[\u001b[01;34mINFO\u001b[00m] |yarp.os.Port| Port /monitor active at tcp://10.0.0.7:10032/",
            "[\u001b[01;34mINFO\u001b[00m] |\u001b[01;34myarp.os.impl.PortCoreInputUnit\u001b[00m|\u001b[31m/monitor"
                    + "\u001b[00m| Receiving input from /tick/monitor to /monitor using tcp",
            "[INFO]|yarp.os.Port|/monitor| Port /monitor active at tcp://10.0.0.7:10002/",
            "yarp: Port /monitor active at tcp://10.0.0.7:10002/",
            "GammaRay server listening on: tcp://127.0.0.1:11732",
            "[INFO] |yarp.os.Port| Port /tool1 active at tcp://10.0.0.1:10002/",
            "[INFO] has grasped ret value 0",
            "robot: the yarp server is down",
        }) {
            parser.acceptLine(line);
        }
        assertEquals(4, parser.yarpLines());
        parser.acceptLine("[DEBUG] Tick intercepted:");
        parser.acceptLine("[INFO] |yarp.os.impl.PortCoreInputUnit| Receiving input from /a to /monitor using tcp");
        assertEquals(4, parser.yarpLines(), "after the first record, nothing more is the preamble");
        parser.reset();
        assertEquals(0, parser.yarpLines());
    }
}
