package dev.predmon.rosbridge;

import com.fasterxml.jackson.core.json.JsonReadFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.json.JsonMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.fasterxml.jackson.dataformat.cbor.databind.CBORMapper;
import dev.predmon.rosbag.BagMessage;
import dev.predmon.rosbag.CdrMessages;
import org.java_websocket.client.WebSocketClient;
import org.java_websocket.handshake.ServerHandshake;

import java.net.URI;
import java.nio.ByteBuffer;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Queue;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * A connection to a rosbridge server (the rosbridge v2 protocol, JSON): subscribes to the topics given as soon as it
 * is open (with {@code cbor-raw}, asking for each message as its CDR bytes in a CBOR binary frame, decoded here by
 * predmon's bundled definition of the subscription's type), queues each message published on them as a {@link BagMessage} timed by when it was received, and, when the
 * connection cannot be made or drops, connects again after a pause that doubles from {@link #FIRST_PAUSE_MILLIS} to
 * {@link #LAST_PAUSE_MILLIS}. Each drop is said once ({@link #takeNotices()}), and so is the connection made again;
 * what happened on the robot meanwhile is unknown, which {@link #takeReconnected()} tells the reader of the queue.
 *
 * <p>The WebSocket's own thread receives; any thread may read the queue and send.
 */
public final class RosbridgeClient implements AutoCloseable {

    static final long FIRST_PAUSE_MILLIS = 250;
    static final long LAST_PAUSE_MILLIS = 8_000;

    private static final ObjectMapper JSON = JsonMapper.builder()
            .enable(JsonReadFeature.ALLOW_NON_NUMERIC_NUMBERS).build();
    private static final ObjectMapper CBOR = new CBORMapper();

    /** A topic to subscribe to, and its type ({@code pkg/msg/Type}, or null to let the server find it). */
    public record Subscription(String topic, String type) {
    }

    private final URI uri;
    private final List<Subscription> subscriptions;
    /** With cbor-raw: each topic's decoder; null for JSON. */
    private final Map<String, CdrMessages> raw;
    /** Topics whose message could not be decoded, said once each. */
    private final Set<String> undecodable = ConcurrentHashMap.newKeySet();
    private final List<String> onOpen = new ArrayList<>();
    private final Queue<BagMessage> messages = new ConcurrentLinkedQueue<>();
    private final Queue<String> notices = new ConcurrentLinkedQueue<>();
    private final ScheduledExecutorService retries = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "rosbridge-reconnect");
        t.setDaemon(true);
        return t;
    });
    private volatile Connection current;
    private volatile boolean closed;
    private volatile boolean reconnected;
    private long pause = FIRST_PAUSE_MILLIS;
    /** When the connection was lost (System.nanoTime), 0 while connected or before the first connection. */
    private long lostAt;
    private boolean everConnected;
    private boolean failureTold;
    private long index;
    /** When a message is received, in nanoseconds since the epoch: the wall clock; tests replay a run's own times. */
    static volatile java.util.function.LongSupplier clock = RosbridgeClient::now;

    public RosbridgeClient(URI uri, List<Subscription> subscriptions) {
        this(uri, subscriptions, false);
    }

    /**
     * With {@code cborRaw}, subscribes with rosbridge's {@code cbor-raw} compression.
     *
     * @throws IllegalArgumentException with {@code cborRaw}, for a subscription without a type or of a type predmon
     *                                  bundles no definition of
     */
    public RosbridgeClient(URI uri, List<Subscription> subscriptions, boolean cborRaw) {
        this.uri = uri;
        this.subscriptions = List.copyOf(subscriptions);
        this.raw = cborRaw ? decoders(this.subscriptions) : null;
    }

    /**
     * Each subscription's decoder for {@code cbor-raw}.
     *
     * @throws IllegalArgumentException naming the topic that has no type, or whose type has no bundled definition
     */
    public static Map<String, CdrMessages> decoders(List<Subscription> subscriptions) {
        Map<String, CdrMessages> out = new HashMap<>();
        for (Subscription s : subscriptions) {
            if (s.type() == null) {
                throw new IllegalArgumentException(s.topic() + ": cbor-raw sends CDR bytes, which need the topic's "
                        + "type: give it a type in the abstraction file");
            }
            try {
                out.put(s.topic(), CdrMessages.of(s.type()));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException(s.topic() + " (" + s.type() + "): cbor-raw sends CDR bytes, and "
                        + e.getMessage(), e);
            }
        }
        return out;
    }

    /** Also sends {@code op} (a JSON text) each time the connection opens, after the subscriptions. */
    public synchronized void sendOnOpen(String op) {
        onOpen.add(op);
    }

    /** Begins connecting; returns at once. */
    public void start() {
        connect();
    }

    public URI uri() {
        return uri;
    }

    private synchronized void connect() {
        if (closed) {
            return;
        }
        current = new Connection(uri);
        current.connect();
    }

    /** Whether the connection is open now. */
    public boolean connected() {
        Connection c = current;
        return c != null && c.isOpen();
    }

    /** The next message received, or null. */
    public BagMessage next() {
        return messages.poll();
    }

    /** What the user should be told since the last call: connections lost and made again. */
    public List<String> takeNotices() {
        List<String> out = new ArrayList<>();
        for (String n = notices.poll(); n != null; n = notices.poll()) {
            out.add(n);
        }
        return out;
    }

    /** Whether the connection was made again since the last call: the messages next begin after a gap. */
    public boolean takeReconnected() {
        boolean r = reconnected;
        reconnected = false;
        return r;
    }

    /** Sends {@code op} when connected; whether it was sent. */
    public boolean send(String op) {
        Connection c = current;
        if (c == null || !c.isOpen()) {
            return false;
        }
        try {
            c.send(op);
            return true;
        } catch (org.java_websocket.exceptions.WebsocketNotConnectedException e) {
            return false;
        }
    }

    private synchronized void opened(Connection c) {
        if (c != current) {
            return;
        }
        for (Subscription s : subscriptions) {
            ObjectNode op = JSON.createObjectNode().put("op", "subscribe").put("topic", s.topic());
            if (s.type() != null) {
                op.put("type", s.type());
            }
            if (raw != null) {
                op.put("compression", "cbor-raw");
            }
            c.send(op.toString());
        }
        onOpen.forEach(c::send);
        if (lostAt != 0) {
            notices.add("connected again after " + String.format(java.util.Locale.ROOT, "%.1f",
                    (System.nanoTime() - lostAt) / 1e9) + " s; what happened meanwhile is not known, so the runs "
                    + "judged begin anew");
            reconnected = true;
        } else if (failureTold) {
            notices.add("connected");
        }
        lostAt = 0;
        everConnected = true;
        failureTold = false;
        pause = FIRST_PAUSE_MILLIS;
    }

    private synchronized void dropped(Connection c, String why) {
        if (c != current || closed) {
            return;
        }
        if (everConnected && lostAt == 0) {
            lostAt = System.nanoTime();
            notices.add("connection lost (" + why + "); reconnecting, and no verdict on what happens "
                    + "until it is back");
        } else if (!everConnected && !failureTold) {
            failureTold = true;
            notices.add("cannot connect (" + why + "); retrying");
        }
        long wait = pause;
        pause = Math.min(pause * 2, LAST_PAUSE_MILLIS);
        try {
            var unused = retries.schedule(this::connect, wait, TimeUnit.MILLISECONDS);
        } catch (java.util.concurrent.RejectedExecutionException closing) {
            // closed meanwhile
        }
    }

    private void received(String text) {
        JsonNode op;
        try {
            op = JSON.readTree(text);
        } catch (java.io.IOException e) {
            return; // not JSON: not an operation of the protocol
        }
        if (!op.path("op").asText().equals("publish") || !op.path("msg").isObject()) {
            return; // status, service responses, ...
        }
        String topic = op.path("topic").asText();
        String type = typeOf(topic);
        queue(topic, type, JsonMessages.fields(op.get("msg"), type));
    }

    /**
     * A binary frame: with cbor-raw, a CBOR {@code {"op":"publish","topic":...,"msg":{"secs","nsecs","bytes"}}},
     * {@code bytes} the message serialised as CDR.
     */
    private void received(ByteBuffer frame) {
        JsonNode op;
        try {
            byte[] b = new byte[frame.remaining()];
            frame.get(b);
            op = CBOR.readTree(b);
        } catch (java.io.IOException e) {
            return; // not CBOR: not an operation of the protocol
        }
        String topic = op.path("topic").asText();
        CdrMessages decoder = raw == null ? null : raw.get(topic);
        JsonNode bytes = op.path("msg").path("bytes");
        if (!op.path("op").asText().equals("publish") || decoder == null || !bytes.isBinary()) {
            return;
        }
        try {
            queue(topic, decoder.type(), decoder.decode(bytes.binaryValue()));
        } catch (IllegalArgumentException | java.io.IOException e) {
            if (undecodable.add(topic)) {
                notices.add("a message of " + topic + " is not a " + decoder.type() + " in CDR (" + e.getMessage()
                        + "); such messages are left out");
            }
        }
    }

    private void queue(String topic, String type, Map<String, Object> fields) {
        long nanos = clock.getAsLong();
        synchronized (this) {
            messages.add(new BagMessage(null, ++index, topic, type, nanos, fields));
        }
    }

    static long now() {
        Instant now = Instant.now();
        return now.getEpochSecond() * 1_000_000_000L + now.getNano();
    }

    private String typeOf(String topic) {
        for (Subscription s : subscriptions) {
            if (s.topic().equals(topic)) {
                return s.type();
            }
        }
        return null;
    }

    @Override
    public void close() {
        closed = true;
        retries.shutdownNow();
        Connection c = current;
        if (c != null) {
            c.close();
        }
    }

    /** One attempt at a connection: Java-WebSocket's clients are not reused once closed. */
    private final class Connection extends WebSocketClient {

        Connection(URI address) {
            super(address);
            setConnectionLostTimeout(10); // pings: a peer gone without closing is noticed within 10-20 s
        }

        @Override
        public void onOpen(ServerHandshake handshake) {
            opened(this);
        }

        @Override
        public void onMessage(String message) {
            received(message);
        }

        @Override
        public void onMessage(ByteBuffer bytes) {
            received(bytes);
        }

        @Override
        public void onClose(int code, String reason, boolean remote) {
            dropped(this, reason == null || reason.isBlank() ? "code " + code : reason);
        }

        @Override
        public void onError(Exception ex) {
            // onClose follows
        }
    }
}
