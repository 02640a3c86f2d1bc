package dev.predmon.abstraction;

import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.parse.LogRecord;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import static dev.predmon.abstraction.AbstractionTest.command;
import static dev.predmon.abstraction.AbstractionTest.reply;
import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * {@link Rules} remembers what each connection decides in a bounded table: however many connections a log has and
 * in whatever order they come, and whether or not the parser handed over the same string instances, every record is
 * classified as a fresh abstraction classifies it alone.
 */
class RouteTableTest {

    private static final String[] LOCATIONS = {"kitchen", "charging_station", "bedroom", ""};

    /** Records over many more connections than the table holds: clients, locations, kinds, dropped ones. */
    private static List<LogRecord> records(Random random, int n) {
        List<LogRecord> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            String client = switch (random.nextInt(5)) {
                case 0 -> "/GoToGoToClient/" + LOCATIONS[random.nextInt(LOCATIONS.length)];
                case 1 -> "/GoToIsAtClient/robot" + random.nextInt(400);
                case 2 -> "/BatteryReaderBatteryLevelClient";
                case 3 -> "/Skill" + random.nextInt(300) + "/BT_rpc/client";
                default -> "/BatteryReaderBatteryNotChargingClient";
            };
            String location = LOCATIONS[random.nextInt(LOCATIONS.length)];
            String[] call = switch (random.nextInt(6)) {
                case 0 -> new String[] {"GoTo", "goTo", location, "running"};
                case 1 -> new String[] {"GoTo", "getStatus", location, random.nextBoolean() ? "running" : "success"};
                case 2 -> new String[] {"GoTo", "isAtLocation", location, random.nextBoolean() ? "1" : "1818845542"};
                case 3 -> new String[] {"BatteryReader", "level", "", String.valueOf(random.nextDouble() * 100)};
                case 4 -> new String[] {"BatteryReader", "charging_status", "", random.nextBoolean() ? "0" : "1"};
                default -> new String[] {"Skill_request", "request_ack", "", "2"};
            };
            // New string instances each time, as the general parsing path gives them.
            out.add(random.nextBoolean()
                    ? command(new String(client), "/Server", call[0], new String(call[1]), new String(call[2]))
                    : reply("/Server", new String(client), call[0], call[1], call[2], new String(call[3])));
        }
        return out;
    }

    @Test
    void everyRecordClassifiedAsAlone() {
        Abstraction shared = AbstractionFiles.defaults();
        for (LogRecord r : records(new Random(5), 20_000)) {
            assertEquals(describe(AbstractionFiles.defaults().classify(r)), describe(shared.classify(r)), r.toString());
        }
    }

    private static String describe(Classification c) {
        if (c instanceof Classification.Mapped m) {
            AbstractEvent e = m.event();
            return "mapped " + e.direction() + " " + e.symbol() + " " + e.channel() + " " + e.value();
        }
        return c.toString();
    }
}
