package dev.predmon.monitor;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.learn.Learning;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The runs the chaos soak writes, each watched alone first to know what it gives: simulated runs, a run whose battery
 * sensor flaps at the floor, and a run whose robot freezes for {@value #FREEZE_SECONDS} s in the middle of a
 * navigation due within {@value #DEADLINE_SECONDS} s. The models are learned from {@code sample-logs/} with the
 * thesis's abstraction, its navigation deadline in seconds.
 */
final class ChaosRuns {

    static final int DEADLINE_SECONDS = 45;
    static final int FREEZE_SECONDS = 40;

    /** A run: its text, its records, and the warnings and violations it gives watched alone. */
    record Run(String kind, String text, long records, int warnings, int violations, List<String> violated) {
    }

    final Abstraction abstraction;
    final ModelSet models;
    /** Simulated runs, the freeze among them. */
    final List<Run> pool = new ArrayList<>();
    final Run flapping;
    final Run freeze;

    ChaosRuns(Path dir) throws Exception {
        abstraction = secondsDeadline();
        Path learned = dir.resolve("models");
        Learning.learnAndWrite(Path.of("sample-logs"), learned, abstraction, s -> { });
        models = ModelStore.read(learned, abstraction);
        long seed = 7001;
        for (Scenario s : List.of(Scenario.DEPLETED, Scenario.RECHARGE, Scenario.DEPLETED, Scenario.DIRECT,
                Scenario.DEPLETED, Scenario.RECHARGE)) {
            pool.add(alone(dir, "simulated", simulated(s, seed++)));
        }
        flapping = alone(dir, "flapping", flap(simulated(Scenario.DEPLETED, 7101)));
        freeze = alone(dir, "freeze", freeze(simulated(Scenario.DIRECT, 7001)));
        pool.add(freeze);
        // by hand: the deadline passed in the silence is violated once, at the first record after it
        assertEquals(1, freeze.violated().stream().filter("navigation-in-time"::equals).count(), freeze.violated()
                .toString());
        // every crossing of the floor violates it and raises the alarm again (17 crossings)
        assertTrue(flapping.violations() >= 15 && flapping.warnings() >= 15, "flapping: " + flapping.warnings()
                + " warnings, " + flapping.violations() + " violations");
    }

    /** The thesis's abstraction, its navigation due within {@value #DEADLINE_SECONDS} seconds. */
    private static Abstraction secondsDeadline() throws Exception {
        ObjectMapper json = new ObjectMapper();
        ObjectNode a = (ObjectNode) json.readTree(AbstractionFiles.builtinJson("thesis").orElseThrow());
        a.put("name", "thesis-seconds");
        for (JsonNode p : a.get("properties")) {
            if (p.get("id").asText().equals("navigation-in-time")) {
                ((ObjectNode) p).put("name", "a navigation ends within " + DEADLINE_SECONDS + " seconds");
                ((ObjectNode) p).putObject("within").put("seconds", DEADLINE_SECONDS);
            }
        }
        return AbstractionFiles.fromJson("thesis-seconds", a.toString());
    }

    private static String simulated(Scenario s, long seed) {
        return LogWriter.toText(Simulator.run(s, seed, SimOptions.defaults()), SimOptions.defaults());
    }

    /** From the first battery reading under 20.5 on, every reading alternates 19.9 and 20.1: a sensor at the floor. */
    static String flap(String text) {
        String[] lines = text.split("\n", -1);
        boolean flapping = false;
        int n = 0;
        for (int i = 0; i + 6 < lines.length; i++) {
            if (lines[i].endsWith("Reply intercepted:") && lines[i + 4].equals("  Command   : level")) {
                double value = Double.parseDouble(lines[i + 6].substring(lines[i + 6].indexOf(':') + 1).strip());
                flapping |= value < 20.5;
                if (flapping) {
                    lines[i + 6] = "  Reply     : " + (n++ % 2 == 0 ? "19.900000" : "20.100000");
                }
            }
        }
        assertTrue(n > 30, "the sensor flaps " + n + " times");
        return String.join("\n", lines);
    }

    /**
     * The robot freezes 6 s after the first goTo, for {@value #FREEZE_SECONDS} s: every time stamp from there on moves
     * that much later. The navigation (44.2 s in the simulated run) is then still under way past its deadline. The
     * silence lies in the first half of the run, before the soak's writer renames a log under it.
     */
    static String freeze(String text) {
        String[] lines = text.split("\n", -1);
        double goTo = Double.NaN;
        int frozeAt = -1;
        for (int i = 0; i + 4 < lines.length; i++) {
            double t = ChaosWriter.time(lines[i] + "\n");
            if (Double.isNaN(t)) {
                continue;
            }
            if (Double.isNaN(goTo) && lines[i].endsWith("Command intercepted:")
                    && lines[i + 4].equals("  Command   : goTo")) {
                goTo = t;
            }
            if (!Double.isNaN(goTo) && t >= goTo + 6) {
                frozeAt = frozeAt < 0 ? i : frozeAt;
                lines[i] = String.format(Locale.ROOT, "%.6f", t + FREEZE_SECONDS) + lines[i].substring(
                        lines[i].indexOf('\t'));
            }
        }
        assertTrue(frozeAt > 0 && frozeAt < lines.length / 2, "frozen at line " + frozeAt + " of " + lines.length);
        return String.join("\n", lines);
    }

    /** Watches {@code text} alone, from a file of its own. */
    private Run alone(Path dir, String kind, String text) throws Exception {
        Path file = Files.writeString(dir.resolve("alone-" + kind + "-" + pool.size() + ".log"), text);
        int[] events = new int[2];
        List<String> violated = new ArrayList<>();
        PredictiveMonitor m = new PredictiveMonitor(models, abstraction, 0, abstraction.confirm(), e -> {
            if (e instanceof MonitorEvent.Warning) {
                events[0]++;
            } else if (e instanceof MonitorEvent.Violation v) {
                events[1]++;
                violated.add(v.property());
            }
        });
        try (LogWatcher w = new LogWatcher(file, m, p -> { })) {
            w.drain();
        }
        return new Run(kind, text, m.records(), events[0], events[1], violated);
    }
}
