package dev.predmon.rosbag;

import org.junit.jupiter.api.Assumptions;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The Python writers and readers of ROS 2 bags ({@code rosbags}, {@code mcap}, {@code mcap-ros2-support}) in the
 * virtual environment {@code .ci/run} creates: {@code $PREDMON_VENV}, {@code target/venv}, or
 * {@code ~/.cache/predmon-venv}. A test that needs them is skipped, with a message, where there is none.
 */
public final class PythonBags {

    private PythonBags() {
    }

    /** The venv's python, or a skipped test. */
    public static Path python() {
        List<Path> candidates = new ArrayList<>();
        String env = System.getenv("PREDMON_VENV");
        if (env != null && !env.isBlank()) {
            candidates.add(Path.of(env, "bin", "python"));
        }
        candidates.add(Path.of("target", "venv", "bin", "python"));
        candidates.add(Path.of(System.getProperty("user.home"), ".cache", "predmon-venv", "bin", "python"));
        for (Path p : candidates) {
            if (Files.isExecutable(p) && works(p)) {
                return p.toAbsolutePath();
            }
        }
        Assumptions.abort("no Python virtual environment with rosbags, mcap and mcap-ros2-support (looked at "
                + candidates + "; .ci/run creates one): the test against the independent writers is skipped");
        throw new IllegalStateException("unreachable");
    }

    private static boolean works(Path python) {
        try {
            Process p = new ProcessBuilder(python.toString(), "-c", "import rosbags, mcap, mcap_ros2, numpy")
                    .redirectErrorStream(true).start();
            p.getInputStream().readAllBytes();
            return p.waitFor(60, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    /** Runs {@code src/test/python/<script>} with {@code args} and returns its standard output. */
    public static String run(String script, String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(python().toString(),
                Path.of("src", "test", "python", script).toAbsolutePath().toString()));
        command.addAll(List.of(args));
        Path err = Files.createTempFile("predmon-python", ".err");
        try {
            Process p = new ProcessBuilder(command).redirectError(err.toFile()).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            if (!p.waitFor(120, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                throw new IOException(script + " did not finish within 120 s");
            }
            if (p.exitValue() != 0) {
                throw new IOException(script + " failed: " + Files.readString(err, StandardCharsets.UTF_8));
            }
            return out;
        } finally {
            Files.deleteIfExists(err);
        }
    }
}
