package dev.predmon.support;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.cli.Main;
import picocli.CommandLine;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * {@code watch ... --http 0} run in-process on a thread of its own, as a browser test starts it: the live view's
 * address once watch announces it, its {@code /status} and {@code /metrics}, and a tab of the page in Chromium
 * ({@link BrowserTabs}). Every browser test of the live view that runs watch starts it so. Closing it stops watch
 * (an interrupt, the in-process way) and waits for it to end.
 */
public final class LiveWatch implements AutoCloseable {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Pattern ANNOUNCED = Pattern.compile("live view on (\\S+)");
    private static final HttpClient HTTP = HttpClient.newHttpClient();

    private final Thread thread;
    private final StringWriter out;
    private final StringWriter err;
    private final AtomicInteger code;
    private final URI url;

    private LiveWatch(Thread thread, StringWriter out, StringWriter err, AtomicInteger code, URI url) {
        this.thread = thread;
        this.out = out;
        this.err = err;
        this.code = code;
        this.url = url;
    }

    /**
     * Starts {@code watch} with {@code args} (its logs and models) and {@code --http 0}, and waits up to 60 s for the
     * live view's address; a watch that ends before it fails the test with what it printed.
     */
    public static LiveWatch start(String... args) throws InterruptedException {
        List<String> command = new ArrayList<>(List.of("watch"));
        command.addAll(List.of(args));
        command.addAll(List.of("--http", "0"));
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cl = Main.commandLine();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        AtomicInteger code = new AtomicInteger(-1);
        Thread t = new Thread(() -> code.set(cl.execute(command.toArray(String[]::new))), "watch --http");
        t.start();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (true) {
            Matcher m = ANNOUNCED.matcher(err.toString());
            if (m.find()) {
                return new LiveWatch(t, out, err, code, URI.create(m.group(1)));
            }
            if (!t.isAlive() || System.nanoTime() > deadline) {
                t.interrupt();
                throw new AssertionError("watch never announced its live view (exit " + code.get() + "): " + err);
            }
            Thread.sleep(20);
        }
    }

    /** The live view's address, {@code http://127.0.0.1:PORT/}. */
    public URI url() {
        return url;
    }

    /** Watch's exit code, -1 while it runs. */
    public int code() {
        return code.get();
    }

    /** What watch printed on stdout and stderr so far. */
    public String out() {
        return out.toString();
    }

    public String err() {
        return err.toString();
    }

    /** {@code path} of the live view, as text (a status other than 200 fails the test). */
    public String get(String path) throws IOException, InterruptedException {
        HttpResponse<String> r = HTTP.send(HttpRequest.newBuilder(url.resolve(path)).build(),
                HttpResponse.BodyHandlers.ofString());
        if (r.statusCode() != 200) {
            throw new AssertionError("GET " + path + ": " + r.statusCode() + " " + r.body());
        }
        return r.body();
    }

    /** {@code /status}: every tile, worst first. */
    public JsonNode status() throws IOException, InterruptedException {
        return JSON.readTree(get("/status"));
    }

    /** {@code /metrics}, as Prometheus scrapes it. */
    public String metrics() throws IOException, InterruptedException {
        return get("/metrics");
    }

    /** A tab of {@code tabs} showing the live page (skipped without Chromium, {@code untested} saying what is not). */
    public HeadlessChromium.Page open(BrowserTabs tabs, String untested) throws Exception {
        return tabs.open(url, untested);
    }

    @Override
    public void close() throws InterruptedException {
        thread.interrupt();
        thread.join(10_000);
        if (thread.isAlive()) {
            throw new AssertionError("watch did not stop when interrupted");
        }
    }
}
