package dev.predmon.simulate;

import dev.predmon.parse.RecordKind;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Random;

/**
 * Prints simulated messages as a yarplogger export of the YARP monitor's output: per message one DEBUG
 * entry of seven lines ({@code <Kind> intercepted:} and the From/To/Protocol/Command/Arguments/Reply fields),
 * optionally preceded by the INFO raw-bottle line, in the layout chosen by {@link SimOptions}.
 *
 * <p>The output is a pure function of the run and the options: the late-reply shuffle draws from a random
 * stream seeded by the run's seed.
 */
public final class LogWriter {

    /** YARP's {@code VOCAB_OK}, printed for a true {@code isAtLocation} by newer monitors. */
    public static final String VOCAB_OK = "27503";
    /** YARP's {@code VOCAB_FAIL}, printed for a false {@code isAtLocation}. */
    public static final String VOCAB_FAIL = "1818845542";

    private static final MathContext YARP_DOUBLE = new MathContext(21);
    private static final int MAX_LATE_SHIFT = 3;

    private LogWriter() {
    }

    /** Writes every record of {@code run} to {@code out} (not closed, not flushed). */
    public static void write(SimRun run, SimOptions options, Writer out) throws IOException {
        StringBuilder sb = new StringBuilder(512);
        for (SimEvent e : printOrder(run, options)) {
            sb.setLength(0);
            format(e, options, sb);
            out.write(sb.toString());
        }
    }

    /** The whole log as a string. */
    public static String toText(SimRun run, SimOptions options) {
        StringBuilder sb = new StringBuilder(run.events().size() * 200);
        for (SimEvent e : printOrder(run, options)) {
            format(e, options, sb);
        }
        return sb.toString();
    }

    /**
     * The order in which the monitor prints the events. Without late replies it is the time order. With
     * probability {@link SimOptions#lateReplies()} a reply is moved past the next one to three records,
     * stopping before the next command of its own connection (client and server ports): messages of one
     * connection share a socket and stay in order, different connections race. Tick records are left out when
     * {@link Novelties#noTicks()} asks for a log without them.
     */
    public static List<SimEvent> printOrder(SimRun run, SimOptions options) {
        return printOrder(run.events(), run.seed(), options);
    }

    /** {@link #printOrder(SimRun, SimOptions)} of the events of a run simulated from {@code seed}. */
    static List<SimEvent> printOrder(List<SimEvent> events, long seed, SimOptions options) {
        List<SimEvent> order = new ArrayList<>(events);
        if (options.novelties().noTicks()) {
            order.removeIf(e -> e.kind() == RecordKind.TICK);
        }
        if (options.lateReplies() <= 0) {
            return order;
        }
        Random random = new Random(seed * 31 + 0x1A7E);
        // By identity: each event of the list moves once at most, whatever the other events hold.
        IdentityHashMap<SimEvent, Boolean> moved = new IdentityHashMap<>();
        for (int i = 0; i < order.size(); i++) {
            SimEvent e = order.get(i);
            if (e.kind() != RecordKind.REPLY || moved.containsKey(e) || random.nextDouble() >= options.lateReplies()) {
                continue;
            }
            moved.put(e, Boolean.TRUE);
            int shift = 1 + random.nextInt(MAX_LATE_SHIFT);
            int at = i;
            while (shift-- > 0 && at + 1 < order.size() && !sameConnectionCommand(e, order.get(at + 1))) {
                order.set(at, order.get(at + 1));
                order.set(at + 1, e);
                at++;
            }
        }
        return order;
    }

    /** Lines one record takes in the log: seven, and the raw-bottle line before them if printed. */
    static int linesPerRecord(SimOptions options) {
        return options.rawLines() ? 8 : 7;
    }

