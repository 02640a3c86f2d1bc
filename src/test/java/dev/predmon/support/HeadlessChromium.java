package dev.predmon.support;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import java.io.File;
import java.io.IOException;
import java.net.URI;
import java.net.URLEncoder;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.net.http.WebSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Base64;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;

/**
 * A real browser for tests: Chromium in its own headless mode, driven over the DevTools protocol (a WebSocket, with
 * the JDK's own client), so that no WebDriver, Selenium or download is needed. Only loopback is used: the browser's
 * DevTools port and the pages it opens.
 *
 * <p>{@link #find()} looks for {@code -Dpredmon.chromium=PATH}, else {@code chromium}, {@code chromium-browser},
 * {@code google-chrome} on the PATH (Debian: {@code apt-get install chromium}).
 */
public final class HeadlessChromium implements AutoCloseable {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final List<String> NAMES = List.of("chromium", "chromium-browser", "google-chrome",
            "google-chrome-stable");

    private final Process process;
    private final Path profile;
    private final int port;
    private final HttpClient http = HttpClient.newHttpClient();

    private HeadlessChromium(Process process, Path profile, int port) {
        this.process = process;
        this.profile = profile;
        this.port = port;
    }

    /** The browser to use, if this machine has one. */
    public static Optional<Path> find() {
        String given = System.getProperty("predmon.chromium");
        if (given != null && !given.isBlank()) {
            return Optional.of(Path.of(given)).filter(Files::isExecutable);
        }
        String path = System.getenv("PATH");
        if (path == null) {
            return Optional.empty();
        }
        for (String name : NAMES) {
            for (String dir : path.split(File.pathSeparator, 0)) {
                Path p = Path.of(dir, name);
                if (Files.isExecutable(p)) {
                    return Optional.of(p);
                }
            }
        }
        return Optional.empty();
    }

