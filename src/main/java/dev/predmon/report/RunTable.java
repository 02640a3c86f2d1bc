package dev.predmon.report;

import dev.predmon.evaluate.RunResult;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The report's table of runs, one row per run: its log with its folder, its run number, its verdict in words with
 * what else a reader should know (no model matched from some point, a sudden violation), the warning, violation
 * and lead counted from the start of the run, its forecast, and every model's elimination with its line, time and
 * reason. The row's number and log link to the run's plot, and the plot links back, so that any run's verdict and
 * reason is one click from the top of the page.
 */
final class RunTable {

    private RunTable() {
    }

    /** The table of {@code runs}; the first {@code plotted} of them have a plot to link to. */
    static void html(StringBuilder h, List<RunView> runs, int plotted) {
        h.append("<p class=counts>").append(runs.size()).append(runs.size() == 1 ? " run: " : " runs: ")
                .append(counts(runs)).append(". Times count from the start of each run.</p>\n");
        h.append("<table class=runs><thead><tr><th>#</th><th class=l>log</th><th>run</th><th>fold</th>"
                + "<th class=l>scenario</th><th class=l>verdict</th><th>warning</th><th>violation</th><th>lead</th>"
                + "<th class=forecast>forecast<br><small>at the warning: P, time to violation; without one: highest P</small></th>"
                + "<th class=l>models eliminated: line, time, reason</th></tr></thead>\n<tbody>\n");
        for (RunView v : runs) {
            RunResult r = v.result();
            boolean linked = v.number() <= plotted;
            String link = linked ? "<a href=\"#" + v.anchor() + "\">" : "";
            String end = linked ? "</a>" : "";
            h.append("<tr id=").append(v.rowAnchor()).append(" class=").append(v.tone()).append("><td>")
                    .append(link).append(v.number()).append(end).append("</td><td class=l>").append(link)
                    .append(Svg.esc(v.log())).append(end).append("</td><td>").append(v.runText()).append("</td><td>")
                    .append(r.fold() < 0 ? RunView.NONE : Integer.toString(r.fold())).append("</td><td class=l>")
                    .append(Svg.esc(r.scenario())).append(r.faulty() ? " <small>faulty</small>" : "")
                    .append("</td><td class=\"l v\">").append(v.verdict());
            if (!v.note().isEmpty()) {
                h.append("<div class=note>").append(Svg.esc(v.note())).append("</div>");
            }
            h.append("</td><td>").append(v.at(r.warningTime())).append("</td><td>").append(v.at(r.violationTime()))
                    .append("</td><td>").append(v.duration(r.lead())).append("</td><td class=forecast>")
                    .append(Svg.esc(v.forecastText())).append("</td><td class=l>");
            eliminations(h, v);
            h.append("</td></tr>\n");
        }
        h.append("</tbody></table>\n");
    }

    private static void eliminations(StringBuilder h, RunView v) {
        List<RunResult.Elimination> gone = v.result().eliminations();
        if (gone.isEmpty()) {
            h.append(RunView.NONE);
            return;
        }
        h.append("<ol class=elim>");
        for (RunResult.Elimination x : gone) {
            h.append("<li><b>").append(Svg.esc(x.model())).append("</b> line ").append(x.line()).append(", ")
                    .append(v.at(x.time())).append(": ").append(Svg.esc(x.reason())).append("</li>");
        }
        h.append("</ol>");
    }

    /** How many runs have each verdict, in words: {@code 10 warned ahead, 1 false alarm}. */
    static String counts(List<RunView> runs) {
        Map<String, Integer> n = new LinkedHashMap<>();
        for (String verdict : List.of("warned ahead", "warned too late", "violated without warning", "false alarm",
                "no model matches", "warned, held", "held")) {
            n.put(verdict, 0);
        }
        runs.forEach(v -> n.merge(v.verdict(), 1, Integer::sum));
        StringBuilder s = new StringBuilder();
        n.forEach((verdict, count) -> {
            if (count > 0) {
                s.append(s.isEmpty() ? "" : ", ").append(count).append(' ').append(verdict);
            }
        });
        return s.toString();
    }
}
