package dev.predmon.simulate;

import java.util.Locale;

/**
 * The three stories of the thesis's Section 5.1 that the simulator can tell. Only {@link #DEPLETED} is
 * faulty: it is the scenario a predictive monitor must recognise before the battery monitor fires.
 */
public enum Scenario {
    /** Scenario 1: the robot reaches the kitchen and the level never falls to the early-warning threshold. */
    DIRECT(false, "the robot reaches the kitchen; the battery never falls to the early-warning threshold"),
    /** Scenario 2: the robot recharges on the way, at or above 20%, then reaches the kitchen. */
    RECHARGE(false, "the battery falls to the early-warning threshold on the way; the robot recharges to full "
            + "at the charging station, never below 20%, then reaches the kitchen"),
    /** Scenario 3: the charging station is too far; the battery falls below 20% before the robot gets there. */
    DEPLETED(true, "the battery falls to the early-warning threshold; the robot heads for the charging station, "
            + "which is too far: the level falls below 20% before it arrives and the battery runs out");

    private final boolean faulty;
    private final String description;

    Scenario(boolean faulty, String description) {
        this.faulty = faulty;
        this.description = description;
    }

    /** Whether runs of this scenario violate the safety requirement (battery level >= 20%). */
    public boolean faulty() {
        return faulty;
    }

    /** One sentence for humans and for {@code scenario.json}. */
    public String description() {
        return description;
    }

    /** The name used on the command line and in file names: {@code direct}, {@code recharge}, {@code depleted}. */
    public String id() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The scenario named {@code id}, case-insensitively. */
    public static Scenario fromId(String id) {
        for (Scenario s : values()) {
            if (s.id().equalsIgnoreCase(id.trim())) {
                return s;
            }
        }
        throw new IllegalArgumentException("unknown scenario '" + id + "' (expected direct, recharge or depleted)");
    }
}
