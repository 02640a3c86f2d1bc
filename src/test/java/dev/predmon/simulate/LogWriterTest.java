package dev.predmon.simulate;

import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.io.StringWriter;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The written text: reproducibility, the record layout, the sidecar's violation time and the format flags. */
class LogWriterTest {

    private static final SimOptions DEFAULTS = SimOptions.defaults();

    private static String text(Scenario s, long seed, SimOptions o) {
        return LogWriter.toText(Simulator.run(s, seed, o), o);
    }

    @Test
    void sameSeedSameBytesDifferentSeedsDifferentLogs() throws IOException {
        SimOptions all = DEFAULTS.withLateReplies(0.3).withRawLines(true).withEpoch(true);
        for (Scenario s : Scenario.values()) {
            for (long seed = 1; seed <= 5; seed++) {
                String a = text(s, seed, all);
                StringWriter w = new StringWriter();
                LogWriter.write(Simulator.run(s, seed, all), all, w);
                assertEquals(a, w.toString());
                assertNotEquals(a, text(s, seed + 1, all));
            }
        }
    }

    @Test
    void recordLayoutMatchesTheMonitor() {
        String text = text(Scenario.DIRECT, 3, DEFAULTS);
        String[] lines = text.split("\n", -1);
        assertEquals("", lines[lines.length - 1], "ends with a newline");
        assertEquals(0, (lines.length - 1) % 7);
        assertTrue(lines[0].matches("\\d+\\.\\d{6}\tDEBUG\tTick intercepted:"), lines[0]);
        assertTrue(text.contains("\tDEBUG\tCommand intercepted:\n  From      : /BatteryReaderBatteryLevelClient\n"
                + "  To        : /BatteryComponent\n  Protocol  : BatteryReader\n  Command   : level\n"
                + "  Arguments : \n  Reply     : \n"));
        assertTrue(text.contains("  From      : /GoToComponent\n  To        : /GoToGoToClient/kitchen\n"
                + "  Protocol  : GoTo\n  Command   : getStatus\n  Arguments : kitchen\n  Reply     : 1\n"));
        assertTrue(text.contains("  From      : /GoToDestination/BT_rpc/client\n"));
        assertFalse(text.contains("\r"));
    }

    @Test
    void goToReplyIsEmptyOrEchoesTheDestination() {
        int echoes = 0;
        for (SimRun run : Runs.of(Scenario.DIRECT).subList(0, 40)) {
            for (Runs.Rec r : Runs.read(LogWriter.toText(run, DEFAULTS))) {
                if (r.kind().equals("Reply") && r.command().equals("goTo")) {
                    boolean echo = run.truth().parameters().goToEchoesDestination();
                    assertEquals(echo ? "" : "kitchen", r.args());
                    assertEquals(echo ? "kitchen" : "", r.reply());
                    echoes += echo ? 1 : 0;
                }
            }
        }
        assertTrue(echoes > 0);
    }

    @Test
    void doublesArePrintedLikeYarp() {
        assertEquals("100.0", LogWriter.formatDouble(100.0));
        assertEquals("0.0", LogWriter.formatDouble(0.0));
        assertEquals("97.316999999987189085", LogWriter.formatDouble(97.31699999998719));
        assertEquals("0.100000000000000005551", LogWriter.formatDouble(0.1));
        assertEquals("72.125394", LogWriter.formatTime(72_125_394));
        assertEquals("0.000042", LogWriter.formatTime(42));
    }

    @Test
    void sidecarViolationTimeIsTheFirstLevelReplyBelow20InTheText() {
        for (Scenario s : Scenario.values()) {
            for (SimRun run : Runs.of(s).subList(0, 30)) {
                Double expected = null;
                Double level = null;
                for (Runs.Rec r : Runs.read(LogWriter.toText(run, DEFAULTS))) {
                    if (r.kind().equals("Reply") && r.command().equals("level")
                            && Double.parseDouble(r.reply()) < 20.0) {
                        expected = r.time();
                        level = Double.parseDouble(r.reply());
                        break;
                    }
                }
                assertEquals(expected, run.truth().violationTime(), s + " seed " + run.seed());
                assertEquals(level, run.truth().violationLevel());
                if (!s.faulty()) {
                    assertNull(expected);
                }
            }
        }
    }

