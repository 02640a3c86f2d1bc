package dev.predmon.simulate;

import dev.predmon.parse.RecordKind;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Collects the messages of a simulation with their log times. Within a tick the calls happen one after
 * another, so each command gets a later time than the previous reply and its reply comes a fraction of a
 * millisecond after it; the jitter is drawn from the run's random stream so that the log stays reproducible.
 */
final class Recorder {

    static final String TICK_PORT = "/tick/monitor";
    static final String MONITOR_PORT = "/monitor";

    private final List<SimEvent> events = new ArrayList<>();
    private final Ledger ledger;
    private final SplittableRandom jitter;
    private long cursor;

    Recorder(SplittableRandom jitter) {
        this(jitter, new Ledger());
    }

    /** @param ledger where the ticks are noted, and the tree notes what it does */
    Recorder(SplittableRandom jitter, Ledger ledger) {
        this.jitter = jitter;
        this.ledger = ledger;
    }

    /** Records the tick numbered {@code index} at {@code timeMicros} and moves the clock past it. */
    void tick(long timeMicros, int index) {
        cursor = Math.max(cursor, timeMicros);
        ledger.tick(index, events.size());
        events.add(new SimEvent(cursor, RecordKind.TICK, TICK_PORT, MONITOR_PORT, "", "tick",
                Integer.toString(index), ""));
        cursor += jitter.nextLong(80, 600);
    }

    /**
     * Records a command and its reply. {@code replyArgument} is what the reply record prints as Arguments:
     * usually {@code argument}, empty when a server echoes its argument in the reply instead.
     *
     * @return {@code reply}, for chaining in the skills
     */
    String call(String client, String server, String protocol, String command, String argument,
                String replyArgument, String reply) {
        events.add(new SimEvent(cursor, RecordKind.COMMAND, client, server, protocol, command, argument, ""));
        cursor += jitter.nextLong(60, 700);
        events.add(new SimEvent(cursor, RecordKind.REPLY, server, client, protocol, command, replyArgument, reply));
        cursor += jitter.nextLong(150, 2500);
        return reply;
    }

    /** A command and reply whose reply repeats the argument, the usual case. */
    String call(String client, String server, String protocol, String command, String argument, String reply) {
        return call(client, server, protocol, command, argument, argument, reply);
    }

    List<SimEvent> events() {
        return events;
    }

    /** What happened so far, as the tree and the components noted it. */
    Ledger ledger() {
        return ledger;
    }

    /** Index of the last reply recorded: the one of the last {@link #call}. */
    int lastReply() {
        return events.size() - 1;
    }

    /** Index of the last command recorded: the one of the last {@link #call}. */
    int lastCommand() {
        return events.size() - 2;
    }
}
