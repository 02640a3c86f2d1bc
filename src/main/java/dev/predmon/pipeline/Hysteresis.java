package dev.predmon.pipeline;

import dev.predmon.abstraction.AbstractEvent;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.Channel;
import dev.predmon.abstraction.Direction;

import java.util.HashMap;
import java.util.Map;

/**
 * Applies the abstraction's hysteresis ({@link Abstraction#settle}) to the replies of each channel: it remembers
 * the band each channel's last reply settled in. It lives in the shared pipeline, before compaction, so learn and
 * watch settle identically.
 */
final class Hysteresis {

    private final Abstraction abstraction;
    private final Map<Channel, String> settled = new HashMap<>();

    Hysteresis(Abstraction abstraction) {
        this.abstraction = abstraction;
    }

    /** The event, with its band settled; commands and replies of rules without hysteresis pass unchanged. */
    AbstractEvent settle(AbstractEvent e) {
        if (e.direction() != Direction.OUTPUT || !abstraction.hasHysteresis(e.symbol())) {
            return e;
        }
        String band = abstraction.settle(settled.get(e.channel()), e.symbol(), e.value());
        settled.put(e.channel(), band);
        return band.equals(e.symbol()) ? e : new AbstractEvent(e.direction(), band, e.channel(), e.record(), e.value());
    }

    void reset() {
        settled.clear();
    }
}
