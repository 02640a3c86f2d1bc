package dev.predmon.abstraction;

import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Drop filters accept {@code *}, so BT-to-skill ports are dropped even in the older format (no Protocol line). */
class DropGlobTest {

    @Test
    void starMatchesAnyCharacters() {
        assertTrue(Rules.glob("*/BT_rpc/*", "/GoToDestination/BT_rpc/client"));
        assertTrue(Rules.glob("*/BT_rpc/*", "/BatteryLevel/BT_rpc/server"));
        assertFalse(Rules.glob("*/BT_rpc/*", "/GoToGoToClient/kitchen"));
        assertTrue(Rules.glob("/tick/monitor", "/tick/monitor"));
        assertFalse(Rules.glob("/tick/monitor", "/tick/monitor2"));
        assertTrue(Rules.glob("a*b*c", "aXXbYYc"));
        assertFalse(Rules.glob("a*b*c", "aXXbYY"));
        assertTrue(Rules.glob("*", ""));
    }

    @Test
    void olderFormatBtTrafficIsDroppedNotUnmapped() {
        LogRecord r = new LogRecord(1, 1.0, "DEBUG", RecordKind.COMMAND, "/GoToDestination/BT_rpc/client",
                "/GoToDestination/BT_rpc/server", "", "request_ack", "", "");
        assertInstanceOf(Classification.Dropped.class, AbstractionFiles.defaults().classify(r));
    }
}
