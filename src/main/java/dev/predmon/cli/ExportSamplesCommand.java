package dev.predmon.cli;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.files.AtomicFiles;
import dev.predmon.files.OutputFiles;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.learn.ScenarioLearner;
import dev.predmon.learn.ScenarioSpec;
import dev.predmon.samples.SampleFile;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

/** {@code predmon export-samples}: the Mealy samples of {@code learn}, for other learners. */
@Command(name = "export-samples", mixinStandardHelpOptions = true,
        description = {"Write the exact Mealy samples that 'learn' gives LearnLib, one file per scenario "
                + "(<out>/<scenario>.txt), so other learners (AALpy, flexfringe) can be run on the same data.",
                "Format: '#' comment lines (# scenario:, # faulty:, # machine: before each group learned as one "
                        + "machine), then one trace per line: steps 'input/output' separated by single spaces."})
final class ExportSamplesCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--logs", required = true, paramLabel = "DIR", description = "Log directory in the 'learn' layout.")
    Path logs;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "Directory to write the sample files to.")
    Path out;

    @Mixin
    AbstractionOption abstractionOption;

    @Override
    public Integer call() throws Exception {
        PrintWriter o = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Abstraction abstraction = abstractionOption.load();
        List<OutputFiles.Input> inputs = new ArrayList<>(abstractionOption.inputs());
        inputs.add(new OutputFiles.Input(logs, "--logs"));
        OutputFiles.requireOutputDirectory(out, "--out", inputs);
        List<ScenarioSpec> specs = ScenarioLayout.scan(logs, abstraction);
        for (ScenarioSpec s : specs) {
            // Checked before learning: a file that is not a sample file is refused at once, and nothing is written.
            OutputFiles.requireReplaceable(fileOf(s), "--out", SampleFile.SIGNATURE, "a sample file", inputs);
        }
        // Everything is learned before anything is written: a failure (a bad log, a bad scenario.json) leaves no
        // empty or half-written --out behind.
        List<LearnedScenario> learned = new ArrayList<>();
        for (ScenarioSpec s : specs) {
            // learn() itself, so the samples are exactly those learn feeds LearnLib, grouped as it groups them.
            LearnedScenario l = ScenarioLearner.learn(s, abstraction);
            l.skipped().forEach(msg -> err.println("predmon: skipped " + msg));
            learned.add(l);
        }
        Path created = null; // the topmost directory this run creates, if any
        for (Path p = out.toAbsolutePath().normalize(); p != null && !Files.exists(p); p = p.getParent()) {
            created = p;
        }
        List<Path> written = new ArrayList<>();
        try {
            Files.createDirectories(out);
            for (LearnedScenario l : learned) {
                Path file = fileOf(l.spec());
                AtomicFiles.replace(file, SampleFile.text(l));
                written.add(file);
                int n = l.machines().stream().mapToInt(m -> m.samples().size()).sum();
                o.println("wrote " + file + ": " + n + " trace(s)");
            }
        } catch (IOException e) {
            if (created != null) { // directories of its own: remove what this run put there
                for (Path f : written) {
                    Files.deleteIfExists(f);
                }
                for (Path d = out.toAbsolutePath().normalize(); d != null && d.startsWith(created); d = d.getParent()) {
                    Files.deleteIfExists(d);
                }
            }
            throw e;
        }
        o.flush();
        err.flush();
        return ExitCodes.OK;
    }

    private Path fileOf(ScenarioSpec s) {
        return out.resolve(s.name() + ".txt");
    }
}
