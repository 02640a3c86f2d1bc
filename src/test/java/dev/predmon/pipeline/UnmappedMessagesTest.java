package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.abstraction.file.AbstractionFiles;
import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Which unmapped messages mean the robot did something the models never saw. */
class UnmappedMessagesTest {

    private final Abstraction thesis = AbstractionFiles.builtin("thesis").orElseThrow();

    private static UnmappedMessage message(String protocol, String command, UnmappedMessage.Kind kind, String detail) {
        return new UnmappedMessage(protocol, command, kind, detail);
    }

    @Test
    void aPlaceTheAbstractionDoesNotKnowIsNovelty() {
        assertTrue(UnmappedMessages.novelty(message("GoTo", "goTo", UnmappedMessage.Kind.COMMAND_LOCATION, "office"), thesis));
        assertTrue(UnmappedMessages.novelty(message("GoTo", "getStatus", UnmappedMessage.Kind.REPLY_LOCATION, "office"),
                thesis));
    }

    @Test
    void aCommandOrReplyOfAMappedComponentThatNoRuleTakesIsNovelty() {
        assertTrue(UnmappedMessages.novelty(message("GoTo", "dance", UnmappedMessage.Kind.COMMAND, ""), thesis));
        assertTrue(UnmappedMessages.novelty(message("GoTo", "getStatus", UnmappedMessage.Kind.REPLY, "7"), thesis));
    }

    @Test
    void aComponentTheAbstractionLeavesOutIsNot() {
        assertFalse(UnmappedMessages.novelty(message("Camera", "grab", UnmappedMessage.Kind.COMMAND, ""), thesis));
        assertFalse(UnmappedMessages.novelty(message("Camera", "grab", UnmappedMessage.Kind.REPLY, "frame"), thesis));
    }

    /** Grouped by command from the messages themselves: why each command's messages are not mapped, in one line. */
    @Test
    void messagesAreToldByCommandWithWhy() {
        Map<UnmappedMessage, Long> unmapped = Map.of(
                message("GoTo", "goTo", UnmappedMessage.Kind.COMMAND_LOCATION, "user"), 4L,
                message("GoTo", "getStatus", UnmappedMessage.Kind.REPLY_LOCATION, "user"), 2L,
                message("GoTo", "getStatus", UnmappedMessage.Kind.REPLY, "7"), 1L,
                message("ArmService", "hasGrasped", UnmappedMessage.Kind.COMMAND, ""), 3L,
                message("ArmService", "hasGrasped", UnmappedMessage.Kind.REPLY, "1"), 3L);
        assertEquals(List.of("ArmService/hasGrasped (6 messages): no rule for this command",
                "GoTo/goTo (4 messages): about locations it does not know: 'user'",
                "GoTo/getStatus (3 messages): about locations it does not know: 'user'; 1 distinct reply no rule takes"),
                UnmappedMessages.lines(unmapped));
        assertEquals(List.of("ArmService/hasGrasped command", "ArmService/hasGrasped reply '1'",
                        "GoTo/getStatus reply '7'", "GoTo/getStatus reply about unknown location 'user'",
                        "GoTo/goTo command about unknown location 'user'"),
                List.copyOf(UnmappedMessages.texts(unmapped).keySet()), "the texts JSON shows, in their order");
    }
}
