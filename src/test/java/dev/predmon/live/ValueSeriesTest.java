package dev.predmon.live;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class ValueSeriesTest {

    @Test
    void keepsEveryReadingUntilFullThenThinsEvenlyKeepingTheFirstAndTheLatest() {
        ValueSeries s = new ValueSeries(8);
        for (int i = 0; i < 8; i++) {
            s.add(i, 100 - i);
        }
        assertEquals(8, s.points().size());
        for (int i = 8; i < 1000; i++) {
            s.add(i, 100 - i * 0.1);
            List<double[]> p = s.points();
            assertTrue(p.size() <= 9, "at most capacity + the latest: " + p.size());
            assertEquals(0.0, p.get(0)[0], "the first reading stays");
            assertEquals(i, p.get(p.size() - 1)[0], "the latest reading is last");
            for (int k = 1; k < p.size(); k++) {
                assertTrue(p.get(k)[0] > p.get(k - 1)[0], "in time order, no repeats");
            }
        }
        List<double[]> p = s.points();
        double gap = p.get(1)[0] - p.get(0)[0];
        for (int k = 2; k < p.size() - 1; k++) {
            assertEquals(gap, p.get(k)[0] - p.get(k - 1)[0], "evenly thinned");
        }
        s.clear();
        assertTrue(s.points().isEmpty() && s.isEmpty());
    }
}
