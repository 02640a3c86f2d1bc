package dev.predmon.forecast;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

class ThresholdChoiceTest {

    private static ThresholdChoice.Peak safe(double p) {
        return new ThresholdChoice.Peak(p, false);
    }

    private static ThresholdChoice.Peak bad(double p) {
        return new ThresholdChoice.Peak(p, true);
    }

    @Test
    void separablePeaksGiveTheMiddleOfTheGap() {
        ThresholdChoice.Choice c = ThresholdChoice.choose(List.of(safe(0.3), safe(0.5), bad(0.9), bad(0.95)));
        assertEquals(0.7, c.threshold(), 1e-9);
        assertTrue(c.validated());
    }

    @Test
    void overlappingPeaksMakeTheFewestWrongCalls() {
        ThresholdChoice.Choice c = ThresholdChoice.choose(List.of(safe(0.4), safe(0.8), bad(0.7), bad(0.9),
                bad(0.95)));
        // at 0.85: 1 miss (0.7), 0 false alarms; at 0.6: 1 false alarm, 0 misses; the wider gap decides
        assertTrue(c.threshold() > 0.4 && c.threshold() < 0.9, c.toString());
    }

    @Test
    void peaksBelowEvenOddsNeverSetTheThreshold() {
        // The violating runs stand out, but at 0.3-0.35 each warning would say the run more likely holds.
        ThresholdChoice.Choice c = ThresholdChoice.choose(List.of(safe(0.1), safe(0.2), bad(0.3), bad(0.35)));
        assertTrue(c.threshold() >= ThresholdChoice.FLOOR, c.toString());
        assertTrue(c.note().contains("warned 0 of 2 violations, 0 false alarm(s)"), c.note());
        assertTrue(c.validated());
    }

    @Test
    void withoutBothOutcomesTheDefaultIsNotValidated() {
        ThresholdChoice.Choice c = ThresholdChoice.choose(List.of(safe(0.2), safe(0.4)));
        assertEquals(ThresholdChoice.DEFAULT, c.threshold());
        assertFalse(c.validated());
    }
}
