package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.support.HandRuns;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.DoubleUnaryOperator;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Times that go backwards are accepted: the monitor prints late replies out of time order legitimately, and a
 * clock can be reset. Decisions follow the order of the log, never its times, so every record is processed, the
 * verdict is that of the same log with sane times, and a warning carries the time of the record that raised it.
 */
class BackwardTimesCliTest {

    private static final Pattern TIME = Pattern.compile("(?m)^(-?\\d+\\.\\d+)\\t");

    @TempDir
    Path tmp;
    Path models;

    @BeforeEach
    void learn() throws Exception {
        Path logs = tmp.resolve("logs");
        models = tmp.resolve("models");
        CliEndToEndTest.learnHandRuns(logs, models, "recharge");
    }

    /** The depleted run with every record's time mapped by {@code f}. */
    private static String depletedWithTimes(DoubleUnaryOperator f) {
        Matcher m = TIME.matcher(HandRuns.depleted().text());
        StringBuilder sb = new StringBuilder();
        while (m.find()) {
            m.appendReplacement(sb, String.format(Locale.ROOT, "%.6f\t", f.applyAsDouble(Double.parseDouble(m.group(1)))));
        }
        return m.appendTail(sb).toString();
    }

    private List<JsonNode> watchJson(String text) throws Exception {
        Path log = Files.writeString(tmp.resolve("run.log"), text);
        Cli r = Cli.run("watch", "--log", log.toString(), "--models", models.toString(), "--no-follow", "--json");
        assertEquals(ExitCodes.WARNING, r.code(), "the same verdict as with sane times: " + r.err() + r.out());
        assertTrue(r.err().isEmpty(), "nothing to complain about: " + r.err());
        List<JsonNode> events = new ArrayList<>();
        for (String line : r.out().split("\n", 0)) {
            events.add(new ObjectMapper().readTree(line));
        }
        return events;
    }

    private static JsonNode event(List<JsonNode> events, String name) {
        return events.stream().filter(e -> e.get("event").asText().equals(name)).findFirst().orElseThrow();
    }

    /** The time printed on the header at {@code line} of {@code text}. */
    private static double timeAtLine(String text, long line) {
        String header = text.lines().skip(line - 1).findFirst().orElseThrow();
        return Double.parseDouble(header.substring(0, header.indexOf('\t')));
    }

    @Test
    void aLogWhoseTimesRunBackwardsIsFullyProcessed() throws Exception {
        List<JsonNode> sane = watchJson(HandRuns.depleted().text());
        String text = depletedWithTimes(t -> 1000 - t); // every record earlier than the one before it
        List<JsonNode> events = watchJson(text);
        JsonNode end = event(events, "end");
        assertEquals(HandRuns.depleted().list().size(), end.get("records").asInt(), "every record processed");
        assertEquals(event(sane, "end").get("pairs"), end.get("pairs"));
        JsonNode warning = event(events, "warning");
        assertEquals(event(sane, "warning").get("line"), warning.get("line"), "raised by the same record");
        assertEquals(timeAtLine(text, warning.get("line").asLong()), warning.get("time").asDouble(), 1e-9,
                "the warning's time is that of the record that raised it");
    }

    @Test
    void negativeTimesAndAClockResetMidRunAreFullyProcessed() throws Exception {
        List<JsonNode> sane = watchJson(HandRuns.depleted().text());
        String text = depletedWithTimes(t -> t < 35 ? t - 1000 : t - 2000); // negative, and jumping back at t=35
        List<JsonNode> events = watchJson(text);
        assertEquals(HandRuns.depleted().list().size(), event(events, "end").get("records").asInt());
        JsonNode warning = event(events, "warning");
        assertEquals(event(sane, "warning").get("line"), warning.get("line"));
        assertTrue(warning.get("time").asDouble() < 0, warning.toString());
        assertEquals(timeAtLine(text, warning.get("line").asLong()), warning.get("time").asDouble(), 1e-9);
        JsonNode violation = event(events, "violation");
        assertEquals(timeAtLine(text, violation.get("line").asLong()), violation.get("time").asDouble(), 1e-9);
    }
}
