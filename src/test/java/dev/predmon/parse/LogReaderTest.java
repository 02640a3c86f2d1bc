package dev.predmon.parse;

import dev.predmon.parse.ParseProblem.Severity;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.io.OutputStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class LogReaderTest {

    @TempDir
    Path dir;

    private final List<LogRecord> records = new ArrayList<>();
    private final List<ParseProblem> problems = new ArrayList<>();

    private long read(Path file) throws IOException {
        return LogReader.read(file, records::add, problems::add);
    }

    @Test
    void yarploggerSaveFile() throws IOException, URISyntaxException {
        Path file = Path.of(Objects.requireNonNull(getClass().getResource("/parse/yarplogger-save.txt")).toURI());
        assertEquals(3, read(file));
        assertEquals(List.of(
                new LogRecord(24, 13.25, "DEBUG", RecordKind.COMMAND, "/GoToGoToClient/kitchen", "/GoToComponent",
                        "GoTo", "goTo", "kitchen", ""),
                new LogRecord(34, 1.0, "DEBUG", RecordKind.REPLY, "/GoToComponent", "/GoToGoToClient/kitchen",
                        "GoTo", "getStatus", "kitchen", "1"),
                new LogRecord(63, 21.0, "DEBUG", RecordKind.REPLY, "/BatteryComponent",
                        "/BatteryReaderBatteryLevelClient", "", "level", "", "19.5")), records);
        assertEquals(List.of(), problems);
    }

    /**
     * A capture stopped inside a record header loses that record as one stopped inside a field line does, and says
     * so the same way, in both layouts; a last line that is no header's beginning is another program's line.
     */
    @Test
    void aLogCutInsideARecordHeaderWarnsAsOneCutInsideAFieldLine() throws IOException {
        String record = "71.8\tDEBUG\tCommand intercepted:\n  From      : /a\n  To        : /b\n  Protocol  : P\n"
                + "  Command   : c\n  Arguments : \n  Reply     : \n";
        for (String cut : List.of("72.0\tDEBUG\tReply inter", "72.0\tDEBUG\tR", "72.0 DEBUG Message rece")) {
            records.clear();
            problems.clear();
            assertEquals(1, read(write(record + cut)), cut);
            assertEquals(List.of(new ParseProblem(8, Severity.WARNING, "log ends in the middle of a record started "
                    + "at line 8: missing the rest of its header and its fields")), problems, cut);
        }
        String console = "[DEBUG] Command intercepted:\n  From      : /a\n  To        : /b\n  Protocol  : P\n"
                + "  Command   : c\n  Arguments : \n  Reply     : \n";
        for (String cut : List.of("\u001b[01;32mDEBUG\u001b[00m] Command interc", "[DEBUG] Tick")) {
            problems.clear();
            read(write(console + cut));
            assertEquals(1, problems.size(), cut);
            assertTrue(problems.get(0).message().startsWith("log ends in the middle of a record started at line 8"),
                    problems.toString());
        }
        for (String other : List.of("72.0\tINFO\tsome other program's line", "GammaRay server listening on: tcp")) {
            problems.clear();
            read(write(record + other));
            assertEquals(List.of(), problems, other);
        }
    }

    @Test
    void saveFileEntryEndingBeforeItsRecordIsReported() throws IOException {
        Path file = write(String.join("\n", "1", "1", "NULL-DATA", "/log/a", "/a", "a", "log", "1",
                "0", "1", "0", "0", "0", "0", "1", "1",
                "0", "3.5", "2", "<#STRING_START#>Command intercepted:", "  From : /a", "  To : /b<#STRING_END#>",
                "1", "4.5", "2", "<#STRING_START#>Command intercepted:", "  From : /a", "  To : /b",
                "  Protocol : P", "  Command : c", "  Arguments :", "  Reply :<#STRING_END#>", ""));
        assertEquals(1, read(file));
        assertEquals(new LogRecord(26, 4.5, "DEBUG", RecordKind.COMMAND, "/a", "/b", "P", "c", "", ""), records.get(0));
        assertEquals(List.of(new ParseProblem(22, Severity.ERROR,
                "entry text ended before the record started at line 20 was complete: expected 'Protocol :'")), problems);
    }

    @Test
    void crlfInvalidUtf8AndUnterminatedLastLine() throws IOException {
        byte[] bad = {(byte) 0xC3, (byte) 0x28, (byte) 0xFF, '\r', '\n'};
        String log = "1.0 DEBUG Command intercepted:\r\n  From : /a\u00e9\r\n  To : /b\r\n  Protocol : P\r\n"
                + "  Command : c\r\n  Arguments : x\r\n  Reply : y";
        Path file = dir.resolve("log.txt");
        try (OutputStream out = Files.newOutputStream(file)) {
            out.write(bad);
            out.write(log.getBytes(StandardCharsets.UTF_8));
        }
        assertEquals(1, read(file));
        assertEquals(List.of(new LogRecord(2, 1.0, "DEBUG", RecordKind.COMMAND, "/a\u00e9", "/b", "P", "c", "x", "y")),
                records);
        assertEquals(List.of(), problems);
    }

    @Test
    void hugeLineWithoutNewlineIsReportedOnceWithoutHoldingIt() throws IOException {
        Path file = dir.resolve("huge.txt");
        String good = SampleLogs.mixed(2, 1);
        try (OutputStream out = Files.newOutputStream(file)) {
            out.write(good.getBytes(StandardCharsets.UTF_8));
            byte[] block = "x".repeat(1 << 16).getBytes(StandardCharsets.US_ASCII);
            for (int i = 0; i < 160; i++) {
                out.write(block);
            }
        }
        assertEquals(2, read(file));
        assertEquals(1, problems.size());
        ParseProblem problem = problems.get(0);
        assertEquals(Severity.ERROR, problem.severity());
        assertEquals(good.lines().count() + 1, problem.line());
        assertTrue(problem.message().contains("10485760 bytes"), problem.message());
    }

    @Test
    void hugeLineInTheMiddleIsSkippedAndParsingGoesOn() throws IOException {
        String log = SampleLogs.mixed(1, 2) + "y".repeat(3 << 20) + "\n" + SampleLogs.mixed(3, 3);
        assertEquals(4, read(write(log)));
        assertEquals(1, problems.size());
        assertEquals(SampleLogs.mixed(1, 2).lines().count() + 1, problems.get(0).line());
    }

    @Test
    void emptyFile() throws IOException {
        assertEquals(0, read(write("")));
        assertEquals(List.of(), records);
        assertEquals(List.of(), problems);
    }

    @Test
    void missingFileIsAnIoError() {
        assertThrows(NoSuchFileException.class, () -> read(dir.resolve("absent.log")));
    }

    @Test
    void mixedLogCountsExactly() throws IOException {
        assertEquals(500, read(write(SampleLogs.mixed(500, 7))));
        assertEquals(List.of(), problems);
    }

    private Path write(String text) throws IOException {
        return Files.writeString(dir.resolve("log-" + System.nanoTime() + ".txt"), text);
    }
}
