package dev.predmon.abstraction;

import dev.predmon.parse.Decimals;
import dev.predmon.parse.LogRecord;

/**
 * A record of the skill-component interface turned into a symbol of the abstraction.
 *
 * @param direction input (a skill's command) or output (a component's reply)
 * @param symbol    the abstract symbol, safe in DOT: {@code goTo_ki_i}, {@code o_level_medium_four}
 * @param channel   the connection, used to pair a reply with its command
 * @param record    the record it came from
 * @param value     a reply's value as the number its rule's ranges read ({@link Decimals#parse}),
 *                  NaN for commands and replies of rules without ranges: read once, by the abstraction, and used by
 *                  the hysteresis and the noise estimate
 */
public record AbstractEvent(Direction direction, String symbol, Channel channel, LogRecord record, double value) {

    /** An event without a numeric value. */
    public AbstractEvent(Direction direction, String symbol, Channel channel, LogRecord record) {
        this(direction, symbol, channel, record, Double.NaN);
    }
}
