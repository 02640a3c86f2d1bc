package dev.predmon.property;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** Numbers in verdicts: as users read them, and never hundreds of digits. */
class NumbersTest {

    @Test
    void everydayNumbersAsTheyAreAndHugeOnesInScientificNotation() {
        assertEquals("20", Numbers.text(20));
        assertEquals("19.5", Numbers.text(19.5));
        assertEquals("9.956", Numbers.text(9.956));
        assertEquals("1e308", Numbers.text(1e308), "a floor of 1e308: not 309 digits");
        assertEquals("-1.79769e308", Numbers.text(-Double.MAX_VALUE));
        assertEquals("19.9 below the floor 1e308", new Bound("b", "b", null, null, 1e308).violation(19.9));
    }
}
