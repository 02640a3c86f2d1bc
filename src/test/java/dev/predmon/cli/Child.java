package dev.predmon.cli;

import org.junit.jupiter.api.Assumptions;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertTrue;

/** predmon run as a real child process (its own JVM, working directory and signals), with what it printed. */
record Child(int code, String out, String err) {

    /** The command line of {@code predmon ARGS} in a JVM of its own (C1 only: it starts in a third of the time). */
    static List<String> command(String... args) {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), Main.class.getName()));
        command.addAll(List.of(args));
        return command;
    }

    /** {@code p}'s standard output, line by line as it comes, read by a thread of its own until {@code p} ends. */
    static List<String> stdoutLines(Process p) {
        List<String> out = new CopyOnWriteArrayList<>();
        Thread reader = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
                for (String line = r.readLine(); line != null; line = r.readLine()) {
                    out.add(line);
                }
            } catch (IOException e) {
                // the child is gone
            }
        }, "child-stdout");
        reader.setDaemon(true);
        reader.start();
        return out;
    }

    /** Runs {@code predmon ARGS} in {@code cwd} to its end. */
    static Child run(Path cwd, String... args) throws Exception {
        return run(cwd, List.of(), args);
    }

    /**
     * As {@link #run}, but as a user whom file permissions bind: as root, without the capabilities that override
     * them (with setpriv; the test is skipped where there is none).
     */
    static Child runBoundByPermissions(Path cwd, String... args) throws Exception {
        if (!"root".equals(System.getProperty("user.name"))) {
            return run(cwd, List.of(), args);
        }
        Assumptions.assumeTrue(Files.isExecutable(Path.of("/usr/bin/setpriv")),
                "as root, permissions can only be tested with setpriv");
        return run(cwd, List.of("/usr/bin/setpriv", "--inh-caps=-dac_override,-dac_read_search",
                "--bounding-set=-dac_override,-dac_read_search"), args);
    }

    /**
     * As {@link #run}, with a limit on the size of every file it writes ({@code ulimit -f}, in KiB): a write past it
     * fails as on a full disk (the JVM ignores SIGXFSZ). Skipped where there is no bash.
     */
    static Child runWithFileSizeLimit(Path cwd, int kib, String... args) throws Exception {
        Assumptions.assumeTrue(Files.isExecutable(Path.of("/bin/bash")), "ulimit needs bash");
        return run(cwd, List.of("/bin/bash", "-c", "ulimit -f " + kib + " && exec \"$@\"", "predmon"), args);
    }

    private static Child run(Path cwd, List<String> prefix, String... args) throws Exception {
        List<String> command = new ArrayList<>(prefix);
        command.addAll(command(args));
        Path out = Files.createTempFile("predmon-out", ".txt");
        Path err = Files.createTempFile("predmon-err", ".txt");
        try {
            Process p = new ProcessBuilder(command).directory(cwd.toFile())
                    .redirectOutput(out.toFile()).redirectError(err.toFile()).start();
            assertTrue(p.waitFor(60, TimeUnit.SECONDS), "predmon finished");
            return new Child(p.exitValue(), Files.readString(out), Files.readString(err));
        } finally {
            Files.deleteIfExists(out);
            Files.deleteIfExists(err);
        }
    }
}