    /**
     * The line of each event's record in the log printed from {@code events} alone (1-based, the line of its DEBUG
     * header); an event left out of the log (a Tick record without ticks) gets the line of the next event printed,
     * or the line after the log's last when none follows.
     */
    static long[] headerLines(List<SimEvent> events, long seed, SimOptions options) {
        List<SimEvent> order = printOrder(events, seed, options);
        IdentityHashMap<SimEvent, Integer> position = new IdentityHashMap<>();
        for (int i = 0; i < order.size(); i++) {
            position.put(order.get(i), i);
        }
        int per = linesPerRecord(options);
        long[] lines = new long[events.size()];
        long next = (long) order.size() * per + 1;
        for (int i = events.size() - 1; i >= 0; i--) {
            Integer at = position.get(events.get(i));
            if (at != null) {
                next = (long) at * per + per - 6;
            }
            lines[i] = next;
        }
        return lines;
    }

    private static boolean sameConnectionCommand(SimEvent reply, SimEvent next) {
        return next.kind() == RecordKind.COMMAND && next.client().equals(reply.client())
                && next.server().equals(reply.server());
    }

    /** Appends the record of {@code e} (and its raw-bottle line if asked) to {@code sb}. */
    public static void format(SimEvent e, SimOptions options, StringBuilder sb) {
        String nl = options.crlf() ? "\r\n" : "\n";
        String sep = options.spaces() ? " " : "\t";
        String time = formatTime(e.timeMicros());
        String reply = printedReply(e, options);
        if (options.rawLines()) {
            sb.append(time).append(sep).append("INFO").append(sep)
                    .append('"').append(e.from()).append("\" \"").append(e.to()).append("\" \"")
                    .append(e.kind().name().toLowerCase(Locale.ROOT)).append("\" \"")
                    .append(e.protocol()).append("\" (").append(e.command()).append(") (")
                    .append(e.argument()).append(") (").append(reply).append(')').append(nl);
        }
        sb.append(time).append(sep).append("DEBUG").append(sep).append(kindLabel(e.kind()))
                .append(" intercepted:").append(nl);
        field(sb, "From", e.from(), nl);
        field(sb, "To", e.to(), nl);
        field(sb, "Protocol", e.protocol(), nl);
        field(sb, "Command", e.command(), nl);
        field(sb, "Arguments", e.argument(), nl);
        field(sb, "Reply", reply, nl);
    }

    private static void field(StringBuilder sb, String label, String value, String nl) {
        sb.append("  ").append(label);
        for (int i = label.length(); i < 10; i++) {
            sb.append(' ');
        }
        sb.append(": ").append(value).append(nl);
    }

    private static String kindLabel(RecordKind kind) {
        return switch (kind) {
            case COMMAND -> "Command";
            case REPLY -> "Reply";
            case TICK -> "Tick";
            case UNKNOWN -> "Unknown";
        };
    }

    private static String printedReply(SimEvent e, SimOptions options) {
        if (options.vocab() && e.kind() == RecordKind.REPLY && e.command().equals("isAtLocation")) {
            return e.reply().equals("1") ? VOCAB_OK : VOCAB_FAIL;
        }
        return e.reply();
    }

    /** Seconds with six decimals, from microseconds: {@code 72125394 -> "72.125394"}. */
    public static String formatTime(long micros) {
        if (micros < 0) {
            throw new IllegalArgumentException("negative time " + micros);
        }
        String frac = Long.toString(micros % 1_000_000);
        return micros / 1_000_000 + "." + "000000".substring(frac.length()) + frac;
    }

    /**
     * A double as YARP prints it: the exact binary value rounded to 21 significant digits, trailing zeros
     * dropped, {@code .0} added to integers ({@code 97.316999999987189085}, {@code 100.0}).
     */
    public static String formatDouble(double value) {
        if (!Double.isFinite(value)) {
            throw new IllegalArgumentException("not a finite double: " + value);
        }
        String s = new BigDecimal(value).round(YARP_DOUBLE).stripTrailingZeros().toPlainString();
        return s.indexOf('.') < 0 ? s + ".0" : s;
    }

    /** Writes and flushes one record: for callers that pace records themselves. */
    static void writeOne(SimEvent e, SimOptions options, Writer out) {
        StringBuilder sb = new StringBuilder(512);
        format(e, options, sb);
        try {
            out.write(sb.toString());
            out.flush();
        } catch (IOException ex) {
            throw new UncheckedIOException(ex);
        }
    }
}
