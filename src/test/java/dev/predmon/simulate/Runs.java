package dev.predmon.simulate;

import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** Test fixtures: the default runs of seeds 1..200, simulated once per JVM, and a minimal log reader. */
final class Runs {

    static final int SEEDS = 200;

    private static final Map<Scenario, List<SimRun>> CACHE = new EnumMap<>(Scenario.class);

    private Runs() {
    }

    static synchronized List<SimRun> of(Scenario s) {
        return CACHE.computeIfAbsent(s, k -> {
            List<SimRun> runs = new ArrayList<>();
            for (long seed = 1; seed <= SEEDS; seed++) {
                runs.add(Simulator.run(k, seed, SimOptions.defaults()));
            }
            return List.copyOf(runs);
        });
    }

    /** A DEBUG record read back from written text. */
    record Rec(String timeText, String kind, String from, String to, String protocol, String command, String args,
               String reply) {
        double time() {
            return Double.parseDouble(timeText);
        }

        String client() {
            return kind.equals("Reply") ? to : from;
        }

        String server() {
            return kind.equals("Reply") ? from : to;
        }
    }

    private static final Pattern HEAD = Pattern.compile("^(\\d+\\.\\d{6})[\\t ]DEBUG[\\t ](\\w+) intercepted:$");
    private static final Pattern FIELD = Pattern.compile("^  (\\w+) *: (.*)$");

    /** Reads the DEBUG records of a log written with {@code \n} or {@code \r\n}, skipping INFO lines. */
    static List<Rec> read(String text) {
        String[] lines = text.split("\r?\n", -1);
        List<Rec> out = new ArrayList<>();
        for (int i = 0; i < lines.length; i++) {
            Matcher h = HEAD.matcher(lines[i]);
            if (!h.matches()) {
                continue;
            }
            String[] v = new String[6];
            String[] labels = {"From", "To", "Protocol", "Command", "Arguments", "Reply"};
            for (int f = 0; f < 6; f++) {
                Matcher m = FIELD.matcher(lines[i + 1 + f]);
                if (!m.matches() || !m.group(1).equals(labels[f])) {
                    throw new AssertionError("line " + (i + 2 + f) + ": expected " + labels[f] + ", got '"
                            + lines[i + 1 + f] + "'");
                }
                v[f] = m.group(2);
            }
            out.add(new Rec(h.group(1), h.group(2), v[0], v[1], v[2], v[3], v[4], v[5]));
            i += 6;
        }
        return out;
    }
}
