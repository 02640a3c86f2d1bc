package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.simulate.Scenario;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.net.ServerSocket;
import java.net.URI;
import java.net.URLEncoder;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A real Prometheus server scrapes {@code watch --http}'s {@code /metrics} and gives back, through its own query API,
 * the probability gauge of a run that warned. The Prometheus binary is {@code -Dpredmon.prometheus=PATH}, else
 * {@code prometheus} on the PATH (Debian: {@code apt-get install prometheus}, which CI's {@code .ci/run} does);
 * without one the test is skipped with a message.
 */
class PrometheusScrapeTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private final HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();

    @TempDir
    Path dir;

    private static Optional<Path> prometheus() {
        String asked = System.getProperty("predmon.prometheus");
        if (asked != null) {
            return Optional.of(Path.of(asked)).filter(Files::isExecutable);
        }
        return Arrays.stream(System.getenv().getOrDefault("PATH", "").split(":", -1)).filter(d -> !d.isEmpty())
                .map(d -> Path.of(d, "prometheus")).filter(Files::isExecutable).findFirst();
    }

    private static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        }
    }

    private JsonNode get(URI uri) throws Exception {
        return JSON.readTree(http.send(HttpRequest.newBuilder(uri).timeout(Duration.ofSeconds(10)).build(),
                HttpResponse.BodyHandlers.ofString()).body());
    }

    /** The samples of an instant query, as Prometheus's HTTP API answers it. */
    private JsonNode query(URI prometheus, String promql) throws Exception {
        JsonNode answer = get(prometheus.resolve("/api/v1/query?query=" + URLEncoder.encode(promql,
                StandardCharsets.UTF_8)));
        assertEquals("success", answer.get("status").asText(), answer.toString());
        return answer.get("data").get("result");
    }

    /**
     * Prometheus's own lint of metric names, types, units and help ({@code promtool check metrics}) finds nothing in
     * {@code /metrics}, where promtool is installed beside prometheus (Debian's package has both).
     */
    private void lint(Path promtool, URI live) throws Exception {
        if (!Files.isExecutable(promtool)) {
            return;
        }
        byte[] text = http.send(HttpRequest.newBuilder(live.resolve("/metrics")).build(),
                HttpResponse.BodyHandlers.ofByteArray()).body();
        Path file = Files.write(dir.resolve("metrics.txt"), text);
        Process check = new ProcessBuilder(promtool.toString(), "check", "metrics").redirectInput(file.toFile())
                .redirectErrorStream(true).start();
        String said = new String(check.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(check.waitFor(30, TimeUnit.SECONDS));
        assertEquals(0, check.exitValue(), "promtool check metrics: " + said);
        assertEquals("", said.strip(), "promtool check metrics");
    }

    @Test
    @Timeout(120)
    void prometheusScrapesTheProbabilityOfAWarnedRun() throws Exception {
        Optional<Path> binary = prometheus();
        Assumptions.assumeTrue(binary.isPresent(), "no prometheus binary (Debian: apt-get install prometheus; or "
                + "-Dpredmon.prometheus=PATH): the real scrape is not tested");

        // the demo's depleted run, cut halfway between its warning and its violation: a run that warned, live
        String run = FleetWatchTest.run(Scenario.DEPLETED, 9001);
        Path whole = Files.writeString(dir.resolve("whole.log"), run);
        List<JsonNode> events = Cli.run("watch", "--log", whole.toString(), "--no-follow", "--json").jsonLines();
        long warnedAt = Cli.firstEvent(events, "warning").orElseThrow().get("line").asLong();
        long violatedAt = Cli.firstEvent(events, "violation").orElseThrow().get("line").asLong();
        Path log = dir.resolve("robot-7.log");
        Files.writeString(log, run.lines().limit((warnedAt + violatedAt) / 2).map(l -> l + "\n")
                .collect(Collectors.joining()));

        Cli.Running watch = Cli.start("watch", "--log", log.toString(), "--json", "--http", "0",
                "--stale-after", "600");
        Process server = null;
        try {
            URI live = LiveViewTest.url(watch);
            FleetWatchTest.await(() -> watch.out().toString().contains("\"event\":\"warning\""), "the warning");
            JsonNode tile = get(live.resolve("/status")).get("logs").get(0);
            assertEquals("warning", tile.get("state").asText(), tile.toString());
            double shown = tile.get("forecast").get("probability").asDouble();

            int port = freePort();
            Path config = Files.writeString(dir.resolve("prometheus.yml"), String.join("\n",
                    "global:",
                    "  scrape_interval: 1s",
                    "scrape_configs:",
                    "  - job_name: predmon",
                    "    static_configs:",
                    "      - targets: ['127.0.0.1:" + live.getPort() + "']",
                    ""));
            server = new ProcessBuilder(binary.get().toString(), "--config.file=" + config,
                    "--storage.tsdb.path=" + dir.resolve("data"), "--web.listen-address=127.0.0.1:" + port)
                    .redirectErrorStream(true).redirectOutput(dir.resolve("prometheus.out").toFile()).start();
            URI prometheus = URI.create("http://127.0.0.1:" + port + "/");

            String selector = "{log=\"" + log + "\",robot=\"robot-7\",job=\"predmon\"}";
            JsonNode result = null;
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (System.nanoTime() < deadline && server.isAlive()) {
                try {
                    result = query(prometheus, "predmon_violation_probability" + selector);
                    if (result.size() > 0) {
                        break;
                    }
                } catch (IOException notYetUp) {
                    // Prometheus is still starting
                }
                Thread.sleep(250);
            }
            assertTrue(result != null && result.size() == 1, "Prometheus scraped the gauge: " + result + "; "
                    + Files.readString(dir.resolve("prometheus.out")));
            assertEquals(shown, result.get(0).get("value").get(1).asDouble(),
                    "Prometheus has the probability the page shows");
            assertEquals(1.0, query(prometheus, "predmon_state" + selector.replace("}", ",state=\"warning\"}"))
                    .get(0).get("value").get(1).asDouble());
            assertEquals(1.0, query(prometheus, "predmon_warnings_total" + selector).get(0).get("value").get(1)
                    .asDouble());
            JsonNode target = get(prometheus.resolve("/api/v1/targets")).get("data").get("activeTargets").get(0);
            assertEquals("up", target.get("health").asText(), "no scrape error: " + target);
            lint(binary.get().resolveSibling("promtool"), live);
        } finally {
            if (server != null) {
                server.destroy();
                if (!server.waitFor(20, TimeUnit.SECONDS)) {
                    server.destroyForcibly();
                }
            }
            watch.stop();
        }
        assertEquals(ExitCodes.WARNING, watch.code().get(), watch.err().toString());
    }
}
