package dev.predmon.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.simulate.Scenario;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.net.URLEncoder;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code watch --http}: the live view's endpoints over HTTP, as a browser or a script sees them (the page itself is
 * tested in a real browser by {@code LiveBrowserTest}).
 */
class LiveViewTest {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Path MODELS = Path.of("models");
    private final HttpClient http = HttpClient.newHttpClient();

    @TempDir
    Path dir;

    /** The address a running {@code watch --http} announces. */
    static URI url(Cli.Running w) throws InterruptedException {
        FleetWatchTest.await(() -> w.err().toString().contains("live view on "), "announces the live view");
        Matcher m = Pattern.compile("live view on (\\S+)").matcher(w.err().toString());
        assertTrue(m.find());
        return URI.create(m.group(1));
    }

    private HttpResponse<String> get(URI uri, String path) throws Exception {
        return http.send(HttpRequest.newBuilder(uri.resolve(path)).build(), HttpResponse.BodyHandlers.ofString());
    }

    @Test
    @Timeout(60)
    void eventsStreamWhatJsonPrintsWithTheLogAndStatusShowsTheTile() throws Exception {
        Path log = dir.resolve("robot-1.log");
        Cli.Running w = Cli.start("watch", "--log", log.toString(), "--models", MODELS.toString(), "--json", "--http", "0");
        URI url = url(w);
        assertEquals("127.0.0.1", url.getHost(), "loopback by default");

        JsonNode before = JSON.readTree(get(url, "/status").body()).get("logs").get(0);
        assertEquals(log.toString(), before.get("log").asText());
        assertEquals("grey", before.get("light").asText(), "no data yet");

        // send returns with the headers, the body streaming on; the server registers a client before it answers
        HttpResponse<Stream<String>> events = http.send(HttpRequest.newBuilder(url.resolve("/events")).build(),
                HttpResponse.BodyHandlers.ofLines());
        assertEquals("text/event-stream; charset=utf-8", events.headers().firstValue("Content-Type").orElse(""));
        BlockingQueue<String> data = new LinkedBlockingQueue<>();
        Thread reader = new Thread(() -> events.body().filter(l -> l.startsWith("data: "))
                .forEach(l -> data.add(l.substring(6))), "events");
        reader.setDaemon(true);
        reader.start();

        Files.writeString(log, FleetWatchTest.run(Scenario.DEPLETED, 9001), StandardOpenOption.CREATE,
                StandardOpenOption.APPEND);
        List<JsonNode> streamed = new ArrayList<>();
        while (streamed.isEmpty() || !streamed.get(streamed.size() - 1).get("event").asText().equals("violation")
                || !streamed.get(streamed.size() - 1).get("property").asText().equals("battery")) {
            String next = data.poll(20, TimeUnit.SECONDS);
            assertNotNull(next, "the stream stalled after " + streamed);
            streamed.add(JSON.readTree(next));
        }
        List<JsonNode> printed = new ArrayList<>();
        for (String line : w.out().toString().strip().split("\n", -1)) {
            printed.add(JSON.readTree(line));
        }
        // what follows the battery's violation (the forecast, certain now, and the other properties' violations as the
        // run goes on) may be printed before the comparison: compare up to it, message for message
        assertTrue(printed.size() >= streamed.size(), "one message per event");
        for (int i = 0; i < streamed.size(); i++) {
            ObjectNode s = (ObjectNode) streamed.get(i);
            assertEquals(log.toString(), s.remove("log").asText());
            assertEquals(printed.get(i), s, "the same object --json prints, plus the log");
        }

        JsonNode tile = JSON.readTree(get(url, "/status?log=" + URLEncoder.encode(log.toString(),
                StandardCharsets.UTF_8)).body()).get("logs").get(0);
        assertEquals("red", tile.get("light").asText());
        JsonNode warning = printed.stream().filter(e -> e.get("event").asText().equals("warning")).findFirst().orElseThrow();
        JsonNode violation = streamed.get(streamed.size() - 1);
        assertEquals(violation.get("time").asDouble() - warning.get("time").asDouble(), tile.get("lead").asDouble(), 1e-9);
        assertEquals(List.of("depleted"), List.of(tile.get("warning").get("scenarios").get(0).asText()));
        assertTrue(tile.get("series").size() > 10, "the battery over time");
        assertEquals(0, JSON.readTree(get(url, "/status?log=other.log").body()).get("logs").size());
        w.stop();
        assertEquals(ExitCodes.WARNING, w.code().get(), w.err().toString());
    }

    @Test
    @Timeout(30)
    void theServerOnlyShowsAndOnlyToLoopbackNames() throws Exception {
        Cli.Running w = Cli.start("watch", "--log", dir.resolve("a.log").toString(), "--models", MODELS.toString(), "--http", "0");
        URI url = url(w);
        HttpResponse<String> page = get(url, "/");
        assertEquals(200, page.statusCode());
        assertTrue(page.headers().firstValue("Content-Security-Policy").orElse("").contains("default-src 'none'"));
        for (String file : new String[] {"/", "/live.js", "/live.css"}) {
            String body = get(url, file).body();
            Matcher m = Pattern.compile("(https?:)?//[a-z0-9.-]+\\.[a-z]{2,}").matcher(body);
            while (m.find()) {
                assertEquals("http://www.w3.org", m.group(), file + " refers to another site: " + m.group());
            }
        }
        assertEquals(405, http.send(HttpRequest.newBuilder(url.resolve("/status"))
                .POST(HttpRequest.BodyPublishers.ofString("{}")).build(), HttpResponse.BodyHandlers.ofString()).statusCode());
        assertEquals(404, get(url, "/admin").statusCode());
        // A page elsewhere reaching this port through DNS rebinding names its own host, not a loopback one.
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), url.getPort())) {
            s.getOutputStream().write("GET /status HTTP/1.1\r\nHost: attacker.example\r\nConnection: close\r\n\r\n"
                    .getBytes(StandardCharsets.US_ASCII));
            String answer = new String(s.getInputStream().readAllBytes(), StandardCharsets.US_ASCII);
            assertTrue(answer.startsWith("HTTP/1.1 403"), answer);
        }
        w.stop();
    }

    @Test
    void httpNeedsFollowingAndAnAddress() throws Exception {
        Path log = Files.writeString(dir.resolve("a.log"), "");
        Cli r = Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--no-follow", "--http", "0");
        assertEquals(ExitCodes.USAGE, r.code());
        assertTrue(r.err().contains("--http") && r.err().contains("--no-follow"), r.err());
        Cli bad = Cli.run("watch", "--log", log.toString(), "--models", MODELS.toString(), "--http", "somewhere");
        assertEquals(ExitCodes.USAGE, bad.code());
        assertTrue(bad.err().contains("expected [HOST:]PORT"), bad.err());
    }

    @Test
    void aPortInUseIsOneLineOfBadInput() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            Cli r = Cli.run("watch", "--log", dir.resolve("a.log").toString(), "--models", MODELS.toString(),
                    "--http", "127.0.0.1:" + taken.getLocalPort());
            assertEquals(ExitCodes.BAD_INPUT, r.code(), r.err());
            assertEquals(1, r.err().strip().lines().count(), r.err());
            assertTrue(r.err().contains("cannot listen there"), r.err());
        }
    }
}
