package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Runs no learned model fits, never in training: a tour to a new place ({@code --new-location}) and a navigation
 * that aborts ({@code --aborts}). On them the battery's default rule warns every violation the raw-value rule warns
 * ahead, at least as early, and raises no more false alarms: where no model matches, the forecast falls back to a
 * rule at least as good as its baseline, and no clause (the matching's "only faulty") warns on its own where it did
 * no better on the held-out folds.
 */
class NovelRunsBaselineTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path tmp;

    @Test
    void novelRunsAreWarnedAtLeastWhereTheRawValueRuleWarns() throws Exception {
        Path train = tmp.resolve("train");
        for (String s : List.of("direct", "recharge", "depleted")) {
            BoundForecastCliTest.simulate(tmp, s, "300", "--runs", "8", "--out-dir", train.resolve(s).toString());
        }
        int violating = 0;
        int ruleAlarms = 0;
        int rawAlarms = 0;
        for (String[] novelty : List.of(new String[] {"--new-location", "office"}, new String[] {"--aborts", "1"})) {
            Path test = tmp.resolve(novelty[0].substring(2));
            for (String s : List.of("direct", "recharge", "depleted")) {
                BoundForecastCliTest.simulate(tmp, s, "9000", "--runs", "6", novelty[0], novelty[1], "--out-dir",
                        test.resolve(s).toString());
            }
            Cli r = Cli.run("evaluate", "--logs", train.toString(), "--test", test.toString(), "--quiet", "--json");
            assertEquals(0, r.code(), r.err());
            JsonNode runs = JSON.readTree(r.out()).get("runs");
            assertEquals(18, runs.size(), r.out());
            for (JsonNode run : runs) {
                JsonNode raw = run.get("forecast").get("valueRule");
                JsonNode warning = run.get("warningTime");
                JsonNode violation = run.get("violationTime");
                if (violation.isNull()) {
                    rawAlarms += raw.isNull() ? 0 : 1;
                    ruleAlarms += warning.isNull() ? 0 : 1;
                    continue;
                }
                violating++;
                if (!raw.isNull() && raw.asDouble() < violation.asDouble()) {
                    assertTrue(!warning.isNull() && warning.asDouble() <= raw.asDouble(),
                            "the raw value warned " + run.get("log") + " at " + raw + ", the rule at " + warning);
                }
            }
        }
        assertTrue(violating >= 12, "the depleted runs violate: " + violating);
        assertTrue(ruleAlarms <= rawAlarms, ruleAlarms + " false alarms against the raw value's " + rawAlarms);
        System.out.printf("novel runs: %d violating; false alarms: default rule %d, raw value %d%n", violating,
                ruleAlarms, rawAlarms);
    }
}
