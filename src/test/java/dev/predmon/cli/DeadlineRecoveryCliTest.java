package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A navigation that outlasts every training one is warned, and its alarm ends when the robot arrives: watch prints the
 * deadline's warning, its forecast events as they change, then a {@code recovered} event naming the property, and the
 * hooks hear both; the end summary gives each property's verdict with its latest forecast. With the shipped models,
 * whose 30 training navigations from the start to the kitchen took 4 to 285 ticks, against the 400-tick deadline.
 */
class DeadlineRecoveryCliTest {

    @TempDir
    Path dir;

    private static String record(String kind, String from, String to, String protocol, String command, String args,
                                 String reply) {
        return String.format(Locale.ROOT, "[DEBUG] %s intercepted:%n  From      : %s%n  To        : %s%n"
                + "  Protocol  : %s%n  Command   : %s%n  Arguments : %s%n  Reply     : %s%n", kind, from, to, protocol,
                command, args, reply);
    }

    /** A console capture: a tick and a battery reading each tick, a goTo at tick 2 that arrives at tick 352. */
    private static String lateArrival() {
        StringBuilder b = new StringBuilder("[INFO] |yarp.os.Port| Port /monitor active at tcp://192.168.1.10:10031/\n");
        for (int t = 1; t <= 360; t++) {
            b.append(record("Tick", "/tick/monitor", "/monitor", "Tick", "", Integer.toString(t), ""));
            b.append(record("Command", "/BatteryReaderBatteryLevelClient", "/BatteryComponent", "BatteryReader",
                    "level", "", ""));
            b.append(record("Reply", "/BatteryComponent", "/BatteryReaderBatteryLevelClient", "BatteryReader", "level",
                    "", String.format(Locale.ROOT, "%.1f", 95 - t * 0.05)));
            if (t == 2) {
                b.append(record("Command", "/GoToGoToClient/kitchen", "/GoToComponent", "GoTo", "goTo", "kitchen", ""));
                b.append(record("Reply", "/GoToComponent", "/GoToGoToClient/kitchen", "GoTo", "goTo", "kitchen", ""));
            }
            if (t == 352) {
                b.append(record("Command", "/GoToGoToClient/kitchen", "/GoToComponent", "GoTo", "getStatus", "kitchen",
                        ""));
                b.append(record("Reply", "/GoToComponent", "/GoToGoToClient/kitchen", "GoTo", "getStatus", "kitchen",
                        "2"));
            }
        }
        return b.toString();
    }

    @Test
    @Timeout(120)
    void aWarnedNavigationThatArrivesRecoversAndTheHooksHearBoth() throws Exception {
        Path log = Files.writeString(dir.resolve("late.txt"), lateArrival());
        Path heard = dir.resolve("heard.txt");
        String hook = "echo \"$PREDMON_EVENT $PREDMON_PROPERTY $PREDMON_CAUSE|$PREDMON_VALUE|$PREDMON_BATTERY\" >> "
                + heard;
        Cli r = Cli.run("watch", "--log", log.toString(), "--models", "models", "--no-follow", "--json",
                "--on-warning", hook, "--on-recovered", hook);
        ObjectMapper json = new ObjectMapper();
        List<String> told = new ArrayList<>();
        JsonNode end = null;
        for (String line : r.out().lines().toList()) {
            JsonNode e = json.readTree(line);
            String kind = e.get("event").asText();
            if ("navigation-in-time".equals(e.path("property").asText())) {
                if (!kind.equals("forecast")) {
                    // a bounded response has no value: not the battery's, which the log reads all along
                    assertTrue(e.get("value").isNull() && e.get("battery").isNull(), line);
                }
                told.add(kind + (kind.equals("forecast") ? " " + (e.get("deadline").get("novel").asBoolean() ? "novel"
                        : e.get("deadline").get("probability").asText()) : kind.equals("recovered")
                        ? " " + e.get("cause").asText() : " " + e.get("clause").asText()) + " tick "
                        + e.get("time").asInt());
            } else if (kind.equals("end")) {
                end = e;
            }
        }
        // pending from tick 2: P(miss) near 0 while training navigations were still pending (none of them missed:
        // under 2 in 100, never 0); none longer than 285 ticks: at tick 288 (286 ticks pending) it is later than 99%
        // of the training navigations that began where it did, and warned there by the late clause, 114 ticks
        // before the deadline; arrived at 352
        List<String> estimates = told.stream().filter(t -> t.startsWith("forecast ") && !t.startsWith("forecast novel"))
                .toList();
        assertTrue(estimates.get(0).endsWith(" tick 2"), told.toString());
        for (String t : estimates) {
            double p = Double.parseDouble(t.substring("forecast ".length(), t.indexOf(" tick")));
            assertTrue(p > 0 && p < 0.02, t);
        }
        assertEquals(List.of("forecast novel tick 288", "warning deadline tick 288", "recovered discharged tick 352"),
                told.stream().filter(t -> !estimates.contains(t)).toList(), r.out());
        assertTrue(end != null, r.out());
        JsonNode nav = null;
        for (JsonNode p : end.get("properties")) {
            if (p.get("property").asText().equals("navigation-in-time")) {
                nav = p;
            }
        }
        assertTrue(nav != null, end.toString());
        assertEquals("holds", nav.get("verdict").asText());
        assertEquals("deadline", nav.get("forecast").get("model").asText());
        assertEquals("no forecast: no obligation pending", nav.get("forecast").get("words").asText());
        List<String> lines = Files.readAllLines(heard);
        assertEquals(List.of("recovered navigation-in-time discharged||", "warning navigation-in-time ||"),
                lines.stream().sorted().toList(), "each hook ran once, naming the property");
    }

    @Test
    @Timeout(120)
    void aDeadlinesForecastSaysWhatItsTimeLeftCounts() throws Exception {
        Path log = Files.writeString(dir.resolve("late.txt"), lateArrival());
        Cli r = Cli.run("watch", "--log", log.toString(), "--models", "models", "--no-follow", "--eliminations");
        assertTrue(r.out().contains("forecast of navigation-in-time: P(miss) 0.00, 400 ticks left"), r.out());
        assertTrue(r.out().contains("forecast of navigation-in-time: pending longer than any training obligation, 114 "
                + "ticks left"), r.out());
    }
}
