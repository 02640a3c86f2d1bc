package dev.predmon.compact;

import dev.predmon.abstraction.AbstractEvent;

import java.util.function.Consumer;

/** Algorithm 5 (Compactor) of the thesis, streaming. */
public final class Compactor {

    public Compactor(Consumer<IoPair> out) {
        throw new UnsupportedOperationException("TODO compactor");
    }

    /** Takes the next abstract event in log order. */
    public void push(AbstractEvent event) {
        throw new UnsupportedOperationException("TODO compactor");
    }

    /** The input is over: commands still waiting for a reply are dropped (and counted). */
    public void endOfInput() {
        throw new UnsupportedOperationException("TODO compactor");
    }

    /** Forgets everything (the log was truncated or replaced). */
    public void reset() {
        throw new UnsupportedOperationException("TODO compactor");
    }
}