    @Test
    void lateRepliesStayBeforeTheNextCommandOfTheirConnection() {
        SimOptions late = DEFAULTS.withLateReplies(0.5);
        int printedLate = 0;
        for (Scenario s : Scenario.values()) {
            for (SimRun run : Runs.of(s).subList(0, 10)) {
                List<Runs.Rec> recs = Runs.read(LogWriter.toText(run, late));
                assertEquals(run.events().size(), recs.size());
                Map<String, Runs.Rec> open = new HashMap<>();
                double latest = 0;
                for (Runs.Rec r : recs) {
                    String connection = r.client() + " -> " + r.server();
                    if (r.kind().equals("Command")) {
                        assertNull(open.put(connection, r), "unanswered command before " + r);
                    } else if (r.kind().equals("Reply")) {
                        Runs.Rec c = open.remove(connection);
                        assertTrue(c != null && c.command().equals(r.command()), "reply without command " + r);
                        assertTrue(r.time() > c.time());
                        printedLate += r.time() < latest ? 1 : 0;
                    }
                    latest = Math.max(latest, r.time());
                }
                assertTrue(open.isEmpty());
            }
        }
        assertTrue(printedLate > 100, "late replies printed: " + printedLate);
    }

    @Test
    void epochShiftsTheSameRun() {
        SimRun rel = Simulator.run(Scenario.RECHARGE, 7, DEFAULTS);
        SimRun epo = Simulator.run(Scenario.RECHARGE, 7, DEFAULTS.withEpoch(true));
        assertEquals(rel.events().size(), epo.events().size());
        long shift = epo.events().get(0).timeMicros() - rel.events().get(0).timeMicros();
        assertTrue(shift >= 1_600_000_000_000_000L);
        for (int i = 0; i < rel.events().size(); i++) {
            assertEquals(rel.events().get(i).timeMicros() + shift, epo.events().get(i).timeMicros());
        }
        List<Runs.Rec> recs = Runs.read(LogWriter.toText(epo, epo.options()));
        assertTrue(recs.get(0).time() > 1.6e9 && recs.get(0).timeText().matches("\\d{10}\\.\\d{6}"));
        assertTrue(rel.events().get(0).time() < 10);
    }

    @Test
    void rawLinesPrecedeEveryRecord() {
        SimRun run = Simulator.run(Scenario.DIRECT, 2, DEFAULTS);
        String[] lines = LogWriter.toText(run, DEFAULTS.withRawLines(true)).split("\n", 0);
        assertEquals(run.events().size() * 8, lines.length);
        for (int i = 0; i < lines.length; i += 8) {
            String time = lines[i].substring(0, lines[i].indexOf('\t'));
            assertTrue(lines[i].matches("[\\d.]+\tINFO\t\"/[^\"]+\" \"/[^\"]+\" \"(command|reply|tick)\" \"\\w*\" "
                    + "\\(\\w+\\) \\([\\w.]*\\) \\([\\w.]*\\)"), lines[i]);
            assertTrue(lines[i + 1].startsWith(time + "\tDEBUG\t"), lines[i + 1]);
        }
        assertTrue(LogWriter.toText(run, DEFAULTS.withRawLines(true)).contains(
                "\tINFO\t\"/GoToGoToClient/kitchen\" \"/GoToComponent\" \"command\" \"GoTo\" (getStatus) (kitchen) ()"));
    }

    @Test
    void vocabChangesOnlyIsAtLocationReplies() {
        SimRun run = Simulator.run(Scenario.RECHARGE, 4, DEFAULTS);
        List<Runs.Rec> plain = Runs.read(LogWriter.toText(run, DEFAULTS));
        List<Runs.Rec> vocab = Runs.read(LogWriter.toText(run, DEFAULTS.withVocab(true)));
        boolean sawTrue = false;
        for (int i = 0; i < plain.size(); i++) {
            Runs.Rec p = plain.get(i);
            Runs.Rec v = vocab.get(i);
            if (p.kind().equals("Reply") && p.command().equals("isAtLocation")) {
                assertEquals(p.reply().equals("1") ? "27503" : "1818845542", v.reply());
                sawTrue |= p.reply().equals("1");
            } else {
                assertEquals(p, v);
            }
        }
        assertTrue(sawTrue);
    }

    @Test
    void crlfAndSpacesChangeOnlyTheLayout() {
        SimRun run = Simulator.run(Scenario.DEPLETED, 5, DEFAULTS);
        String plain = LogWriter.toText(run, DEFAULTS);
        String crlf = LogWriter.toText(run, DEFAULTS.withCrlf(true));
        assertEquals(plain, crlf.replace("\r\n", "\n"));
        assertFalse(crlf.replace("\r\n", "").contains("\n"));
        String spaces = LogWriter.toText(run, DEFAULTS.withSpaces(true));
        assertFalse(spaces.contains("\t"));
        assertEquals(plain, spaces.replaceAll("(?m)^([\\d.]+) (\\w+) ", "$1\t$2\t"));
        assertEquals(Runs.read(plain), Runs.read(spaces));
    }
}
