package dev.predmon.report;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.evaluate.Evaluation;
import dev.predmon.evaluate.Evaluator;
import dev.predmon.evaluate.Progress;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.support.SimulatedSets;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * The evaluate report as a reader sees it (issue 12): rendered in headless Chromium, no two texts of any drawing
 * on the page overlap, in the charts or in the drawn machines, and the machines drawn are every shipped model's
 * ({@code models/*.dot}), folded and in full. Skipped, with a message, where no Chromium is installed.
 */
class ReportInChromiumTest {

    @TempDir
    static Path dir;
    static Path chromium;

    @BeforeAll
    static void findChromium() {
        chromium = HeadlessChromium.find().orElse(null);
    }

    private static void assumeChromium() {
        assumeTrue(chromium != null, "no chromium or chromium-browser on PATH, so the report is not rendered "
                + "(Debian: apt-get install chromium); MachineLayoutTest still checks the layouts");
    }

    @Test
    void noTextOverlapsAnotherInTheRenderedReportWithEveryShippedModel() throws Exception {
        assumeChromium();
        Path logs = SimulatedSets.write(dir.resolve("logs"), 2, 1);
        Evaluation e = new Evaluator(Abstraction.defaults(), 0, Progress.NONE)
                .crossValidate(ScenarioLayout.scan(logs, Abstraction.defaults()), 2);
        ModelSet shipped = ModelStore.read(Path.of("models"), Abstraction.defaults());
        Evaluation withShipped = new Evaluation(e.mode(), e.folds(), e.threshold(), e.abstraction(), e.scenarios(),
                e.confusion(), e.runs(), e.notes(), shipped);
        String html = HtmlReport.html(withShipped, Abstraction.defaults());

        HeadlessChromium.Measured m = HeadlessChromium.measure(chromium, html, Files.createDirectories(dir.resolve("a")));

        assertEquals(List.of(), m.overlaps(), "overlapping texts (svg, text, text)");
        int drawings = 0;
        for (var model : shipped.models()) {
            drawings += MachineGraph.folded(model).hidden() > 0 ? 2 : 1;
        }
        int charts = e.runs().size() + (e.runs().stream().anyMatch(r -> r.lead() != null) ? 1 : 0);
        assertEquals(drawings + charts, m.svgs(), "every chart and machine drawing rendered");
        // Every label and state name of every machine, plus the charts' texts, was measured.
        long machineTexts = shipped.models().stream().mapToLong(model -> texts(MachineGraph.folded(model))
                + (MachineGraph.folded(model).hidden() > 0 ? texts(MachineGraph.full(model)) : 0)).sum();
        assertTrue(m.texts() > machineTexts, m.texts() + " texts measured, the machines alone have " + machineTexts);
    }

    @Test
    void theCheckFindsTheOverlappingLabelsOfTheDrawingBeforeIssue12() throws Exception {
        assumeChromium();
        String old = Files.readString(Path.of("src/test/resources/report/old-recharge-2.svg"), StandardCharsets.UTF_8);
        HeadlessChromium.Measured m = HeadlessChromium.measure(chromium,
                "<!DOCTYPE html><html><body>" + old + "</body></html>", Files.createDirectories(dir.resolve("b")));
        assertEquals(1, m.svgs());
        assertTrue(m.overlaps().stream().anyMatch(o -> o.contains("batteryStatus_i / o_batteryStatus_false")
                && o.contains("batteryStatus_i / o_batteryStatus_true")), String.join("\n", m.overlaps()));
    }

    private static long texts(MachineGraph g) {
        return g.nodes().size() + g.edges().stream().mapToLong(x -> x.labels().size()).sum();
    }
}
