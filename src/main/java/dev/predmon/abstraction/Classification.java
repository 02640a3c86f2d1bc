package dev.predmon.abstraction;

/** What the abstraction made of one record. */
public sealed interface Classification permits Classification.Dropped, Classification.Unmapped, Classification.Mapped {

    /** Not part of the skill-component interface (BT-to-skill traffic, ticks): ignored on purpose. */
    record Dropped() implements Classification {
    }

    /** Part of the interface, but no rule maps it: which kind of message, and why. */
    record Unmapped(UnmappedMessage message) implements Classification {
    }

    /** Mapped to a symbol. */
    record Mapped(AbstractEvent event) implements Classification {
    }
}
