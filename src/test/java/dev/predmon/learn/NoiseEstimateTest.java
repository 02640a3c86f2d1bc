package dev.predmon.learn;

import dev.predmon.pipeline.LogTrace;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The sensor noise a training set shows, and the hysteresis learn derives from it. */
class NoiseEstimateTest {

    private static LogTrace.Run run(List<Double> levels) {
        return new LogTrace.Run(0, 1, List.of(), false, Map.of("level_i", levels));
    }

    /** A battery draining from 90 to 20 in steps of 0.7, charging back to 100, then draining: two turns, no noise. */
    private static List<Double> smooth() {
        List<Double> v = new ArrayList<>();
        for (double x = 90; x > 20; x -= 0.7) {
            v.add(x);
        }
        for (double x = 20; x < 100; x += 2) {
            v.add(x);
        }
        v.add(100.0);
        v.add(100.0);
        for (double x = 100; x > 80; x -= 0.7) {
            v.add(x);
        }
        return v;
    }

    @Test
    void aSmoothBatteryThatTurnsShowsNoNoiseAndGetsNoHysteresis() {
        assertEquals(List.of(), NoiseEstimate.zigzagSteps(smooth()));
        assertEquals(Map.of(), NoiseEstimate.hysteresis(List.of(run(smooth()), run(smooth()))));
    }

    @Test
    void gaussianNoiseIsMeasuredOnTheOrderOfItsSigma() {
        Random r = new Random(7);
        List<LogTrace.Run> runs = new ArrayList<>();
        for (int k = 0; k < 10; k++) {
            runs.add(run(smooth().stream().map(x -> x + 0.5 * r.nextGaussian()).toList()));
        }
        double h = NoiseEstimate.hysteresis(runs).get("level_i");
        assertTrue(h >= 0.3 && h <= 1.5, "sigma 0.5 gives a hysteresis of the order of the noise, got " + h);
        List<LogTrace.Run> louder = new ArrayList<>();
        for (int k = 0; k < 10; k++) {
            louder.add(run(smooth().stream().map(x -> x + 2.0 * r.nextGaussian()).toList()));
        }
        assertTrue(NoiseEstimate.hysteresis(louder).get("level_i") > h, "more noise, more hysteresis");
    }

    @Test
    void aZigzagIsThreeChangesOfAlternatingSign() {
        assertEquals(List.of(1.0), NoiseEstimate.zigzagSteps(List.of(50.0, 49.0, 50.0, 49.5)));
        assertEquals(List.of(), NoiseEstimate.zigzagSteps(List.of(50.0, 49.0, 49.0, 50.0, 51.0)), "one turn is no zigzag");
    }
}
