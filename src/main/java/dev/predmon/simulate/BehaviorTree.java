package dev.predmon.simulate;

import java.util.List;
import java.util.function.BooleanSupplier;

/**
 * The case study's behaviour tree (thesis Figure 3.4) with BehaviorTree.CPP's reactive semantics, and its
 * skills (thesis Section 3.2.2), which turn each tick of a leaf into calls on the components.
 *
 * <p>Reactive control nodes re-tick all children from the left on every tick. A child that returns RUNNING
 * makes its parent halt the children after it; SUCCESS of a fallback or FAILURE of a sequence halts all of
 * them. Halting is what makes an action skill send {@code halt(location)}: a robot heading for the kitchen is
 * halted the moment the battery condition fails, and again when {@code IsAtDestination} becomes true.
 */
final class BehaviorTree {

    enum Status { IDLE, RUNNING, SUCCESS, FAILURE }

    private BehaviorTree() {
    }

    /**
     * Builds the tree of the reference document over {@code c}, recording its traffic in {@code r}.
     *
     * @param earlyWarning {@code BatteryLevel} succeeds while the level is strictly above it
     * @param destination  the tour location of {@code IsAtDestination} and {@code GoToDestination}
     */
    static Node build(Components c, Recorder r, double earlyWarning, boolean goToEchoes, String destination) {
        return build(c, r, earlyWarning, goToEchoes, destination, null, null);
    }

    /**
     * The tree of the reference document, with the novelties that change the tree itself.
     *
     * @param lateTurn the battery condition of a tree that turns late, or null for the usual one
     * @param arm      the arm that grasps an object at the tour location (the tree then fetches it once there), or
     *                 null for the case study's tree, which only goes there
     */
    static Node build(Components c, Recorder r, double earlyWarning, boolean goToEchoes, String destination,
                      LateTurn lateTurn, Arm arm) {
        Node batteryLevel = new Condition("BatteryLevel", r, () -> {
            double level = c.level();
            r.call("/BatteryReaderBatteryLevelClient", "/BatteryComponent", "BatteryReader", "level", "",
                    LogWriter.formatDouble(level));
            r.ledger().note(Ledger.Kind.READING, r.lastReply(), null, level);
            return lateTurn == null ? level > earlyWarning : lateTurn.batteryLevel(level, earlyWarning, c.tick());
        });
        Node notCharging = new Condition("BatteryNotCharging", r, () -> r.call(
                "/BatteryReaderBatteryNotChargingClient", "/BatteryComponent", "BatteryReader", "charging_status",
                "", Integer.toString(c.chargingStatus())).equals("0"));
        Node atStation = isAt("IsAtChargingStation", Components.CHARGING_STATION, c, r);
        Node goToStation = new GoTo("GoToChargingStation", Components.CHARGING_STATION, c, r, goToEchoes);
        Node atDestination = isAt("IsAtDestination", destination, c, r);
        Node goToDestination = new GoTo("GoToDestination", destination, c, r, goToEchoes);
        Node battery = Reactive.fallback(
                Reactive.sequence(batteryLevel, notCharging),
                Reactive.sequence(Reactive.fallback(atStation, goToStation), new Wait()));
        if (arm == null) {
            return Reactive.sequence(battery, Reactive.fallback(atDestination, goToDestination));
        }
        Node isFetched = new Condition("IsFetched", r, () -> r.call("/ArmServiceIsFetchedClient", Arm.PORT,
                Arm.PROTOCOL, "hasGrasped", "", arm.hasGrasped() ? "1" : "0").equals("1"));
        return Reactive.sequence(battery, Reactive.fallback(atDestination, goToDestination),
                Reactive.fallback(isFetched, new Fetch(arm, r)));
    }

    private static Node isAt(String skill, String location, Components c, Recorder r) {
        return new Condition(skill, r, () -> r.call("/GoToIsAtClient/" + location, "/GoToComponent", "GoTo",
                "isAtLocation", location, c.isAtLocation(location) ? "1" : "0").equals("1"));
    }

    /** A node of the tree: {@link #tick()} runs it once, {@link #halt()} stops it if it is running. */
    abstract static class Node {
        private Status status = Status.IDLE;

        final Status tick() {
            status = onTick(status);
            return status;
        }

        final void halt() {
            if (status == Status.RUNNING) {
                onHalt();
            }
            status = Status.IDLE;
        }

        /** One tick; {@code previous} is the status this node returned last (IDLE after a halt). */
        abstract Status onTick(Status previous);

        void onHalt() {
        }
    }

    /**
     * BehaviorTree.CPP's {@code ReactiveSequence} and {@code ReactiveFallback}: every tick re-evaluates the children
     * from the left; a child answering {@code stopOn} ends the tick with that answer, a running child ends it
     * running, and children no longer ticked are halted. A sequence stops on FAILURE, a fallback on SUCCESS.
     */
    static final class Reactive extends Node {
        private final Status stopOn;
        private final List<Node> children;

        private Reactive(Status stopOn, Node... children) {
            this.stopOn = stopOn;
            this.children = List.of(children);
        }

        static Reactive sequence(Node... children) {
            return new Reactive(Status.FAILURE, children);
        }

        static Reactive fallback(Node... children) {
            return new Reactive(Status.SUCCESS, children);
        }

        @Override
        Status onTick(Status previous) {
            for (int i = 0; i < children.size(); i++) {
                Status s = children.get(i).tick();
                if (s == Status.RUNNING) {
                    haltFrom(children, i + 1);
                    return Status.RUNNING;
                }
                if (s == stopOn) {
                    haltFrom(children, 0);
                    return stopOn;
                }
            }
            haltFrom(children, 0);
            return stopOn == Status.SUCCESS ? Status.FAILURE : Status.SUCCESS;
        }

