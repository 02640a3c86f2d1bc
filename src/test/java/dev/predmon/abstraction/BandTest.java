package dev.predmon.abstraction;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

/** {@link Band}'s written-out equality is a record's: every component, doubles as {@link Double#compare} does. */
class BandTest {

    @Test
    void equalityIsComponentWise() {
        Band b = new Band(20, true, 25, true);
        assertEquals(new Band(20, true, 25, true), b);
        assertEquals(new Band(20, true, 25, true).hashCode(), b.hashCode());
        assertNotEquals(new Band(20, false, 25, true), b);
        assertNotEquals(new Band(20, true, 25, false), b);
        assertNotEquals(new Band(21, true, 25, true), b);
        assertNotEquals(new Band(20, true, 26, true), b);
        assertNotEquals(b, null);
        assertNotEquals(b, "[20, 25]");
    }

    @Test
    void doublesCompareAsDoubleCompareDoes() {
        assertNotEquals(new Band(0.0, false, 1, true), new Band(-0.0, false, 1, true));
        assertEquals(new Band(Double.NaN, false, 1, true), new Band(Double.NaN, false, 1, true));
        assertEquals(new Band(Double.NaN, false, 1, true).hashCode(), new Band(Double.NaN, false, 1, true).hashCode());
        Band infinite = new Band(Double.NEGATIVE_INFINITY, false, Double.POSITIVE_INFINITY, false);
        assertEquals(new Band(Double.NEGATIVE_INFINITY, false, Double.POSITIVE_INFINITY, false), infinite);
    }
}
