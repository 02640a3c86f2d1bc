package dev.predmon.support;

import dev.predmon.simulate.LogWriter;
import dev.predmon.simulate.Scenario;
import dev.predmon.simulate.SimOptions;
import dev.predmon.simulate.Simulator;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** Writes small simulated log directories in the {@code learn} layout. */
public final class SimulatedSets {

    private SimulatedSets() {
    }

    /** {@code runs} runs of each scenario, seeds {@code firstSeed..}, under {@code dir}. */
    public static Path write(Path dir, int runs, long firstSeed) throws IOException {
        for (Scenario s : Scenario.values()) {
            Path d = Files.createDirectories(dir.resolve(s.id()));
            Files.writeString(d.resolve("scenario.json"),
                    "{\"faulty\": " + s.faulty() + ", \"description\": \"" + s.id() + "\"}");
            for (long seed = firstSeed; seed < firstSeed + runs; seed++) {
                Files.writeString(d.resolve(s.id() + "-" + seed + ".log"),
                        LogWriter.toText(Simulator.run(s, seed, SimOptions.defaults()), SimOptions.defaults()));
            }
        }
        return dir;
    }
}