        @Override
        void onHalt() {
            haltFrom(children, 0);
        }
    }

    private static void haltFrom(List<Node> children, int from) {
        for (int i = from; i < children.size(); i++) {
            children.get(i).halt();
        }
    }

    /** The tree's {@code Wait} leaf: runs forever, calls nothing; the robot waits while it charges. */
    static final class Wait extends Node {
        @Override
        Status onTick(Status previous) {
            return Status.RUNNING;
        }
    }

    /** The BT side of a skill: the {@code Skill_request} traffic between the tree and the skill. */
    private static String skillPort(String skill, String side) {
        return "/" + skill + "/BT_rpc/" + side;
    }

    private static void ack(Recorder r, String skill, Status s) {
        int code = switch (s) {
            case IDLE -> 0;
            case RUNNING -> 1;
            case SUCCESS -> 2;
            case FAILURE -> 3;
        };
        r.call(skillPort(skill, "client"), skillPort(skill, "server"), "Skill_request", "request_ack", "",
                Integer.toString(code));
    }

    /** A condition skill: one component call per tick, SUCCESS when it answers true. */
    static final class Condition extends Node {
        private final String skill;
        private final Recorder r;
        private final BooleanSupplier query;

        Condition(String skill, Recorder r, BooleanSupplier query) {
            this.skill = skill;
            this.r = r;
            this.query = query;
        }

        @Override
        Status onTick(Status previous) {
            Status s = query.getAsBoolean() ? Status.SUCCESS : Status.FAILURE;
            ack(r, skill, s);
            return s;
        }
    }

    /**
     * An action skill (thesis Figure 3.5): {@code goTo(location)} on its first tick, {@code getStatus(location)}
     * on every later one, {@code halt(location)} when the tree halts it.
     */
    static final class GoTo extends Node {
        private final String skill;
        private final String location;
        private final Components c;
        private final Recorder r;
        private final boolean echoes;
        private final String client;

        GoTo(String skill, String location, Components c, Recorder r, boolean echoes) {
            this.skill = skill;
            this.location = location;
            this.c = c;
            this.r = r;
            this.echoes = echoes;
            this.client = "/GoToGoToClient/" + location;
        }

        @Override
        Status onTick(Status previous) {
            Status s;
            if (previous != Status.RUNNING) {
                r.call(skillPort(skill, "client"), skillPort(skill, "server"), "Skill_request", "send_start", "",
                        "");
                c.goTo(location);
                r.call(client, "/GoToComponent", "GoTo", "goTo", location, echoes ? "" : location,
                        echoes ? location : "");
                r.ledger().note(Ledger.Kind.GO_TO, r.lastCommand(), location, 0);
                s = Status.RUNNING;
            } else {
                int code = c.getStatus(location);
                r.call(client, "/GoToComponent", "GoTo", "getStatus", location, Integer.toString(code));
                r.ledger().note(Ledger.Kind.STATUS, r.lastReply(), location, code);
                s = code == Components.SUCCESS ? Status.SUCCESS
                        : code == Components.ABORT ? Status.FAILURE : Status.RUNNING;
            }
            ack(r, skill, s);
            return s;
        }

        @Override
        void onHalt() {
            r.call(skillPort(skill, "client"), skillPort(skill, "server"), "Skill_request", "send_stop", "", "");
            c.halt(location);
            r.call(client, "/GoToComponent", "GoTo", "halt", location, "");
            r.ledger().note(Ledger.Kind.HALT, r.lastCommand(), location, 0);
        }
    }

    /**
     * The fetch skill of the R1 fetch-and-carry tree: on its first tick {@code preGrasp} and {@code extractHand}, then
     * one attempt per tick ({@code openHand}, {@code closeHand}, {@code hasGrasped}) until the hand holds the object.
     */
    static final class Fetch extends Node {
        private static final String CLIENT = "/ArmServiceFetchClient";
        private final Arm arm;
        private final Recorder r;

        Fetch(Arm arm, Recorder r) {
            this.arm = arm;
            this.r = r;
        }

        @Override
        Status onTick(Status previous) {
            if (previous != Status.RUNNING) {
                r.call(skillPort("Fetch", "client"), skillPort("Fetch", "server"), "Skill_request", "send_start", "",
                        "");
                r.call(CLIENT, Arm.PORT, Arm.PROTOCOL, "preGrasp", "", Arm.OK);
                r.call(CLIENT, Arm.PORT, Arm.PROTOCOL, "extractHand", "", Arm.OK);
            }
            r.call(CLIENT, Arm.PORT, Arm.PROTOCOL, "openHand", "", Arm.OK);
            boolean held = arm.closeHand();
            r.call(CLIENT, Arm.PORT, Arm.PROTOCOL, "closeHand", "", Arm.OK);
            r.call(CLIENT, Arm.PORT, Arm.PROTOCOL, "hasGrasped", "", held ? "1" : "0");
            r.ledger().note(Ledger.Kind.GRASP, r.lastReply(), null, held ? 1 : 0);
            Status s = held ? Status.SUCCESS : Status.RUNNING;
            ack(r, "Fetch", s);
            return s;
        }

        @Override
        void onHalt() {
            r.call(skillPort("Fetch", "client"), skillPort("Fetch", "server"), "Skill_request", "send_stop", "", "");
        }
    }
}
