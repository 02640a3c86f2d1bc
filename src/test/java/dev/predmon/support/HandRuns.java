package dev.predmon.support;

/**
 * Two hand-written runs of the case study: a recharge run (nominal) and a depleted run (faulty) that share their
 * beginning and part when the depleted run's battery keeps falling on the way to the charging station (thesis
 * Figure 5.6, with the refined bands of Section 5.2).
 */
public final class HandRuns {

    private HandRuns() {
    }

    /** Both scenarios start alike: high battery, to the kitchen, battery drops under 50, to the station. */
    private static Records start(Records r) {
        return r.at(0).level(80).charging(false).isAt("kitchen", false).goTo("kitchen").status("kitchen", 1)
                .at(10).level(70).at(20).level(48).isAt("charging_station", false).halt("kitchen")
                .goTo("charging_station").status("charging_station", 1).at(30).level(43);
    }

    /** Reaches the station at 38%, charges to full, reaches the kitchen. */
    public static Records recharge() {
        return start(new Records()).at(40).level(38).isAt("charging_station", true).charging(true)
                .at(50).level(60).at(60).level(100).charging(false).isAt("kitchen", false).goTo("kitchen")
                .status("kitchen", 1).at(70).level(90).isAt("kitchen", true).halt("kitchen");
    }

    /** Never reaches the station: 38, 33, 28, 23, then 18 (the violation, at t=80) and 0. */
    public static Records depleted() {
        return start(new Records()).at(40).level(38).at(50).level(33).at(60).level(28).at(70).level(23)
                .at(80).level(18).at(90).level(0);
    }
}
