package dev.predmon.live;

import java.io.IOException;
import java.io.InterruptedIOException;
import java.net.URI;
import java.net.URISyntaxException;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;

/**
 * One request of the live view and its answer, on a connection that is closed after it (no keep-alive: the page asks
 * about once a second, on loopback). An answer is either whole, with its length, or a stream that lasts until the
 * connection closes ({@code /events}). A client that stops reading is dropped after {@value #WRITE_MILLIS} ms
 * instead of holding the thread that writes to it.
 */
final class Exchange implements AutoCloseable {

    /** How long one write may wait for a client that does not read. */
    static final long WRITE_MILLIS = 10_000;
    private static final Pattern METHOD = Pattern.compile("[A-Z]{1,16}");
    private static final Map<Integer, String> REASONS = Map.of(200, "OK", 400, "Bad Request", 403, "Forbidden",
            404, "Not Found", 405, "Method Not Allowed", 503, "Service Unavailable");

    private final Connection connection;
    private final String method;
    private final URI uri;
    /** Request headers by lower-case name, the first of each. */
    private final Map<String, String> headers;
    private final Map<String, String> answerHeaders = new LinkedHashMap<>();
    /** Waits for a client's socket to take more bytes; opened only when one did not. */
    private Selector writable;

    private Exchange(Connection connection, String method, URI uri, Map<String, String> headers) {
        this.connection = connection;
        this.method = method;
        this.uri = uri;
        this.headers = headers;
    }

    /**
     * Where the request head in {@code buffer[0, position)} ends (just after its blank line), or -1 while it has not
     * ended. A bare newline ends a line as well as CR LF does.
     */
    static int headEnd(ByteBuffer buffer) {
        for (int i = 1; i < buffer.position(); i++) {
            if (buffer.get(i) == '\n' && (buffer.get(i - 1) == '\n'
                    || (i >= 2 && buffer.get(i - 1) == '\r' && buffer.get(i - 2) == '\n'))) {
                return i + 1;
            }
        }
        return -1;
    }

    /** The request whose complete head is in {@code buffer}; {@link #malformed()} if it is no HTTP/1 request. */
    static Exchange of(Connection connection, ByteBuffer buffer) {
        byte[] bytes = new byte[headEnd(buffer)];
        buffer.get(0, bytes);
        // With its trailing empty lines: a head of blank lines alone is then one empty request line (a 400), where
        // split without a limit left no line at all.
        String[] lines = new String(bytes, StandardCharsets.ISO_8859_1).split("\r?\n", -1);
        String[] request = lines[0].split(" ", -1);
        if (request.length != 3 || !METHOD.matcher(request[0]).matches() || !request[2].startsWith("HTTP/1.")) {
            return new Exchange(connection, null, null, Map.of());
        }
        URI uri;
        try {
            uri = new URI(request[1]);
        } catch (URISyntaxException e) {
            return new Exchange(connection, null, null, Map.of());
        }
        // Only a path (origin form): an absolute URI (http://evil.com/status) or a path with an authority
        // (//evil.com/status) names another host than the Host header the loopback check reads.
        if (!request[1].startsWith("/") || uri.getRawAuthority() != null) {
            return new Exchange(connection, null, null, Map.of());
        }
        Map<String, String> headers = new HashMap<>();
        for (int i = 1; i < lines.length; i++) {
            int colon = lines[i].indexOf(':');
            if (colon > 0) {
                String name = lines[i].substring(0, colon).strip().toLowerCase(Locale.ROOT);
                if (headers.putIfAbsent(name, lines[i].substring(colon + 1).strip()) != null && name.equals("host")) {
                    // two Host headers: which one a proxy or the browser meant is anyone's guess (HTTP says 400)
                    return new Exchange(connection, null, null, Map.of());
                }
            }
        }
        return new Exchange(connection, request[0], uri, headers);
    }

    /**
     * Whether the head was no HTTP/1 request for this server (it is answered 400): no request line of three parts,
     * a target that is not a path, or two {@code Host} headers.
     */
    boolean malformed() {
        return method == null;
    }

    String method() {
        return method;
    }

    /** The request target; its path is decoded by {@link URI#getPath()}. */
    URI uri() {
        return uri;
    }

