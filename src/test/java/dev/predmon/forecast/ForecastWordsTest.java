package dev.predmon.forecast;

import org.junit.jupiter.api.Test;

import java.util.Locale;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** A forecast's words, and the numbers in them written as {@code String.format} would. */
class ForecastWordsTest {

    @Test
    void numbersReadAsStringFormatWritesThem() {
        double[] edges = {0, -0.0, 0.125, 1.005, 2.675, -0.001, -0.005, 0.5, 99.995, 100.5, 1e20, -1e-9, 33.456,
            Double.MIN_VALUE, Double.MAX_VALUE, Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (double x : edges) {
            for (int digits = 0; digits <= 3; digits++) {
                assertEquals(String.format(Locale.ROOT, "%." + digits + "f", x), ForecastWords.fixed(x, digits),
                        x + " with " + digits + " decimals");
            }
        }
        Random random = new Random(7);
        for (int i = 0; i < 20_000; i++) {
            double x = (random.nextDouble() - 0.5) * Math.pow(10, random.nextInt(8) - 3);
            int digits = random.nextInt(3);
            assertEquals(String.format(Locale.ROOT, "%." + digits + "f", x), ForecastWords.fixed(x, digits),
                    x + " with " + digits + " decimals");
        }
    }

    @Test
    void aWarningsForecastSaysHowSureHowSoonAndOnWhatEvidence() {
        Forecast f = new Forecast(0.734, 83.26, 49.61, null, Forecast.Basis.RESYNCHRONISED, 412L, 29, 10, 33.456,
                -0.1234, "s");
        assertEquals("P(violation) 0.73, about 83.3 s to the violation (49.6 s or more) [resynchronised]: 10 of 29 "
                + "training runs in the states the latest steps lead to and went as low as 33.46 violated; the value "
                + "33.46 falls 0.12 per s; novel behaviour since line 412 (matching resumed on the latest steps)",
                ForecastWords.line(f));
        Forecast g = new Forecast(0.05, 8.3, 8.2, 9.0, Forecast.Basis.MATCHED, null, 12, 0, 45.0, -0.01, "ticks");
        assertEquals("P(violation) 0.05, about 8.30 ticks to the violation (8.20-9.00 ticks) [matched, 0 of 12 runs]",
                ForecastWords.brief(g));
    }

    /** A scoped bound outside its scope: P 0.004 reads 0.00, and a time to a violation beside it would contradict it. */
    @Test
    void aProbabilityThatReadsZeroHasNoTimeToAViolation() {
        Forecast f = new Forecast(0.004, 765.0, 500.0, 900.0, Forecast.Basis.MATCHED, null, 12, 0, 80.0, null, "ticks");
        assertEquals("P(violation) 0.00, no violation in sight [matched, 0 of 12 runs]", ForecastWords.brief(f));
        assertEquals(null, dev.predmon.event.ForecastJson.of(f).timeToViolation(), "nor in the JSON");
        Forecast g = new Forecast(0.005, 765.0, 500.0, 900.0, Forecast.Basis.MATCHED, null, 12, 1, 80.0, null, "ticks");
        assertEquals("P(violation) 0.01, about 765 ticks to the violation (500-900 ticks) [matched, 1 of 12 runs]",
                ForecastWords.brief(g));
    }
}
