package dev.predmon.cli;

import dev.predmon.BadInputException;
import dev.predmon.Terminal;
import picocli.CommandLine;
import picocli.CommandLine.IDefaultValueProvider;
import picocli.CommandLine.Model.ArgSpec;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.ParameterException;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeSet;
import java.util.regex.Pattern;

/**
 * A command's settings from one file, for a service: one {@code name = value} a line, {@code name} a long option of
 * the command without its dashes, {@code #} starting a comment line. The value is the rest of the line without the
 * blanks around it, taken as it is (no quotes, no escapes, no variables): what the option would get on the command
 * line. A value all in quotes is refused, since its quotes would reach the option. A switch takes {@code true} or {@code false}. An option that may be repeated ({@code log}) may be repeated;
 * any other is set once.
 *
 * <p>It is picocli's default-value provider of the command: an option given on the command line wins, and picocli
 * converts and checks the file's values as it does the command line's. Every entry is checked when the file is read,
 * before anything runs, so that a mistake is one line naming the file, the line and what was expected (exit 2, as
 * the same mistake on the command line); a file that cannot be read is bad input (exit 3).
 */
final class ConfigFile implements IDefaultValueProvider {

    /** No settings file is this long: a longer one is some other file. */
    static final int MAX_BYTES = 1 << 20;
    private static final Pattern NAME = Pattern.compile("[a-z][a-z0-9-]*");
    /** Options that are no setting: they ask for something else than watching, or name this file. */
    private static final List<String> NOT_SETTINGS = List.of("--config", "--help", "--version");

    /** One entry of the file. */
    record Entry(String name, String value, int line) {
    }

    private final Path file;
    /** By option name ({@code --log}), in the file's order. */
    private final Map<String, List<Entry>> entries;

    private ConfigFile(Path file, Map<String, List<Entry>> entries) {
        this.file = file;
        this.entries = entries;
    }

