package dev.predmon.report;

import org.junit.jupiter.api.Test;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.Arrays;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The terminal's per-run table: verdicts in words, times from the start of the run, folders, aligned columns. */
class TextReportTest {

    private static List<String> runLines() {
        StringWriter s = new StringWriter();
        try (PrintWriter out = new PrintWriter(s)) {
            TextReport.print(out, JudgedRuns.evaluation(JudgedRuns.oneOfEach()));
        }
        List<String> lines = Arrays.asList(s.toString().split("\n"));
        return lines.subList(lines.indexOf("times from the start of each run") + 1, lines.size());
    }

    @Test
    void eachRunReadsInWordsWithItsFolderAndTimesFromItsStart() {
        List<String> rows = runLines();
        assertEquals(7, rows.size(), String.join("\n", rows));
        assertTrue(rows.get(1).startsWith("depleted/depleted-1.log "), rows.get(1));
        assertTrue(rows.get(1).contains("warned ahead") && rows.get(1).contains("23.5 s")
                && rows.get(1).contains("27.4 s") && rows.get(1).contains("3.9 s"), rows.get(1));
        assertTrue(rows.get(2).contains("warned too late") && rows.get(2).contains("warned at the violation"));
        assertTrue(rows.get(3).contains("violated without warning"), rows.get(3));
        assertTrue(rows.get(4).contains("false alarm") && rows.get(4).contains("no model matched from 25.0 s"));
        assertTrue(rows.get(5).startsWith("recharge/recharge-1.log ") && rows.get(5).contains("no model matches"),
                rows.get(5));
        assertTrue(rows.get(6).contains("held"), rows.get(6));
        for (String r : rows) {
            assertFalse(r.matches(".*\\d{7,}.*"), "an epoch time in " + r);
            assertFalse(r.contains("quiet"), r);
        }
    }

    @Test
    void columnsLineUp() {
        List<String> rows = runLines();
        // Right-aligned columns end where their header ends; left-aligned ones start where it starts.
        String header = rows.get(0);
        int verdict = header.indexOf("verdict");
        int leadEnd = header.indexOf("lead") + "lead".length();
        for (String r : rows.subList(1, rows.size())) {
            assertEquals(' ', r.charAt(verdict - 1), r);
            assertTrue(Character.isLetter(r.charAt(verdict)), r);
            assertTrue(r.charAt(leadEnd - 1) == 's' || r.charAt(leadEnd - 1) == '—', r);
            assertEquals(' ', r.charAt(leadEnd), r);
        }
    }

    @Test
    void theRunNumberOfALogOfSeveralRunsHasAColumn() {
        String row = runLines().get(5);
        assertTrue(row.matches("recharge/recharge-1\\.log +1 .*"), row);
    }
}
