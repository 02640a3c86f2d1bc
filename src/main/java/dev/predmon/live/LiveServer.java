package dev.predmon.live;

import com.fasterxml.jackson.databind.ObjectMapper;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.Inet6Address;
import java.net.InetSocketAddress;
import java.net.URI;
import java.net.URLDecoder;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * The live view's HTTP server, on {@link HttpListener} (bounded against slow and idle clients; why not a library or
 * the JDK's server: see the pom). It has
 * four endpoints and none that changes anything: {@code /} (the page, with {@code /live.js} and
 * {@code /live.css}: hand-written, no library, nothing fetched from elsewhere), {@code /events} (Server-Sent
 * Events), {@code /status} (a JSON snapshot of every tile; {@code ?log=NAME} for one) and {@code /metrics} (the
 * same for Prometheus, see {@link Metrics}). Only GET and HEAD are answered.
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
    private static final String TEXT = "text/plain; charset=utf-8";
    private static final String POLICY = "default-src 'none'; script-src 'self'; style-src 'self'; "
            + "img-src 'self'; connect-src 'self'; base-uri 'none'; form-action 'none'; frame-ancestors 'none'";

    private final Board board;
    private final HttpListener listener;
    private final Set<String> hosts;
    private final Map<String, byte[]> files = new HashMap<>();

    private LiveServer(Board board, HttpListener listener, Set<String> hosts) {
        this.board = board;
        this.listener = listener;
        this.hosts = hosts;
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
        HttpListener listener = HttpListener.bind(address.socketAddress());
        int port = listener.address().getPort();
        Set<String> hosts = address.loopback()
                ? Set.of("127.0.0.1:" + port, "localhost:" + port, "[::1]:" + port) : null;
        LiveServer live = new LiveServer(board, listener, hosts);
        listener.start(live::handle);
        return live;
    }

    /** Where the page is, e.g. {@code http://127.0.0.1:8080/}. */
    public URI url() {
        InetSocketAddress a = listener.address();
        String host = a.getAddress().isAnyLocalAddress() ? "127.0.0.1"
                : a.getAddress() instanceof Inet6Address ? "[" + a.getAddress().getHostAddress() + "]"
                : a.getAddress().getHostAddress();
        return URI.create("http://" + host + ":" + a.getPort() + "/");
    }

    private void handle(Exchange x) throws IOException {
        x.answerHeader("X-Content-Type-Options", "nosniff");
        x.answerHeader("Referrer-Policy", "no-referrer");
        x.answerHeader("Cache-Control", "no-store");
        String method = x.method();
        if (!method.equals("GET") && !method.equals("HEAD")) {
            x.answerHeader("Allow", "GET, HEAD");
            x.send(405, TEXT, "the live view only shows: GET and HEAD\n");
            return;
        }
        String host = x.header("Host");
        if (hosts != null && (host == null || !hosts.contains(host.toLowerCase(Locale.ROOT)))) {
            x.send(403, TEXT, "bound to loopback, the live view answers requests for " + hosts + " only\n");
            return;
        }
        String path = x.uri().getPath();
        if ("/events".equals(path)) {
            board.stream().serve(x);
        } else if ("/status".equals(path)) {
            x.send(200, "application/json", JSON.writeValueAsBytes(board.status(query(x.uri(), "log"))));
        } else if ("/metrics".equals(path)) {
            x.send(200, Metrics.CONTENT_TYPE, board.metrics().scrape());
        } else if (FILES.containsKey(path)) {
            String name = FILES.get(path);
            x.answerHeader("Content-Security-Policy", POLICY);
            x.send(200, TYPES.get(name.substring(name.lastIndexOf('.') + 1)),
                    name.equals("index.html") ? page() : files.get(name));
        } else {
            x.send(404, TEXT, "not found: the live view has /, /events, /status and /metrics\n");
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
        for (String part : q.split("&", -1)) {
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
        listener.close();
    }
}
