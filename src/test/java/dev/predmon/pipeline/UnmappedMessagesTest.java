package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.abstraction.file.AbstractionFiles;
import org.junit.jupiter.api.Test;

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
}
