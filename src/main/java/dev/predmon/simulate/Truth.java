package dev.predmon.simulate;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What really happened in a run, written beside the log as {@code <log>.truth.json} so that evaluations
 * can compare a monitor's warnings with the ground truth.
 *
 * @param scenario        the story told
 * @param faulty          whether the run violates the safety requirement
 * @param seed            the seed the run was simulated from
 * @param parameters      the sampled physical parameters
 * @param violationTime   log time of the first {@code level} reply below 20.0, or null
 * @param violationLevel  that reply's value, or null
 * @param turnTime        log time of the first {@code level} reply at or below the early warning, or null
 * @param turnLevel       that reply's value: the level at which the robot turned towards the station, or null
 * @param stationLevel    the last {@code level} reply before the robot was first at the station, or null
 * @param endTime         log time of the last record
 * @param batteryTimeline one {@code [time, level]} point per {@code level} reply
 * @param novelties       what the run's novelties made happen, or null when it was simulated without any (the
 *                        JSON then has no {@code novelties} field, as before novelties existed)
 * @param properties      per property id ({@code battery}, {@code charger-in-time}, {@code no-abort},
 *                        {@code navigation-in-time}, {@code grasp-in-time}), whether the run violated it and where
 *                        first, as the simulator judged it from what it did ({@link PropertyJudge})
 */
public record Truth(Scenario scenario, boolean faulty, long seed, SimParameters parameters, Double violationTime,
                    Double violationLevel, Double turnTime, Double turnLevel, Double stationLevel, double endTime,
                    List<double[]> batteryTimeline, NoveltyTruth novelties, Map<String, PropertyTruth> properties) {

    public Truth {
        properties = properties == null ? Map.of() : Collections.unmodifiableMap(
                new LinkedHashMap<>(properties));
    }

    /** The truth of a run without novelties, whose properties were not judged. */
    public Truth(Scenario scenario, boolean faulty, long seed, SimParameters parameters, Double violationTime,
                 Double violationLevel, Double turnTime, Double turnLevel, Double stationLevel, double endTime,
                 List<double[]> batteryTimeline) {
        this(scenario, faulty, seed, parameters, violationTime, violationLevel, turnTime, turnLevel, stationLevel,
                endTime, batteryTimeline, null, null);
    }

    /** The same truth for the run shifted {@code seconds} later in its log (its lines where they were). */
    public Truth shifted(double seconds) {
        return shifted(seconds, novelties == null ? null : novelties.gapBefore(), 0);
    }

    /**
     * The same truth for the run shifted {@code seconds} later in its log, {@code gap} seconds after the previous, and
     * {@code lines} lines further down.
     */
    Truth shifted(double seconds, Double gap, long lines) {
        List<double[]> timeline = batteryTimeline.stream().map(p -> new double[] {p[0] + seconds, p[1]}).toList();
        Map<String, PropertyTruth> moved = new LinkedHashMap<>();
        properties.forEach((id, p) -> moved.put(id, p.shifted(lines, seconds)));
        return new Truth(scenario, faulty, seed, parameters, plus(violationTime, seconds), violationLevel,
                plus(turnTime, seconds), turnLevel, stationLevel, endTime + seconds, timeline,
                novelties == null ? null : novelties.shifted(seconds, gap), moved);
    }

    private static Double plus(Double t, double seconds) {
        return t == null ? null : t + seconds;
    }
}
