package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Which unmapped messages mean the robot did something the models never saw. */
class UnmappedMessagesTest {

    private final Abstraction thesis = AbstractionFiles.builtin("thesis").orElseThrow();

    @Test
    void aPlaceTheAbstractionDoesNotKnowIsNovelty() {
        assertTrue(UnmappedMessages.novelty("GoTo/goTo command about unknown location 'office'", thesis));
        assertTrue(UnmappedMessages.novelty("GoTo/getStatus reply about unknown location 'office'", thesis));
    }

    @Test
    void aCommandOrReplyOfAMappedComponentThatNoRuleTakesIsNovelty() {
        assertTrue(UnmappedMessages.novelty("GoTo/dance command", thesis));
        assertTrue(UnmappedMessages.novelty("GoTo/getStatus reply '7'", thesis));
    }

    @Test
    void aComponentTheAbstractionLeavesOutIsNot() {
        assertFalse(UnmappedMessages.novelty("Camera/grab command", thesis));
        assertFalse(UnmappedMessages.novelty("Camera/grab reply 'frame'", thesis));
    }
}
