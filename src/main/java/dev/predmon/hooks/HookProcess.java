package dev.predmon.hooks;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

/**
 * One hook command as a child process: started in a process group of its own, its input written while the timeout
 * already runs, and at the timeout killed with everything in its group.
 *
 * <p>A shell command may leave children behind that are no longer its descendants: {@code (cmd &)} starts
 * {@code cmd} from a subshell that exits at once, and {@code cmd} is then a child of init. Such children stay in the
 * command's process group, so the command is started with {@code setsid} (util-linux, on every Linux) as the leader
 * of a new session and process group, and killing it kills the whole group ({@code kill -KILL -- -PGID}), and every
 * descendant that left the group too. Where {@code setsid} is not installed only the command and its descendants can
 * be killed.
 *
 * <p>The event's JSON is written on another thread: a command that does not read its input blocks a write of more
 * than a pipe's buffer (64 KiB on Linux) for ever, and the timeout must still end it.
 */
final class HookProcess {

    /** {@code setsid}, when installed. */
    private static final Optional<Path> SETSID = List.of(Path.of("/usr/bin/setsid"), Path.of("/bin/setsid")).stream()
            .filter(Files::isExecutable).findFirst();

    /** How a command ended. */
    sealed interface Outcome permits Exited, TimedOut, NotStarted {
    }

    /** It exited with {@code code}. */
    record Exited(int code) implements Outcome {
    }

    /** It was still running at the timeout and was killed, with its process group. */
    record TimedOut() implements Outcome {
    }

    /** It could not be started. */
    record NotStarted(String why) implements Outcome {
    }

    private HookProcess() {
    }

    /**
     * Runs {@code command} with the shell, {@code input} and a newline on its standard input, {@code env} added to
     * its environment, its standard output discarded and its standard error predmon's.
     *
     * @throws InterruptedException when the calling thread is interrupted while the command runs: it is killed first
     */
    static Outcome run(String command, Map<String, String> env, String input, Duration timeout)
            throws InterruptedException {
        List<String> argv = new ArrayList<>();
        SETSID.filter(s -> !windows()).ifPresent(s -> argv.add(s.toString()));
        argv.addAll(CommandHooks.shell(command));
        ProcessBuilder pb = new ProcessBuilder(argv);
        pb.environment().putAll(env);
        pb.redirectOutput(ProcessBuilder.Redirect.DISCARD);
        pb.redirectError(ProcessBuilder.Redirect.INHERIT);
        long deadline = System.nanoTime() + timeout.toNanos();
        Process p;
        try {
            p = pb.start();
        } catch (IOException e) {
            return new NotStarted(e.getMessage());
        }
        Thread writer = new Thread(() -> write(p, input), "predmon-hook-input");
        writer.setDaemon(true);
        writer.start();
        try {
            if (!p.waitFor(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS)) {
                kill(p);
                return new TimedOut();
            }
        } catch (InterruptedException e) {
            kill(p);
            throw e;
        }
        return new Exited(p.exitValue());
    }

    private static void write(Process p, String input) {
        try (OutputStream in = p.getOutputStream()) {
            in.write((input + "\n").getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            // The command ended or closed its input without reading it all (or was killed): it need not read it.
        }
    }

    /** Kills a command, its process group and whatever it started (a shell's children would otherwise live on). */
    static void kill(Process p) {
        // The group at once when the command leads one: the shell and its children die together, so no shell prints
        // "Killed" for a child on watch's stderr, beside the report line that already says so.
        List<ProcessHandle> children = p.descendants().toList();
        if (SETSID.isPresent() && !windows()) {
            killGroup(p.pid());
        }
        p.destroyForcibly();
        children.forEach(ProcessHandle::destroyForcibly);
    }

    /** {@code kill -KILL -- -PGID}: every process of the group, detached ones included. */
    private static void killGroup(long pgid) {
        try {
            Process kill = new ProcessBuilder("kill", "-KILL", "--", "-" + pgid)
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD)
                    .redirectError(ProcessBuilder.Redirect.DISCARD).start();
            kill.waitFor(5, TimeUnit.SECONDS);
        } catch (IOException e) {
            // no kill(1): the command and its descendants are still killed one by one
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static boolean windows() {
        return System.getProperty("os.name", "").startsWith("Windows");
    }
}
