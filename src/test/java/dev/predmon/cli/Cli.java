package dev.predmon.cli;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import picocli.CommandLine;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicInteger;

import static org.junit.jupiter.api.Assertions.assertFalse;

/** Runs predmon's command line in-process and captures what it prints. */
record Cli(int code, String out, String err) {

    private static final ObjectMapper JSON = new ObjectMapper();

    static Cli run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        int code = cl.execute(args);
        return new Cli(code, out.toString(), err.toString());
    }

    /** The output as {@code --json} commands print it, one JSON value per line (blank lines skipped). */
    List<JsonNode> jsonLines() throws JsonProcessingException {
        List<JsonNode> values = new ArrayList<>();
        for (String line : out.split("\n", -1)) {
            if (!line.isBlank()) {
                values.add(JSON.readTree(line));
            }
        }
        return values;
    }

    /** The first of {@code events} (as {@link #jsonLines} reads them) whose "event" field is {@code kind}. */
    static Optional<JsonNode> firstEvent(List<JsonNode> events, String kind) {
        return events.stream().filter(e -> e.get("event").asText().equals(kind)).findFirst();
    }

    /**
     * A command running in-process on a thread of its own (watch, which runs until stopped), its output captured
     * as it comes; {@code code} is -1 until it ends.
     */
    record Running(Thread thread, StringWriter out, StringWriter err, AtomicInteger code) {

        /** Interrupts it, the in-process way to stop watch, and waits for it to end. */
        void stop() throws InterruptedException {
            thread.interrupt();
            thread.join(10_000);
            assertFalse(thread.isAlive(), "stops when interrupted");
        }
    }

    /** Starts the command line on its own thread; see {@link Running}. */
    static Running start(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        AtomicInteger code = new AtomicInteger(-1);
        Thread t = new Thread(() -> code.set(cl.execute(args)), args.length > 0 ? args[0] : "predmon");
        t.start();
        return new Running(t, out, err, code);
    }
}