    /** Starts the browser headless with a fresh profile and a window of this size. */
    public static HeadlessChromium start(Path binary, int width, int height) throws IOException, InterruptedException {
        Path profile = Files.createTempDirectory("predmon-chromium-");
        List<String> command = List.of(binary.toString(), "--headless", "--no-sandbox", "--disable-gpu",
                "--disable-quic", "--no-first-run", "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--disable-extensions", "--hide-scrollbars", "--user-data-dir=" + profile,
                "--remote-debugging-address=127.0.0.1", "--remote-debugging-port=0",
                "--window-size=" + width + "," + height, "about:blank");
        Process p = new ProcessBuilder(command).redirectErrorStream(true)
                .redirectOutput(profile.resolve("browser-output.txt").toFile()).start();
        // The browser writes its DevTools port into the profile once it listens.
        Path active = profile.resolve("DevToolsActivePort");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!Files.exists(active) || Files.readAllLines(active).isEmpty()) {
            if (!p.isAlive() || System.nanoTime() > deadline) {
                String output = Files.exists(profile.resolve("browser-output.txt"))
                        ? Files.readString(profile.resolve("browser-output.txt")) : "";
                p.destroyForcibly();
                throw new IOException("Chromium did not start (" + (p.isAlive() ? "timeout" : "exit " + p.exitValue())
                        + "): " + output);
            }
            Thread.sleep(50);
        }
        int port = Integer.parseInt(Files.readAllLines(active).get(0).strip());
        return new HeadlessChromium(p, profile, port);
    }

    /** Opens {@code url} in a new tab. */
    public Page open(URI url) throws IOException, InterruptedException {
        URI create = URI.create("http://127.0.0.1:" + port + "/json/new?"
                + URLEncoder.encode(url.toString(), StandardCharsets.UTF_8));
        HttpResponse<String> r = http.send(HttpRequest.newBuilder(create).PUT(HttpRequest.BodyPublishers.noBody())
                .build(), HttpResponse.BodyHandlers.ofString());
        if (r.statusCode() != 200) {
            throw new IOException("DevTools would not open a tab: " + r.statusCode() + " " + r.body());
        }
        String ws = JSON.readTree(r.body()).get("webSocketDebuggerUrl").asText();
        Page page = new Page();
        page.socket = http.newWebSocketBuilder().connectTimeout(Duration.ofSeconds(10))
                .buildAsync(URI.create(ws), page).join();
        return page;
    }

    @Override
    public void close() throws IOException {
        process.descendants().forEach(ProcessHandle::destroyForcibly);
        process.destroyForcibly();
        try {
            process.waitFor(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        try (Stream<Path> files = Files.walk(profile)) {
            for (Path f : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(f);
            }
        } catch (IOException e) {
            // The browser may still be writing into its profile while it dies; a temporary directory is left.
        }
    }

    /** One tab: evaluate JavaScript in it, take a screenshot of it. */
    public static final class Page implements WebSocket.Listener {
        private final AtomicInteger ids = new AtomicInteger();
        private final Map<Integer, CompletableFuture<JsonNode>> pending = new ConcurrentHashMap<>();
        private final StringBuilder partial = new StringBuilder();
        private WebSocket socket;

        /** Calls a DevTools method and returns its result. */
        public JsonNode call(String method, ObjectNode params) throws Exception {
            int id = ids.incrementAndGet();
            CompletableFuture<JsonNode> answer = new CompletableFuture<>();
            pending.put(id, answer);
            ObjectNode message = JSON.createObjectNode().put("id", id).put("method", method);
            message.set("params", params);
            socket.sendText(JSON.writeValueAsString(message), true).join();
            JsonNode r = answer.get(30, TimeUnit.SECONDS);
            if (r.has("error")) {
                throw new IllegalStateException(method + ": " + r.get("error"));
            }
            return r.get("result");
        }

        /** The value of a JavaScript expression that gives a string (or null). */
        public String eval(String expression) throws Exception {
            ObjectNode p = JSON.createObjectNode().put("expression", expression).put("returnByValue", true);
            JsonNode r = call("Runtime.evaluate", p);
            if (r.has("exceptionDetails")) {
                throw new IllegalStateException("the page threw: " + r.get("exceptionDetails"));
            }
            JsonNode v = r.get("result").get("value");
            return v == null || v.isNull() ? null : v.asText();
        }

        /**
         * Waits up to {@code seconds} until the JavaScript {@code condition} holds (one that throws does not), else
         * fails the test: timed out, {@code what}.
         */
        public void await(String condition, String what, long seconds) throws Exception {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
            while (!"true".equals(eval("String(!!(() => { try { return " + condition + "; } catch (e) { return false; }"
                    + " })())"))) {
                if (System.nanoTime() > deadline) {
                    throw new AssertionError("timed out after " + seconds + " s: " + what);
                }
                Thread.sleep(50);
            }
        }

        /** Saves a PNG of what the tab shows. */
        public void screenshot(Path png) throws Exception {
            JsonNode r = call("Page.captureScreenshot", JSON.createObjectNode().put("format", "png"));
            Files.createDirectories(png.toAbsolutePath().getParent());
            Files.write(png, Base64.getDecoder().decode(r.get("data").asText()));
        }

        @Override
        public CompletionStage<?> onText(WebSocket ws, CharSequence data, boolean last) {
            partial.append(data);
            if (last) {
                try {
                    JsonNode m = JSON.readTree(partial.toString());
                    if (m.has("id")) {
                        CompletableFuture<JsonNode> f = pending.remove(m.get("id").asInt());
                        if (f != null) {
                            f.complete(m);
                        }
                    }
                } catch (IOException e) {
                    pending.values().forEach(f -> f.completeExceptionally(e));
                }
                partial.setLength(0);
            }
            ws.request(1);
            return null;
        }

        @Override
        public void onError(WebSocket ws, Throwable error) {
            pending.values().forEach(f -> f.completeExceptionally(error));
        }
    }
}
