package dev.predmon.property;

/**
 * A comparison of a numeric value with a number, {@code battery < 30}. A trigger that is a condition fires when the
 * condition becomes true: at a reading that satisfies it after one that did not, or at the run's first reading.
 *
 * @param value  what is read
 * @param op     how it is compared
 * @param number with what
 */
public record Condition(ValueReader value, Op op, double number) {

    /** The comparisons, named as the abstraction file's ranges name their ends. */
    public enum Op {
        BELOW("below", "<"), AT_MOST("atMost", "<="), ABOVE("above", ">"), AT_LEAST("atLeast", ">=");

        /** The key of the abstraction file. */
        public final String key;
        final String symbol;

        Op(String key, String symbol) {
            this.key = key;
            this.symbol = symbol;
        }
    }

    /** Whether reading {@code v} satisfies the condition (NaN never does). */
    public boolean test(double v) {
        return switch (op) {
            case BELOW -> v < number;
            case AT_MOST -> v <= number;
            case ABOVE -> v > number;
            case AT_LEAST -> v >= number;
        };
    }

    /** In a user's words: {@code BatteryReader/level < 30}. */
    public String describe() {
        return value.describe() + " " + op.symbol + " " + Numbers.text(number);
    }
}
