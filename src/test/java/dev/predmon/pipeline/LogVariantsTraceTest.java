package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.compact.IoPair;
import dev.predmon.parse.LogReader;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.SimRun;
import dev.predmon.simulate.Simulator;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

/**
 * Every log layout of the README (Logs accepted) must give the same abstract trace, end to end, as the plain current
 * format: otherwise models learned from one robot's logs would not recognise another's. A run is simulated,
 * written in each layout, read back through the shared pipeline, and the compacted pairs compared.
 */
class LogVariantsTraceTest {

    private static final Abstraction A = AbstractionFiles.defaults();

    @TempDir
    Path tmp;

    /**
     * What must not depend on the layout: the compacted trace, the first safety violation (its value), and that
     * every interface message is mapped (BT-to-skill traffic dropped even without a Protocol line).
     */
    private List<String> trace(String text, String name) throws Exception {
        Path log = Files.writeString(tmp.resolve(name), text);
        LogTrace t = Traces.read(log, A);
        assertEquals(Map.of(), t.unmapped(), name + ": unmapped interface messages");
        List<String> symbols = new ArrayList<>();
        for (IoPair p : t.pairs()) {
            symbols.add(p.input() + "/" + p.output());
        }
        double[] violation = {Double.NaN};
        LogReader.read(log, r -> {
            double v = A.safety().orElseThrow().valueOf(r);
            if (Double.isNaN(violation[0]) && A.safety().orElseThrow().violatedBy(v)) {
                violation[0] = v;
            }
        }, p -> { });
        symbols.add("violation=" + violation[0]);
        return symbols;
    }

    private static List<LogRecord> records(Path log) throws Exception {
        List<LogRecord> out = new ArrayList<>();
        LogReader.read(log, out::add, p -> { });
        return out;
    }

    @ParameterizedTest
    @EnumSource(Scenario.class)
    void everyLayoutGivesTheSameTrace(Scenario scenario) throws Exception {
        SimRun run = Simulator.run(scenario, 77, SimOptions.defaults());
        SimOptions plain = SimOptions.defaults();
        String text = LogWriter.toText(run, plain);
        List<String> expected = trace(text, "plain.log");
        assertFalse(expected.size() < 2);
        assertEquals(scenario.faulty(), !expected.get(expected.size() - 1).equals("violation=NaN"));

        assertEquals(expected, trace(LogWriter.toText(run, plain.withRawLines(true)), "raw.log"), "INFO raw-bottle lines");
        assertEquals(expected, trace(LogWriter.toText(run, plain.withLateReplies(0.5)), "late.log"), "late replies");
        assertEquals(expected, trace(LogWriter.toText(run, plain.withVocab(true)), "vocab.log"), "isAtLocation vocabs");
        assertEquals(expected, trace(LogWriter.toText(run, plain.withSpaces(true)), "spaces.log"), "space columns");
        assertEquals(expected, trace(LogWriter.toText(run, plain.withCrlf(true)), "crlf.log"), "CRLF");
        SimRun epochRun = Simulator.run(scenario, 77, plain.withEpoch(true));
        assertEquals(expected, trace(LogWriter.toText(epochRun, plain.withEpoch(true)), "epoch.log"), "epoch times");

        List<LogRecord> recs = records(tmp.resolve("plain.log"));
        assertEquals(expected, trace(olderFormat(recs), "older.log"), "older 'Message received:' format");
        assertEquals(expected, trace(saveFile(recs), "save.txt"), "yarplogger save file");
    }

    /** The older monitor: no Protocol line, one kind line, all arguments and reply values on one line. */
    private static String olderFormat(List<LogRecord> recs) {
        StringBuilder sb = new StringBuilder();
        for (LogRecord r : recs) {
            String kind = r.kind() == RecordKind.COMMAND ? "Command  " : r.kind() == RecordKind.REPLY ? "Reply    " : "Tick     ";
            String values = (r.arguments() + " " + r.reply()).trim();
            sb.append(String.format(Locale.ROOT, "%.6f\tDEBUG\tMessage received:%n", r.time()))
                    .append("From : ").append(r.from()).append('\n')
                    .append("To : ").append(r.to()).append('\n')
                    .append(kind).append(": ").append(r.command()).append('\n')
                    .append("Arguments: ").append(values).append('\n');
        }
        return sb.toString();
    }

    /** yarplogger's own save file (YarpLoggerFiles.cpp): version, one port header, then entries. */
    private static String saveFile(List<LogRecord> recs) {
        StringBuilder sb = new StringBuilder();
        sb.append("1\n1\nNULL-DATA\n/log/host/monitor/1\n/monitor\nmonitor\nlog\n1\n0\n0\n0\n0\n0\n0\n")
                .append(recs.size()).append('\n').append(recs.size()).append('\n');
        long counter = 0;
        for (LogRecord r : recs) {
            String kind = switch (r.kind()) {
                case COMMAND -> "Command";
                case REPLY -> "Reply";
                case TICK -> "Tick";
                case UNKNOWN -> "Unknown";
            };
            sb.append(counter++).append('\n').append(String.format(Locale.ROOT, "%.6f", r.time())).append('\n')
                    .append("2\n<#STRING_START#>").append(kind).append(" intercepted:\n")
                    .append("  From      : ").append(r.from()).append('\n')
                    .append("  To        : ").append(r.to()).append('\n')
                    .append("  Protocol  : ").append(r.protocol()).append('\n')
                    .append("  Command   : ").append(r.command()).append('\n')
                    .append("  Arguments : ").append(r.arguments()).append('\n')
                    .append("  Reply     : ").append(r.reply()).append("<#STRING_END#>\n");
        }
        return sb.toString();
    }
}