    /**
     * Reads {@code file} and checks every entry against {@code spec}'s options.
     *
     * @throws ParameterException naming the file and line of the first mistake; for a file that cannot be read, its
     *                            cause is a {@link BadInputException}
     */
    static ConfigFile read(Path file, CommandSpec spec) {
        List<String> lines = lines(file, spec);
        Map<String, List<Entry>> entries = new LinkedHashMap<>();
        CommandLine probe = null;
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i).strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            int n = i + 1;
            int eq = line.indexOf('=');
            if (eq < 0) {
                throw error(spec, file, n, "expected 'name = value' (a long option of '" + spec.qualifiedName()
                        + "' without its dashes), got '" + Terminal.line(shorten(line)) + "'");
            }
            String name = line.substring(0, eq).strip();
            String value = line.substring(eq + 1).strip();
            OptionSpec option = option(spec, file, n, name);
            List<Entry> earlier = entries.computeIfAbsent(option.longestName(), k -> new ArrayList<>());
            if (!earlier.isEmpty() && !repeatable(option)) {
                throw error(spec, file, n, "'" + name + "' is set again (first on line " + earlier.get(0).line()
                        + "); it takes one value");
            }
            if (value.isEmpty()) {
                throw error(spec, file, n, "'" + name + "' has no value");
            }
            if (quoted(value)) {
                // taken as it is, the quotes would reach the option: a hook's shell would look for a command named
                // "echo ..." and fail at the first warning
                throw error(spec, file, n, "'" + name + "' is quoted: values are taken as they are, quotes included; "
                        + "write it without the quotes around it");
            }
            if (option.arity().max() == 0) {
                checkSwitch(spec, file, n, option, value);
            } else {
                if (probe == null) {
                    probe = probe(spec);
                }
                check(spec, probe, file, n, option, value);
            }
            earlier.add(new Entry(name, value, n));
        }
        return new ConfigFile(file, entries);
    }

    /** The file's lines, UTF-8. */
    private static List<String> lines(Path file, CommandSpec spec) {
        try {
            if (Files.isDirectory(file)) {
                throw new BadInputException(file + ": cannot read: is a directory; --config names a settings file");
            }
            byte[] bytes;
            try (InputStream in = Files.newInputStream(file)) {
                // at most a byte past the limit: /dev/zero or a FIFO has no size to ask first
                bytes = in.readNBytes(MAX_BYTES + 1);
            }
            if (bytes.length > MAX_BYTES) {
                throw new BadInputException(file + ": larger than 1 MiB: not a settings file");
            }
            String text = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(bytes)).toString();
            // a byte-order mark, as some editors write one, is no part of the first name
            return (text.startsWith("\uFEFF") ? text.substring(1) : text).lines().toList();
        } catch (CharacterCodingException e) {
            throw unreadable(spec, new BadInputException(file + ": not UTF-8 text: not a settings file", e));
        } catch (IOException e) {
            throw unreadable(spec, BadInputException.cannotRead(file, e));
        } catch (BadInputException e) {
            throw unreadable(spec, e);
        }
    }

    /** Whether {@code value} is all in one pair of quotes, {@code "..."} or {@code '...'}, with none inside. */
    static boolean quoted(String value) {
        if (value.length() < 2) {
            return false;
        }
        char q = value.charAt(0);
        return (q == '"' || q == '\'') && value.charAt(value.length() - 1) == q
                && value.indexOf(q, 1) == value.length() - 1;
    }

    private static ParameterException unreadable(CommandSpec spec, BadInputException e) {
        return new ParameterException(spec.commandLine(), e.getMessage(), e);
    }

    /** The option a name in the file stands for. */
    private static OptionSpec option(CommandSpec spec, Path file, int line, String name) {
        if (name.startsWith("-")) {
            throw error(spec, file, line, "write the option's name without its dashes: '"
                    + name.replaceFirst("^-+", "") + "'");
        }
        OptionSpec option = NAME.matcher(name).matches() ? spec.findOption("--" + name) : null;
        if (option == null || option.inherited() || NOT_SETTINGS.contains(option.longestName())) {
            throw error(spec, file, line, "unknown setting '" + Terminal.line(shorten(name)) + "'; the settings are "
                    + String.join(", ", names(spec)));
        }
        if (!option.longestName().equals("--" + name)) {
            throw error(spec, file, line, "write '" + option.longestName().substring(2) + "', the option's long name");
        }
        return option;
    }

    /** Every name the file may set, sorted. */
    static List<String> names(CommandSpec spec) {
        TreeSet<String> names = new TreeSet<>();
        for (OptionSpec o : spec.options()) {
            if (!o.inherited() && !NOT_SETTINGS.contains(o.longestName()) && o.longestName().startsWith("--")) {
                names.add(o.longestName().substring(2));
            }
        }
        return List.copyOf(names);
    }

    /** Whether the file may give {@code option} several times: a list of paths or texts, as --log is. */
    private static boolean repeatable(OptionSpec option) {
        if (!option.isMultiValue()) {
            return false;
        }
        Class<?> type = option.typeInfo().getAuxiliaryTypes()[0];
        return type == Path.class || type == String.class;
    }

    private static void checkSwitch(CommandSpec spec, Path file, int line, OptionSpec option, String value) {
        if (!value.equalsIgnoreCase("true") && !value.equalsIgnoreCase("false")) {
            throw error(spec, file, line, "'" + option.longestName().substring(2) + "' is a switch: true or false, "
                    + "got '" + Terminal.line(shorten(value)) + "'");
        }
    }

    /**
     * A command line of the command's own to check values on: its conversions and checks give picocli's message, or
     * the option's own, to which the file and line are put in front. The command's required options get a stand-in,
     * so that only the value checked is judged.
     */
    private static CommandLine probe(CommandSpec spec) {
        CommandLine probe = new CommandLine(spec.userObject().getClass());
        // asked before the provider is set: picocli asks the provider whether an option is required
        List<ArgSpec> required = probe.getCommandSpec().requiredArgs();
        probe.setDefaultValueProvider(arg -> required.contains(arg) ? "-" : null);
        return probe;
    }

    /** Checks a value as the command line would take it. */
    private static void check(CommandSpec spec, CommandLine probe, Path file, int line, OptionSpec option,
                              String value) {
        try {
            probe.parseArgs(option.longestName() + "=" + value);
        } catch (ParameterException e) {
            throw error(spec, file, line, e.getMessage());
        }
    }

    private static ParameterException error(CommandSpec spec, Path file, int line, String message) {
        return new ParameterException(spec.commandLine(), file + ":" + line + ": " + message);
    }

    private static String shorten(String s) {
        return s.length() > 60 ? s.substring(0, 60) + "..." : s;
    }

    /**
     * The file's value of an option the command line did not give, as picocli takes it: {@code $} doubled, since
     * picocli would otherwise replace {@code ${NAME}} in it by a variable (a hook command's {@code $PREDMON_...}
     * are the shell's). For an option set several times, the first (see {@link #complete}).
     */
    @Override
    public String defaultValue(ArgSpec arg) {
        if (!(arg instanceof OptionSpec o)) {
            return null;
        }
        List<Entry> e = entries.get(o.longestName());
        if (e == null) {
            return null;
        }
        String value = e.get(0).value();
        return o.arity().max() == 0 ? value.toLowerCase(Locale.ROOT) : value.replace("$", "$$");
    }

    /**
     * After parsing: the options the file gives several values and the command line none get all of them (picocli
     * takes one default value per option).
     */
    void complete(CommandSpec spec) {
        for (Map.Entry<String, List<Entry>> e : entries.entrySet()) {
            OptionSpec option = spec.findOption(e.getKey());
            if (e.getValue().size() < 2 || spec.commandLine().getParseResult().hasMatchedOption(option)) {
                continue;
            }
            boolean paths = option.typeInfo().getAuxiliaryTypes()[0] == Path.class; // else texts, see repeatable
            List<Object> values = new ArrayList<>();
            for (Entry entry : e.getValue()) {
                values.add(paths ? Path.of(entry.value()) : entry.value());
            }
            option.setValue(values);
        }
    }

    @Override
    public String toString() {
        return file.toString();
    }
}
