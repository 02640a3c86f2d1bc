package dev.predmon.simulate;

/**
 * The arm component of the fetch-and-carry tree ({@code ArmService} on {@code /ArmComponent}): it closes the hand on
 * the object, and {@code hasGrasped} tells whether it holds it. A grasp fails a number of times drawn per run, then
 * holds: 0 to 3 failures as in the recordings (the fourth {@code closeHand} grasps), or as many as
 * {@link Novelties#graspFailures()} asks for, a grasp retried dozens of times as the real robot did.
 */
final class Arm {

    static final String PORT = "/ArmComponent";
    static final String PROTOCOL = "ArmService";
    /** YARP's {@code VOCAB_OK}: the arm's commands answer with it. */
    static final String OK = "27503";

    private final int failures;
    private int attempts;
    private boolean grasped;

    /** @param failures attempts that fail before one holds */
    Arm(int failures) {
        this.failures = failures;
    }

    /** One attempt: the hand closes; whether it holds the object now. */
    boolean closeHand() {
        attempts++;
        grasped |= attempts > failures;
        return grasped;
    }

    /** {@code ArmService.hasGrasped()}. */
    boolean hasGrasped() {
        return grasped;
    }

    /** The attempts so far. */
    int attempts() {
        return attempts;
    }
}
