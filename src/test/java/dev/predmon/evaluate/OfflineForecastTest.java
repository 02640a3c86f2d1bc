package dev.predmon.evaluate;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.forecast.Forecast;
import dev.predmon.forecast.Forecaster;
import dev.predmon.learn.ForecastTraining;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.pipeline.LogTrace;
import dev.predmon.pipeline.RunLabel;
import dev.predmon.pipeline.RunTiming;
import dev.predmon.pipeline.Traces;
import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Novelties;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.SimRun;
import dev.predmon.simulate.Simulator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

/**
 * The forecast {@code learn} makes of a training run (to choose the threshold and the calibration) is the one
 * {@code watch} makes of the same log, also where the log names a place the abstraction does not know: the trace
 * misses a step there, and both treat the run as novel from that message.
 */
class OfflineForecastTest {

    @TempDir
    Path tmp;

    @Test
    void learnForecastsARunToANewPlaceAsWatchDoes() throws Exception {
        Abstraction abstraction = AbstractionFiles.defaults();
        ModelSet models = ModelStore.read(Path.of("models"), abstraction);
        SimOptions options = SimOptions.defaults().withNovelties(Novelties.NONE.withNewLocation("office"));
        SimRun sim = Simulator.run(Scenario.RECHARGE, 3, options);
        Path log = Files.writeString(tmp.resolve("office.log"), LogWriter.toText(sim, options));

        LogTrace.Run run = Traces.read(log, abstraction).runs().get(0);
        List<RunTiming.Gap> gaps = run.timing().gaps();
        assertFalse(gaps.isEmpty(), "the messages about the office are gaps in the trace");
        List<Forecast> offline = ForecastTraining.forecast(new Forecaster(models.forecast(), models.machines()), run);

        Trail trail = new Trail();
        Replay.run(log, "recharge", false, RunLabel.ALL, -1, models, abstraction, 0, abstraction.confirm(),
                PredictiveMonitor.defaultRule(models), trail);
        List<Forecast> watched = trail.afterPairs(0);

        assertEquals(Long.valueOf(gaps.get(0).line()), offline.get(offline.size() - 1).novelSince());
        List<Long> offlineNovel = offline.stream().map(Forecast::novelSince).distinct().toList();
        List<Long> watchedNovel = watched.stream().map(Forecast::novelSince).distinct().toList();
        assertEquals(watchedNovel, offlineNovel, "novel from the same line, offline and live");
    }
}
