package dev.predmon.cli;

import dev.predmon.Terminal;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.learn.Conflict;
import dev.predmon.learn.LearnedScenario;
import dev.predmon.learn.Learning;
import dev.predmon.pipeline.UnmappedMessages;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.Callable;

/** {@code predmon learn}: one Mealy machine per scenario (more when its runs conflict), written as DOT. */
@Command(name = "learn", mixinStandardHelpOptions = true,
        description = {"Learn one Mealy machine per scenario from logs with LearnLib's BlueFringeRPNIMealy.",
                "--logs holds one directory per scenario with its *.log files and a scenario.json "
                        + "{\"faulty\": true|false, \"description\": \"...\"}, or is a folder of recordings not "
                        + "sorted into scenarios: every *.log and *.txt file in it and its subfolders is a log, and the "
                        + "abstraction's safety monitor labels each run (scenarios 'violating' and 'safe'). Runs of a "
                        + "scenario that disagree "
                        + "after the same inputs are split into conflict-free groups, one machine each "
                        + "(<scenario>-<k>.dot). Writes <models>/*.dot, <models>/index.json and "
                        + "<models>/abstraction.json atomically.",
                "--models must be new, empty or a model directory learn wrote, and apart from --logs: anything "
                        + "else is refused (exit 3) and left untouched.",
                "Names, one line each on stderr, every name of a property (a command, a port, a protocol, a reply) "
                        + "that no training log holds, at its key in the abstraction file with the nearest names that "
                        + "occur: a warning, since such a property reads \"no evidence\" on every run, never \"holds\" "
                        + "('predmon abstraction check FILE LOGS...' checks the same before learning).",
                "Prints per property how many training runs violated it and how many gave no evidence for it.",
                "Ends with the models' scorecard, per property: the violations warned and the false alarms in "
                        + "cross-validation, the median lead, and the Brier score against the base rate's."})
final class LearnCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Mixin
    AbstractionOption abstractionOption;

    @Option(names = "--logs", paramLabel = "DIR", defaultValue = "sample-logs", description = "Log directory (default: ${DEFAULT-VALUE}).")
    Path logs;

    @Option(names = "--models", paramLabel = "DIR", defaultValue = "models", description = "Model directory to write (default: ${DEFAULT-VALUE}).")
    Path models;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Abstraction abstraction = abstractionOption.load();
        Map<UnmappedMessage, Long> unmapped = new TreeMap<>();
        Learning.Result result;
        // Ctrl-C (or SIGTERM) ends the JVM with 130 (143): say so, and what the model directory holds, in one line.
        String stoppedLine = String.format("predmon: learn stopped before it finished; %s holds whole models, the "
                + "ones it held before (or the new ones, if they were already being put in place): run learn again",
                Terminal.line(models.toString()));
        Thread stopped = new Thread(() -> {
            out.flush();
            err.println(stoppedLine);
            err.flush();
        }, "learn-stopped");
        Runtime.getRuntime().addShutdownHook(stopped);
        try {
            result = Learning.learnAndWrite(logs, models, abstraction, l -> {
                l.problems().forEach(err::println);
                l.skipped().forEach(msg -> err.println("predmon: skipped " + msg));
                l.unmapped().forEach((k, n) -> unmapped.merge(k, n, Long::sum));
                report(out, l);
            });
        } finally {
            try {
                Runtime.getRuntime().removeShutdownHook(stopped);
            } catch (IllegalStateException shuttingDown) {
                // the JVM is already ending: the hook says why
            }
        }
        List<LearnedScenario> learned = result.scenarios();
        result.notes().forEach(n -> err.println("predmon: note: " + n));
        if (!unmapped.isEmpty()) {
            err.println("predmon: interface messages that no abstraction rule maps (not learned), by command:");
            UnmappedMessages.lines(unmapped).forEach(line -> err.println("  " + Terminal.line(line)));
            UnmappedMessages.likelyFix(unmapped, abstraction).ifPresent(fix -> err.println("predmon: warning: the "
                    + "built-in abstraction '" + fix + "' maps most of what '" + abstraction.name() + "' leaves out of "
                    + "these logs: is it the one they need? try --abstraction " + fix));
        }
        if (learned.stream().noneMatch(l -> l.spec().faulty())) {
            err.println("predmon: note: no scenario is faulty, so 'watch' can never warn with these models");
        }
        if (learned.stream().allMatch(l -> l.spec().faulty())) {
            err.println("predmon: note: no scenario is nominal, so 'watch' warns at the first faulty match");
        }
        String file = abstractionOption.value == null ? abstraction.name() : abstractionOption.value;
        result.evidence().unseen().forEach(p -> err.println("predmon: warning: " + Terminal.line(file + ": "
                + p.describe())));
        int machines = learned.stream().mapToInt(l -> l.machines().size()).sum();
        out.println("wrote " + models + ": " + machines + " machine(s) for " + learned.size() + " scenario(s), "
                + "abstraction '" + abstraction.name() + "'");
        result.evidence().runs().forEach(r -> out.println(r.line()));
        result.forecast().allScorecards().forEach(c -> c.lines().forEach(out::println));
        new java.util.TreeMap<>(result.forecast().events()).forEach((id, e) -> {
            if (!e.forecasts()) {
                out.println(id + ": no forecast: " + e.why());
            }
        });
        out.flush();
        return ExitCodes.OK;
    }

    private static void report(PrintWriter out, LearnedScenario l) {
        int samples = l.machines().stream().mapToInt(m -> m.samples().size()).sum();
        StringBuilder sb = new StringBuilder();
        sb.append("scenario ").append(l.spec().name()).append(l.spec().faulty() ? " (faulty)" : " (nominal)")
                .append(": ").append(samples).append(" run(s) -> ");
        for (int i = 0; i < l.machines().size(); i++) {
            LearnedScenario.Machine m = l.machines().get(i);
            sb.append(i == 0 ? "" : ", ").append(m.id()).append(".dot ").append(m.machine().size())
                    .append(" states from ").append(m.samples().size()).append(" run(s)");
        }
        out.println(sb);
        for (Conflict c : l.splits()) {
            out.println("  split: " + c.describe());
        }
    }
}