    /** A request header's first value, or null. */
    String header(String name) {
        return headers.get(name.toLowerCase(Locale.ROOT));
    }

    /** Sets a header of the answer (before it is sent). */
    void answerHeader(String name, String value) {
        answerHeaders.put(name, value);
    }

    void send(int status, String type, String body) throws IOException {
        send(status, type, body.getBytes(StandardCharsets.UTF_8));
    }

    /** A whole answer with its length (its body left out for HEAD, as HTTP says). */
    void send(int status, String type, byte[] body) throws IOException {
        answerHeaders.put("Content-Type", type);
        answerHeaders.put("Content-Length", Integer.toString(body.length));
        ByteBuffer head = ByteBuffer.wrap(head(status));
        write(head, "HEAD".equals(method) ? ByteBuffer.allocate(0) : ByteBuffer.wrap(body));
    }

    /** Starts an answer whose body goes on until the connection closes: {@link #write(String)} adds to it. */
    void stream(int status, String type) throws IOException {
        answerHeaders.put("Content-Type", type);
        write(ByteBuffer.wrap(head(status)), ByteBuffer.allocate(0));
    }

    /** More of a streamed answer. */
    void write(String text) throws IOException {
        write(ByteBuffer.wrap(text.getBytes(StandardCharsets.UTF_8)), ByteBuffer.allocate(0));
    }

    /**
     * From the thread that reads request heads, which must never wait: the answer goes out if the socket takes it at
     * once (an answer this short always does on a fresh connection), and the connection is closed either way.
     */
    void refuse(int status, String body) {
        answerHeaders.put("Content-Type", "text/plain; charset=utf-8");
        byte[] text = body.getBytes(StandardCharsets.UTF_8);
        answerHeaders.put("Content-Length", Integer.toString(text.length));
        try {
            connection.channel().write(new ByteBuffer[] {ByteBuffer.wrap(head(status)), ByteBuffer.wrap(text)});
        } catch (IOException gone) {
            // the client is gone: nothing to tell it
        }
        close();
    }

    private byte[] head(int status) {
        StringBuilder b = new StringBuilder("HTTP/1.1 ").append(status).append(' ')
                .append(REASONS.getOrDefault(status, "Status")).append("\r\n");
        answerHeaders.forEach((k, v) -> b.append(k).append(": ").append(v).append("\r\n"));
        return b.append("Connection: close\r\n\r\n").toString().getBytes(StandardCharsets.ISO_8859_1);
    }

    /** Writes every byte, waiting at most {@value #WRITE_MILLIS} ms for a client that does not read. */
    private void write(ByteBuffer first, ByteBuffer second) throws IOException {
        SocketChannel channel = connection.channel();
        ByteBuffer[] both = {first, second};
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(WRITE_MILLIS);
        while (first.hasRemaining() || second.hasRemaining()) {
            if (channel.write(both) > 0) {
                continue;
            }
            long left = deadline - System.nanoTime();
            if (left <= 0) {
                throw new IOException("the client stopped reading");
            }
            if (writable == null) {
                writable = Selector.open();
                channel.register(writable, SelectionKey.OP_WRITE);
            }
            writable.select(Math.max(1, TimeUnit.NANOSECONDS.toMillis(left)));
            writable.selectedKeys().clear();
            if (Thread.currentThread().isInterrupted()) {
                throw new InterruptedIOException("the live view is closing");
            }
        }
    }

    /**
     * Ends the answer and closes the connection. What the client sent beyond the head is read first (a little), as
     * closing a socket with unread bytes resets the connection, and the client may then lose the answer.
     */
    @Override
    public void close() {
        SocketChannel channel = connection.channel();
        try {
            channel.shutdownOutput();
            ByteBuffer discard = ByteBuffer.allocate(4096);
            for (int i = 0; i < 16 && channel.read(discard) > 0; i++) {
                discard.clear();
            }
        } catch (IOException gone) {
            // closed by the client already: nothing left to end
        }
        if (writable != null) {
            try {
                writable.close();
            } catch (IOException e) {
                // its descriptor is released whatever close reports
            }
        }
        connection.close();
    }
}
