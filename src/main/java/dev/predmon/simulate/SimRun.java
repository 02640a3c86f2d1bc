package dev.predmon.simulate;

import java.util.List;

/**
 * One simulated run: the intercepted messages in the order they happened, and the ground truth.
 *
 * @param scenario the story told
 * @param seed     the seed it was simulated from
 * @param options  the options it was simulated with ({@link LogWriter} may be given others to print it)
 * @param events   messages in time order (non-decreasing {@link SimEvent#timeMicros()}), immutable
 * @param truth    what really happened
 */
public record SimRun(Scenario scenario, long seed, SimOptions options, List<SimEvent> events, Truth truth) {

    public SimRun {
        events = List.copyOf(events);
    }
}
