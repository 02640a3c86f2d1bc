package dev.predmon.compact;

import dev.predmon.abstraction.AbstractEvent;
import dev.predmon.abstraction.Channel;
import dev.predmon.abstraction.Direction;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** Algorithm 5 on the thesis's Figure 4.8 and on randomly delayed replies. */
class CompactorTest {

    /** Client port, server port, protocol, command of the four channels of Figure 4.8. */
    private static final Map<String, Channel> CHANNELS = Map.of(
            "level", new Channel("/BatteryReaderBatteryLevelClient", "/BatteryComponent", "BatteryReader", "level"),
            "batteryStatus", new Channel("/BatteryReaderBatteryNotChargingClient", "/BatteryComponent", "BatteryReader",
                    "charging_status"),
            "isAt_ki", new Channel("/GoToIsAtClient/kitchen", "/GoToComponent", "GoTo", "isAtLocation"),
            "goTo_ki", new Channel("/GoToGoToClient/kitchen", "/GoToComponent", "GoTo", "goTo"));

    private long line;

    /** The event of an abstract symbol as it appears in Figure 4.8: {@code level_i}, {@code o_goto_ki}, ... */
    private AbstractEvent event(String symbol) {
        boolean input = symbol.endsWith("_i");
        String key = input ? symbol.substring(0, symbol.length() - 2)
                : symbol.startsWith("o_goto_") ? "goTo_ki"
                : symbol.startsWith("o_isAt_ki") ? "isAt_ki"
                : symbol.startsWith("o_level") ? "level" : "batteryStatus";
        return event(CHANNELS.get(key), input, symbol, "");
    }

    private AbstractEvent event(Channel c, boolean input, String symbol, String arguments) {
        line += 8;
        LogRecord r = input
                ? new LogRecord(line, line, "DEBUG", RecordKind.COMMAND, c.client(), c.server(), c.protocol(), c.command(), arguments, "")
                : new LogRecord(line, line, "DEBUG", RecordKind.REPLY, c.server(), c.client(), c.protocol(), c.command(), arguments, "v");
        return new AbstractEvent(input ? Direction.INPUT : Direction.OUTPUT, symbol, c, r);
    }

    private static List<String> run(Compactor c, List<AbstractEvent> events, List<IoPair> out) {
        events.forEach(c::push);
        c.endOfInput();
        List<String> flat = new ArrayList<>();
        out.forEach(p -> flat.add(p.input() + "/" + p.output()));
        return flat;
    }

    @Test
    void figure48() {
        List<AbstractEvent> a = new ArrayList<>();
        for (String s : """
                level_i o_level_high batteryStatus_i o_batteryStatus_false isAt_ki_i o_isAt_ki_false goTo_ki_i
                level_i batteryStatus_i o_batteryStatus_false isAt_ki_i o_isAt_ki_false
                level_i batteryStatus_i o_batteryStatus_false isAt_ki_i o_isAt_ki_false
                batteryStatus_i o_batteryStatus_false isAt_ki_i o_isAt_ki_false
                batteryStatus_i o_batteryStatus_false isAt_ki_i o_isAt_ki_false
                level_i o_goto_ki""".split("\\s+", -1)) {
            a.add(event(s));
        }
        List<IoPair> out = new ArrayList<>();
        Compactor c = new Compactor(out::add);
        List<String> b = run(c, a, out);
        assertEquals(List.of("level_i/o_level_high", "batteryStatus_i/o_batteryStatus_false",
                "isAt_ki_i/o_isAt_ki_false", "goTo_ki_i/o_goto_ki"), b);
        // 1 level + 5 batteryStatus + 5 isAt + 1 goTo answered; 3 level commands never answered.
        assertEquals(new CompactorStats(12, 4, 3, 0), c.stats());
        assertEquals(a.get(6).record(), out.get(3).command());
        assertEquals(a.get(a.size() - 1).record(), out.get(3).reply());
    }

    @Test
    void outputChangeIsKeptAndLastIsUpdatedByDroppedPairs() {
        List<AbstractEvent> log = new ArrayList<>();
        for (String s : "isAt_ki_i o_isAt_ki_false isAt_ki_i o_isAt_ki_false isAt_ki_i o_isAt_ki_true isAt_ki_i o_isAt_ki_true isAt_ki_i o_isAt_ki_false".split(" ", -1)) {
            log.add(event(s));
        }
        List<IoPair> out = new ArrayList<>();
        assertEquals(List.of("isAt_ki_i/o_isAt_ki_false", "isAt_ki_i/o_isAt_ki_true", "isAt_ki_i/o_isAt_ki_false"),
                run(new Compactor(out::add), log, out));
    }

