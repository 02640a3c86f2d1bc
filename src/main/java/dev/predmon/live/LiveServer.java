package dev.predmon.live;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.InetSocketAddress;
import java.net.URI;
import java.net.URLDecoder;
import java.nio.charset.StandardCharsets;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The live view's HTTP server, on the JDK's own {@code com.sun.net.httpserver} (why that one: see the pom). It has
 * three endpoints and none that changes anything: {@code /} (the page, with {@code /live.js} and
 * {@code /live.css}: hand-written, no library, nothing fetched from elsewhere), {@code /events} (Server-Sent
 * Events) and {@code /status} (a JSON snapshot of every tile; {@code ?log=NAME} for one). Only GET and HEAD are
 * answered.
 *
 * <p>Bound to loopback (the default), it also answers only requests addressed to a loopback name, so that a web
 * page elsewhere cannot read it through DNS rebinding. Bound elsewhere it answers anyone who can reach it, which
 * is why {@code watch} warns then.
 */
public final class LiveServer implements AutoCloseable {

    private static final ObjectMapper JSON = new ObjectMapper();
    /** The page's own files, and nothing else. */
    private static final Map<String, String> FILES = Map.of(
            "/", "index.html", "/index.html", "index.html", "/live.js", "live.js", "/live.css", "live.css",
            "/favicon.svg", "favicon.svg", "/words.js", "words.js", "/tile.js", "tile.js", "/plot.js", "plot.js");
    private static final Map<String, String> TYPES = Map.of(
            "html", "text/html; charset=utf-8", "js", "text/javascript; charset=utf-8",
            "css", "text/css; charset=utf-8", "svg", "image/svg+xml");
    private static final String POLICY = "default-src 'none'; script-src 'self'; style-src 'self'; "
            + "img-src 'self'; connect-src 'self'; base-uri 'none'; form-action 'none'; frame-ancestors 'none'";

    private final Board board;
    private final HttpServer server;
    private final ExecutorService threads;
    private final Set<String> hosts;
    private final Map<String, byte[]> files;

    private LiveServer(Board board, HttpServer server, ExecutorService threads, Set<String> hosts) {
        this.board = board;
        this.server = server;
        this.threads = threads;
        this.hosts = hosts;
        this.files = new java.util.HashMap<>();
        for (String name : Set.copyOf(FILES.values())) {
            files.put(name, resource(name));
        }
    }

    /**
     * Starts serving {@code board} at {@code address}.
     *
     * @throws IOException when the address cannot be bound (in use, not an address of this machine)
     */
    public static LiveServer start(HttpAddress address, Board board) throws IOException {
        InetSocketAddress bind = address.socketAddress();
        HttpServer server = HttpServer.create(bind, 0);
        AtomicInteger n = new AtomicInteger();
        // Each open event stream holds a thread; the few beyond them keep the page and /status answering.
        ExecutorService threads = Executors.newFixedThreadPool(EventStream.MAX_CLIENTS + 4, r -> {
            Thread t = new Thread(r, "predmon-http-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
        server.setExecutor(threads);
        int port = server.getAddress().getPort();
        Set<String> hosts = address.loopback()
                ? Set.of("127.0.0.1:" + port, "localhost:" + port, "[::1]:" + port) : null;
        LiveServer live = new LiveServer(board, server, threads, hosts);
        server.createContext("/", live::handle);
        server.start();
        return live;
    }

    /** Where the page is, e.g. {@code http://127.0.0.1:8080/}. */
    public URI url() {
        InetSocketAddress a = server.getAddress();
        String host = a.getAddress().isAnyLocalAddress() ? "127.0.0.1"
                : a.getAddress() instanceof java.net.Inet6Address ? "[" + a.getAddress().getHostAddress() + "]"
                : a.getAddress().getHostAddress();
        return URI.create("http://" + host + ":" + a.getPort() + "/");
    }

    private void handle(HttpExchange x) throws IOException {
        try {
            x.getResponseHeaders().set("X-Content-Type-Options", "nosniff");
            x.getResponseHeaders().set("Referrer-Policy", "no-referrer");
            x.getResponseHeaders().set("Cache-Control", "no-store");
            String method = x.getRequestMethod();
            if (!method.equals("GET") && !method.equals("HEAD")) {
                x.getResponseHeaders().set("Allow", "GET, HEAD");
                Responses.text(x, 405, "the live view only shows: GET and HEAD\n");
                return;
            }
            String host = x.getRequestHeaders().getFirst("Host");
            if (hosts != null && (host == null || !hosts.contains(host.toLowerCase(java.util.Locale.ROOT)))) {
                Responses.text(x, 403, "bound to loopback, the live view answers requests for " + hosts + " only\n");
                return;
            }
            String path = x.getRequestURI().getPath();
            if (path.equals("/events")) {
                board.stream().serve(x);
            } else if (path.equals("/status")) {
                byte[] body = JSON.writeValueAsBytes(board.status(query(x.getRequestURI(), "log")));
                Responses.bytes(x, 200, "application/json", body);
            } else if (FILES.containsKey(path)) {
                String name = FILES.get(path);
                x.getResponseHeaders().set("Content-Security-Policy", POLICY);
                Responses.bytes(x, 200, TYPES.get(name.substring(name.lastIndexOf('.') + 1)),
                        name.equals("index.html") ? page() : files.get(name));
            } else {
                Responses.text(x, 404, "not found: the live view has /, /events and /status\n");
            }
        } catch (IOException gone) {
            x.close(); // the client went away mid-answer: nobody is left to tell
        } catch (RuntimeException bug) {
            x.close();
            throw bug;
        }
    }

    /**
     * The page with the current {@code /status} in it, as a JSON data block (not a script: the policy allows none
     * inline), so that it shows every tile as soon as it loads. {@code <} is escaped so that no log name can end
     * the block.
     */
    private byte[] page() throws IOException {
        String status = JSON.writeValueAsString(board.status(null)).replace("<", "\\u003c");
        return new String(files.get("index.html"), StandardCharsets.UTF_8).replace("{{status}}", status)
                .getBytes(StandardCharsets.UTF_8);
    }

    /** A query parameter's decoded value, or null. */
    static String query(URI uri, String name) {
        String q = uri.getRawQuery();
        if (q == null) {
            return null;
        }
        for (String part : q.split("&")) {
            int eq = part.indexOf('=');
            String key = URLDecoder.decode(eq < 0 ? part : part.substring(0, eq), StandardCharsets.UTF_8);
            if (key.equals(name)) {
                return eq < 0 ? "" : URLDecoder.decode(part.substring(eq + 1), StandardCharsets.UTF_8);
            }
        }
        return null;
    }

    private static byte[] resource(String name) {
        try (InputStream in = LiveServer.class.getResourceAsStream(name)) {
            if (in == null) {
                throw new IllegalStateException("the jar lacks the live view's " + name);
            }
            return in.readAllBytes();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Ends the event streams and stops serving. */
    @Override
    public void close() {
        board.stream().close();
        server.stop(0);
        threads.shutdownNow();
    }
}
