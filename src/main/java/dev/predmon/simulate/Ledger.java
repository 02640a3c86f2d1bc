package dev.predmon.simulate;

import java.util.ArrayList;
import java.util.List;

/**
 * What the simulated robot did, noted by the tree and the components as it happens: the ticks, the battery readings
 * the tree got, the navigations it started, halted and was told about, where the robot arrived and how each grasp
 * attempt went. {@link PropertyJudge} judges the properties from it, so that a run's truth comes from the simulator's
 * knowledge and not from reading its log back.
 */
final class Ledger {

    /** What a note is about. */
    enum Kind {
        /** A tick of the tree began; its Tick record is {@code event}. */
        TICK,
        /** The tree read the battery: {@code value} is the {@code level} reply {@code event}. */
        READING,
        /** The tree sent {@code goTo(place)}: the command {@code event}. */
        GO_TO,
        /** The tree halted the navigation to {@code place}. */
        HALT,
        /** The navigation component answered {@code getStatus(place)} with {@code value}: the reply {@code event}. */
        STATUS,
        /** The robot reached {@code place} (no message of its own: the component's state changed). */
        ARRIVAL,
        /** A grasp attempt ended: {@code value} is the {@code hasGrasped} reply {@code event}, 1 when it held. */
        GRASP
    }

    /**
     * One thing that happened.
     *
     * @param kind  what happened
     * @param event index of its message in the run's events, or -1 when no message shows it
     * @param tick  the tick of the tree it happened in
     * @param place the location it concerns, or null
     * @param value the reading, status code or grasp outcome, else 0
     */
    record Note(Kind kind, int event, int tick, String place, double value) {
    }

    private final List<Note> notes = new ArrayList<>();
    private int tick;

    /** Notes that {@code kind} happened in the current tick. */
    void note(Kind kind, int event, String place, double value) {
        notes.add(new Note(kind, event, tick, place, value));
    }

    /** Notes the start of tick {@code index}, printed as {@code event}. */
    void tick(int index, int event) {
        tick = index;
        notes.add(new Note(Kind.TICK, event, index, null, 0));
    }

    /** Notes that the robot reached {@code place} before tick {@code index} began. */
    void arrived(String place, int index) {
        notes.add(new Note(Kind.ARRIVAL, -1, index, place, 0));
    }

    List<Note> notes() {
        return notes;
    }
}
