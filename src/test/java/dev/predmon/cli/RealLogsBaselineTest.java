package dev.predmon.cli;

import dev.predmon.support.RealLogs;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * On the public recordings of the real monitor (where {@code ../shared/real-logs} exists), 5-fold and leave-one-out:
 * {@code evaluate} prints every property's warnings beside its baseline's on the same held-out runs (the battery
 * beside the raw-value rule, each deadline beside the elapsed-time rule), and the default rule is at least its
 * baseline for each: it warns at least as many violations ahead, and where it warns no more, it raises no more false
 * alarms and has no shorter median lead.
 *
 * <p>Leave-one-out learns once per recording; it runs with {@code -Dpredmon.real-logs.loo=true} (some minutes).
 */
class RealLogsBaselineTest {

    /** One rule's figures on the judged runs: violations warned ahead, false alarms, median lead (NaN: none). */
    record Figures(String property, int warned, int violating, int alarms, double lead) {

        /** Whether these are at least {@code base}'s: recall first, then false alarms, then the lead. */
        boolean atLeast(Figures base) {
            if (warned != base.warned) {
                return warned > base.warned;
            }
            if (alarms != base.alarms) {
                return alarms < base.alarms;
            }
            return Double.isNaN(base.lead) || (!Double.isNaN(lead) && lead >= base.lead);
        }
    }

    private static final Pattern SAFETY = Pattern.compile("\n  (the forecast's warning rule|raw value: warn below[^\n]*?)"
            + " +(\\d+) of (\\d+) violations warned ahead, (\\d+) of \\d+ false alarms, lead median (\\S+)");
    private static final Pattern OTHER = Pattern.compile("\n(\\S+) +\\d+ +\\d+ +(\\d+) +(\\d+) +(\\d+) +(\\S+) +(\\d+)"
            + " +(\\d+) +(\\S+)\n");

    @Test
    void fiveFoldsEveryPropertyAtLeastItsBaseline() throws Exception {
        judged("5");
    }

    @Test
    void leaveOneOutEveryPropertyAtLeastItsBaseline() throws Exception {
        int logs = RealLogs.rows().size();
        org.junit.jupiter.api.Assumptions.assumeTrue(Boolean.getBoolean("predmon.real-logs.loo"),
                "skipped: leave-one-out learns " + logs + " times; run with -Dpredmon.real-logs.loo=true");
        judged(Integer.toString(logs));
    }

    private static void judged(String folds) throws Exception {
        RealLogs.rows();
        Cli r = Cli.run("evaluate", "--logs", RealLogs.DIR.toString(), "--abstraction", "scope-fetch", "--folds",
                folds, "--quiet");
        assertEquals(0, r.code(), r.err());
        List<Figures[]> pairs = new ArrayList<>();
        Matcher s = SAFETY.matcher(r.out());
        assertTrue(s.find(), r.out());
        Figures rule = figures("battery", s.group(2), s.group(3), s.group(4), s.group(5));
        assertTrue(s.find(), r.out());
        Figures base = figures("battery", s.group(2), s.group(3), s.group(4), s.group(5));
        pairs.add(new Figures[] {rule, base});
        Matcher o = OTHER.matcher(r.out());
        int from = 0;
        while (o.find(from)) {
            pairs.add(new Figures[] {figures(o.group(1), o.group(3), o.group(2), o.group(4), o.group(5)),
                figures(o.group(1), o.group(6), o.group(2), o.group(7), o.group(8))});
            from = o.end() - 1;
        }
        assertTrue(pairs.size() >= 4, "the battery and the scope-fetch deadlines: " + r.out());
        System.out.println("real recordings, evaluate --folds " + folds + ": default rule | baseline");
        for (Figures[] p : pairs) {
            System.out.printf("  %-20s warned %d of %d, %d false alarm(s), lead %s | warned %d, %d false alarm(s), "
                    + "lead %s%n", p[0].property(), p[0].warned(), p[0].violating(), p[0].alarms(), p[0].lead(),
                    p[1].warned(), p[1].alarms(), p[1].lead());
        }
        for (Figures[] p : pairs) {
            assertTrue(p[0].atLeast(p[1]), p[0] + " against its baseline " + p[1] + "\n" + r.out());
        }
        assertFalse(r.out().contains("baseline (deadlines)"), "every property's baseline is named");
    }

    private static Figures figures(String property, String warned, String violating, String alarms, String lead) {
        return new Figures(property, Integer.parseInt(warned), Integer.parseInt(violating), Integer.parseInt(alarms),
                lead.equals("-") ? Double.NaN : Double.parseDouble(lead));
    }
}
