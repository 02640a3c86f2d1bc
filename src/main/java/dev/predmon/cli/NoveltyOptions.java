package dev.predmon.cli;

import dev.predmon.simulate.Novelties;
import dev.predmon.simulate.Novelties.AbortOn;
import dev.predmon.simulate.Novelties.Span;
import picocli.CommandLine.Option;

/**
 * The options of {@code simulate} that give runs what a real robot does and the default runs never show (see
 * {@link Novelties}). Left out, they change nothing: the logs are byte for byte those of a simulation without them.
 */
final class NoveltyOptions {

    @Option(names = "--aborts", paramLabel = "N", defaultValue = "0",
            description = "Blocked paths per run: the robot stops short and is stuck for --stuck seconds, the "
                    + "navigation component then answers getStatus with 3 (ABORT) and the tree sends goTo again. "
                    + "Default: ${DEFAULT-VALUE}.")
    int aborts;

    @Option(names = "--abort-on", paramLabel = "destination|station|any", defaultValue = "any",
            description = "Which navigation a blocked path aborts: the way to the tour location, the way to the "
                    + "charging station (direct runs never go there and get no abort), or whichever comes first. "
                    + "Default: ${DEFAULT-VALUE}.")
    String abortOn;

    @Option(names = "--stuck", paramLabel = "SECONDS|LOW..HIGH", defaultValue = "10..40",
            description = "How long the robot is stuck before its navigation aborts, drawn per abort from the seed. "
                    + "Default: ${DEFAULT-VALUE}.")
    String stuck;

    @Option(names = "--slowdown", paramLabel = "FACTOR|LOW..HIGH", defaultValue = "1",
            description = "Divide the robot's speed by this factor (drawn per run from the seed when a range): it "
                    + "arrives later and with less battery. Default: ${DEFAULT-VALUE}.")
    String slowdown;

    @Option(names = "--drain-factor", paramLabel = "FACTOR|LOW..HIGH", defaultValue = "1",
            description = "Multiply the battery's drain rates by this factor (drawn per run from the seed when a "
                    + "range): above 1 an ageing battery, below 1 a thriftier robot. Default: ${DEFAULT-VALUE}.")
    String drainFactor;

    @Option(names = "--new-location", paramLabel = "NAME",
            description = "The tour location is NAME instead of kitchen (ports, arguments and replies name it): "
                    + "a place no model learned from default runs has seen.")
    String newLocation;

    @Option(names = "--no-ticks", description = "Leave the Tick records out of the log, as monitors that do not "
            + "print them do: a log of several runs then shows no tick counter starting again.")
    boolean noTicks;

    @Option(names = "--gap", paramLabel = "SECONDS|LOW..HIGH",
            description = "Seconds of silence between two runs of one log; a range such as 5..30 is drawn per gap "
                    + "from the seed. Default: 5.")
    String gap;

    @Option(names = "--never-arrives", paramLabel = "TICKS|LOW..HIGH",
            description = "The way to the tour location (the long leg of a direct run; of a recharge run the way "
                    + "back after charging; with --abort-on station the way to the charging station, the short leg "
                    + "of a recharge run) is blocked for good: the robot stops "
                    + "short, the navigation keeps answering getStatus with 1 (RUNNING), and the log ends TICKS "
                    + "ticks later (drawn per run when a range). Depleted runs never get there and are not stuck.")
    String neverArrives;

    @Option(names = "--grasp", description = "The robot grasps an object at the tour location (ArmService closeHand "
            + "and hasGrasped, one attempt per tick); the grasp holds within 1 to 4 attempts.")
    boolean grasp;

    @Option(names = "--grasp-failures", paramLabel = "N|LOW..HIGH",
            description = "A grasp (implies --grasp) that fails N times before it holds (drawn per run when a "
                    + "range): hasGrasped answers 0 and the tree retries, as the real robot did dozens of times.")
    String graspFailures;

    @Option(names = "--late-turn", paramLabel = "TICKS|LOW..HIGH",
            description = "The tree turns to the charging station TICKS ticks after the first battery reading below "
                    + "30 (drawn per run when a range) instead of at the early warning.")
    String lateTurn;

    @Option(names = "--tick-period", paramLabel = "SECONDS|LOW..HIGH",
            description = "Seconds between two ticks of the tree (drawn per run when a range) instead of the period "
                    + "drawn with the physical parameters (0.2 to 1 s); the real robot ticks about once a second.")
    String tickPeriod;

    /** The novelties asked for; {@link Novelties#NONE} when none is. */
    Novelties novelties() {
        return new Novelties(aborts, AbortOn.fromId(abortOn), parse("--stuck", stuck),
                parse("--slowdown", slowdown), parse("--drain-factor", drainFactor), newLocation, noTicks,
                gap == null ? null : parse("--gap", gap), optional("--never-arrives", neverArrives),
                grasp || graspFailures != null, optional("--grasp-failures", graspFailures),
                optional("--late-turn", lateTurn), optional("--tick-period", tickPeriod));
    }

    private static Span optional(String option, String text) {
        return text == null ? null : parse(option, text);
    }

    private static Span parse(String option, String text) {
        try {
            return Span.parse(text);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(option + ": " + e.getMessage(), e);
        }
    }
}
