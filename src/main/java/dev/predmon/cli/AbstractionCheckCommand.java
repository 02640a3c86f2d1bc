package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.Terminal;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.learn.RecordingFolder;
import dev.predmon.learn.TrainingEvidence;
import dev.predmon.property.UnseenNames;
import dev.predmon.property.Vocabulary;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Callable;

/**
 * {@code abstraction check FILE LOGS...}: every name of the abstraction's properties that no record of the logs holds,
 * one line each, at its key with the nearest names that occur: what {@code learn} warns of, before learning.
 */
@Command(name = "check", mixinStandardHelpOptions = true,
        description = {"Check the properties of an abstraction against logs: one line for every name (a command, a "
                + "port, a protocol, a reply) of a property that no record of the logs holds, at its key in the file "
                + "(properties[2].event.command) with the nearest names that do occur. Such a property reads "
                + "\"no evidence\" on every run like these, never \"holds\".",
                "An absence's event is checked to its message: that its forbidden value never came is the absence "
                        + "holding.",
                "Exit 0 when every name occurs, 1 when one does not, 3 when the abstraction or a log cannot be read."})
final class AbstractionCheckCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "FILE", description = "An abstraction JSON file, or a built-in's name.")
    String file;

    @Parameters(index = "1..*", arity = "1..*", paramLabel = "LOGS",
            description = "Log files, or folders: every *.log and *.txt file under a folder is a log.")
    List<Path> logs;

    @Override
    public Integer call() throws Exception {
        Abstraction abstraction = AbstractionOption.resolve(file);
        Set<Path> all = new LinkedHashSet<>();
        for (Path p : logs) {
            if (Files.isDirectory(p)) {
                all.addAll(RecordingFolder.logs(p));
            } else if (Files.isRegularFile(p)) {
                all.add(p);
            } else {
                throw new BadInputException(p + ": cannot read: no such file or folder");
            }
        }
        if (all.isEmpty()) {
            throw new BadInputException(String.join(", ", logs.stream().map(Path::toString).toList())
                    + ": no *.log or *.txt file to check the properties against");
        }
        Vocabulary seen = TrainingEvidence.vocabulary(all, abstraction.format());
        if (seen.records() == 0) {
            throw new BadInputException(new ArrayList<>(all).get(0) + (all.size() > 1 ? " and the other logs" : "")
                    + ": no YARP monitor record; are these monitor logs?");
        }
        List<UnseenNames.Problem> problems = UnseenNames.check(abstraction.properties(), seen);
        PrintWriter out = spec.commandLine().getOut();
        problems.forEach(p -> out.println(Terminal.line(file + ": " + p.describe())));
        String against = seen.records() + " records of " + all.size() + " log(s)";
        out.println(problems.isEmpty() ? "every name of the " + abstraction.properties().size() + " properties "
                + "occurs in the " + against : problems.size() + " name(s) occur in none of the " + against
                + ": the properties that hold them read \"no evidence\" on runs like these");
        out.flush();
        return problems.isEmpty() ? ExitCodes.OK : ExitCodes.WARNING;
    }
}
