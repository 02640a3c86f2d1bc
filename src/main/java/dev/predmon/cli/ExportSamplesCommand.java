package dev.predmon.cli;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.evaluate.SampleFile;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.learn.ScenarioLayout;
import dev.predmon.learn.ScenarioLearner;
import dev.predmon.learn.ScenarioSpec;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
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
        Files.createDirectories(out);
        for (ScenarioSpec s : ScenarioLayout.scan(logs, abstraction)) {
            // learn() itself, so the samples are exactly those learn feeds LearnLib, grouped as it groups them.
            LearnedScenario l = ScenarioLearner.learn(s, abstraction);
            l.skipped().forEach(msg -> err.println("predmon: skipped " + msg));
            Path file = out.resolve(s.name() + ".txt");
            Files.writeString(file, SampleFile.text(l), StandardCharsets.UTF_8);
            int n = l.machines().stream().mapToInt(m -> m.samples().size()).sum();
            o.println("wrote " + file + ": " + n + " trace(s)");
        }
        o.flush();
        err.flush();
        return ExitCodes.OK;
    }
}