    @Test
    void unansweredCommandDoesNotBlockForever() {
        List<IoPair> out = new ArrayList<>();
        Compactor c = new Compactor(out::add);
        c.push(event("goTo_ki_i"));
        c.push(event("level_i"));
        c.push(event("o_level_high"));
        assertEquals(List.of(), out, "the unanswered goTo at the head holds back later pairs");
        assertEquals(2, c.queued());
        c.push(event("goTo_ki_i"));
        assertEquals(1, out.size(), "the next goTo on the same channel drops the old one and releases the queue");
        assertEquals(1, c.stats().unansweredDropped());
        c.push(event("level_i"));
        c.push(event("o_level_low"));
        c.endOfInput();
        assertEquals(List.of("level_i/o_level_high", "level_i/o_level_low"),
                out.stream().map(p -> p.input() + "/" + p.output()).toList());
        assertEquals(new CompactorStats(2, 2, 2, 0), c.stats());
        assertEquals(0, c.queued());
    }

    @Test
    void orphanRepliesAreCountedAndIgnored() {
        List<IoPair> out = new ArrayList<>();
        Compactor c = new Compactor(out::add);
        c.push(event("o_level_high"));
        c.push(event("level_i"));
        c.push(event("o_level_high"));
        c.push(event("o_level_low"));
        Channel goTo = CHANNELS.get("goTo_ki");
        c.push(event(goTo, true, "goTo_ki_i", "kitchen"));
        c.push(event(goTo, false, "o_goto_ki", "charging_station"));
        c.push(event(goTo, false, "o_goto_ki", "kitchen"));
        c.endOfInput();
        assertEquals(new CompactorStats(2, 2, 0, 3), c.stats());
        c.reset();
        assertEquals(new CompactorStats(0, 0, 0, 0), c.stats());
        c.push(event("level_i"));
        c.push(event("o_level_high"));
        assertEquals(3, out.size(), "after reset the first answer of a query is kept again");
    }

    /**
     * In-order logs against the same logs with replies printed late (but never after their channel's next
     * command): the compacted traces, records included, are identical.
     */
    @Test
    void delayedRepliesGiveTheSameTrace() {
        List<Channel> channels = List.copyOf(new TreeMap<>(CHANNELS).values());
        String[][] outputs = {{"o_a", "o_b"}, {"o_c", "o_d", "o_e"}, {"o_f"}, {"o_g", "o_h"}};
        for (int seed = 0; seed < 500; seed++) {
            Random rnd = new Random(seed);
            List<AbstractEvent> inOrder = new ArrayList<>();
            int steps = 1 + rnd.nextInt(60);
            for (int i = 0; i < steps; i++) {
                int k = rnd.nextInt(channels.size());
                Channel ch = channels.get(k);
                inOrder.add(event(ch, true, "q" + k + "_i", ""));
                int dice = rnd.nextInt(10);
                if (dice > 0) {
                    inOrder.add(event(ch, false, outputs[k][rnd.nextInt(outputs[k].length)], ""));
                }
                if (dice == 9) {
                    inOrder.add(event(ch, false, "o_orphan", ""));
                }
            }
            List<AbstractEvent> delayed = delay(inOrder, rnd);
            List<IoPair> a = new ArrayList<>();
            List<IoPair> b = new ArrayList<>();
            Compactor ca = new Compactor(a::add);
            Compactor cb = new Compactor(b::add);
            run(ca, inOrder, a);
            run(cb, delayed, b);
            assertEquals(a, b, "seed " + seed);
            assertEquals(ca.stats(), cb.stats(), "seed " + seed);
        }
    }

    /** Moves each reply a random distance later, but not past the next command on its own channel. */
    private static List<AbstractEvent> delay(List<AbstractEvent> log, Random rnd) {
        List<AbstractEvent> result = new ArrayList<>(log);
        for (int i = result.size() - 1; i >= 0; i--) {
            AbstractEvent e = result.get(i);
            if (e.direction() != Direction.OUTPUT || rnd.nextBoolean()) {
                continue;
            }
            int limit = i;
            while (limit + 1 < result.size() && !result.get(limit + 1).channel().equals(e.channel())) {
                limit++;
            }
            int target = i + rnd.nextInt(limit - i + 1);
            result.remove(i);
            result.add(target, e);
        }
        return result;
    }

    @Test
    void keepDecisionsFollowCommandOrderNotReplyOrder() {
        Map<String, List<String>> seen = new HashMap<>();
        List<IoPair> out = new ArrayList<>();
        Compactor c = new Compactor(p -> {
            out.add(p);
            seen.computeIfAbsent(p.input(), x -> new ArrayList<>()).add(p.output());
        });
        c.push(event("goTo_ki_i"));
        c.push(event("level_i"));
        c.push(event("o_level_high"));
        c.push(event("o_goto_ki"));
        assertEquals(List.of("goTo_ki_i", "level_i"), out.stream().map(IoPair::input).toList());
        assertEquals(List.of("o_level_high"), seen.get("level_i"));
    }
}
