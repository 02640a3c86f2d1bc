package dev.predmon.parse;

import java.util.ArrayList;
import java.util.List;

/** What a parser emitted, for assertions. */
final class Collected {
    final List<LogRecord> records = new ArrayList<>();
    final List<ParseProblem> problems = new ArrayList<>();
    final LogParser parser = new LogParser(records::add, problems::add);

    /** Feeds {@code text} split on {@code \n}, as a reader would, then ends the input. */
    static Collected parse(String text) {
        Collected collected = new Collected();
        String[] lines = text.split("\n", -1);
        int count = text.isEmpty() || text.endsWith("\n") ? lines.length - 1 : lines.length;
        for (int i = 0; i < count; i++) {
            collected.parser.acceptLine(lines[i]);
        }
        collected.parser.endOfInput();
        return collected;
    }

    static LogRecord record(long line, double time, RecordKind kind, String from, String to, String protocol,
                            String command, String arguments, String reply) {
        return new LogRecord(line, time, "DEBUG", kind, from, to, protocol, command, arguments, reply);
    }
}
