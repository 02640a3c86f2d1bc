package dev.predmon.simulate;

import dev.predmon.parse.LogReader;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;
import dev.predmon.parse.RecordKind;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

/**
 * Test fixture: a log as the project's own parser reads it back, its records by line, with the queries the truth
 * tests ask (the records before a line, the tick a record falls in).
 */
final class ReadBack {

    private final List<LogRecord> records;
    private final Map<Long, Integer> byLine = new HashMap<>();

    private ReadBack(List<LogRecord> records) {
        this.records = records;
        for (int i = 0; i < records.size(); i++) {
            byLine.put(records.get(i).line(), i);
        }
    }

    /** Writes {@code runs} one after another to {@code file} as {@code options} print them, and reads it back. */
    static ReadBack write(Path file, SimOptions options, SimRun... runs) throws IOException {
        try (Writer w = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            for (SimRun run : runs) {
                LogWriter.write(run, options, w);
            }
        }
        return read(file);
    }

    /** Reads {@code file} with the project's parser; a parse problem fails the test. */
    static ReadBack read(Path file) throws IOException {
        List<LogRecord> records = new ArrayList<>();
        List<ParseProblem> problems = new ArrayList<>();
        LogReader.read(file, records::add, problems::add);
        assertEquals(List.of(), problems, file + " reads without a problem");
        return new ReadBack(records);
    }

    List<LogRecord> records() {
        return records;
    }

    /** The record whose header is on {@code line}. */
    LogRecord at(long line) {
        Integer i = byLine.get(line);
        assertNotNull(i, "a record starts at line " + line);
        return records.get(i);
    }

    /** The records before the one at {@code line}, in log order. */
    List<LogRecord> before(long line) {
        return records.subList(0, byLine.get(line));
    }

    /** The records after the one at {@code line}, in log order. */
    List<LogRecord> after(long line) {
        return records.subList(byLine.get(line) + 1, records.size());
    }

    /** The first record that {@code test} accepts. */
    LogRecord first(Predicate<LogRecord> test) {
        return records.stream().filter(test).findFirst().orElseThrow(() -> new AssertionError("no such record"));
    }

    /** The number of the last Tick record at or before {@code r}: the tick of the tree it was printed in. */
    int tickOf(LogRecord r) {
        int tick = -1;
        for (LogRecord x : records) {
            if (x.kind() == RecordKind.TICK) {
                tick = Integer.parseInt(x.arguments());
            }
            if (x.line() == r.line()) {
                return tick;
            }
        }
        throw new AssertionError("not a record of this log: " + r);
    }

    static boolean reply(LogRecord r, String command, String reply) {
        return r.kind() == RecordKind.REPLY && r.command().equals(command) && r.reply().equals(reply);
    }

    static boolean command(LogRecord r, String command, String argument) {
        return r.kind() == RecordKind.COMMAND && r.command().equals(command) && r.arguments().equals(argument);
    }

    static boolean tick(LogRecord r, int tick) {
        return r.kind() == RecordKind.TICK && r.arguments().equals(Integer.toString(tick));
    }
}
