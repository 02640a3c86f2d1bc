package dev.predmon.rosbridge;

import com.fasterxml.jackson.core.json.JsonWriteFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.json.JsonMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.fasterxml.jackson.dataformat.cbor.databind.CBORMapper;
import dev.predmon.rosbag.BagMessage;
import dev.predmon.rosbag.ByteArrays;
import dev.predmon.rosbag.CdrMessages;
import org.java_websocket.WebSocket;
import org.java_websocket.handshake.ClientHandshake;
import org.java_websocket.server.WebSocketServer;

import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.Map;
import java.util.Queue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;


/**
 * A rosbridge server for tests, built from the rosbridge v2 protocol's specification (ROSBRIDGE_PROTOCOL.md): it
 * takes {@code subscribe}, {@code unsubscribe}, {@code advertise} and {@code publish} ops, and sends each message
 * {@link #publish replayed} to it as {@code {"op":"publish","topic":...,"msg":{...}}} to the connections subscribed
 * to its topic, the fields as rosbridge's JSON writes them: byte arrays ({@code uint8[]}, {@code uint8[16]}) as
 * base64 text, NaN and infinities as the bare words Python's JSON writes. A subscription with {@code "compression":
 * "cbor-raw"} gets each message as the protocol says: a binary frame holding the CBOR of
 * {@code {"op":"publish","topic":...,"msg":{"secs":...,"nsecs":...,"bytes":<the message's CDR>}}}.
 */
public final class FakeRosbridge extends WebSocketServer {

    private static final ObjectMapper JSON = JsonMapper.builder()
            .disable(JsonWriteFeature.WRITE_NAN_AS_STRINGS).build();

    /** Each topic subscribed to, with its type, by every connection that did, in order (again after a reconnect). */
    public final List<String> subscribes = new CopyOnWriteArrayList<>();
    /** Each topic advertised, with its type. */
    public final List<String> advertised = new CopyOnWriteArrayList<>();
    /** The messages clients published, by topic. */
    public final Map<String, List<JsonNode>> published = new ConcurrentHashMap<>();
    /** Each subscription's compression, in order ("none" when it asked for none). */
    public final List<String> compressions = new CopyOnWriteArrayList<>();
    /** The binary (cbor-raw) frames sent. */
    public final AtomicInteger binaryFrames = new AtomicInteger();
    private static final ObjectMapper CBOR = new CBORMapper();
    private final Map<WebSocket, List<String>> topics = new ConcurrentHashMap<>();
    /** The topics each connection asked for as cbor-raw. */
    private final Map<WebSocket, List<String>> raw = new ConcurrentHashMap<>();
    private final CountDownLatch started = new CountDownLatch(1);

    public FakeRosbridge() {
        super(new InetSocketAddress(java.net.InetAddress.getLoopbackAddress(), 0));
        setReuseAddr(true);
    }

    /** Starts it and waits until it listens; its URL. */
    public String begin() throws InterruptedException {
        start();
        if (!started.await(10, TimeUnit.SECONDS)) {
            throw new IllegalStateException("the fake rosbridge server did not start");
        }
        return "ws://127.0.0.1:" + getPort();
    }

    /**
     * Makes received messages timed by {@code times} in order (each message received takes the next), the wall
     * clock once they run out: a replayed run keeps its own times. Null restores the wall clock.
     */
    public static void replayClock(Queue<Long> times) {
        RosbridgeClient.clock = times == null ? RosbridgeClient::now : () -> {
            Long t = times.poll();
            return t == null ? RosbridgeClient.now() : t;
        };
    }

    /** A queue of the log times of {@code messages}, for {@link #replayClock}. */
    public static Queue<Long> times(List<BagMessage> messages) {
        Queue<Long> q = new ConcurrentLinkedQueue<>();
        messages.forEach(m -> q.add(m.logTimeNanos()));
        return q;
    }

    /** Sends {@code m} to every connection subscribed to its topic; how many. */
    public int publish(BagMessage m) {
        ObjectNode op = JSON.createObjectNode().put("op", "publish").put("topic", m.topic());
        op.set("msg", JSON.valueToTree(asRosbridge(m.fields(), "", ByteArrays.paths(m.type()))));
        String text;
        try {
            text = JSON.writeValueAsString(op);
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
        int sent = 0;
        for (Map.Entry<WebSocket, List<String>> e : topics.entrySet()) {
            if (e.getValue().contains(m.topic()) && e.getKey().isOpen()) {
                if (raw.getOrDefault(e.getKey(), List.of()).contains(m.topic())) {
                    e.getKey().send(cborRaw(m));
                    binaryFrames.incrementAndGet();
                } else {
                    e.getKey().send(text);
                }
                sent++;
            }
        }
        return sent;
    }

    /** The cbor-raw frame of {@code m}: its CDR bytes (by predmon's bundled definition) in a CBOR publish op. */
    private static byte[] cborRaw(BagMessage m) {
        Map<String, Object> msg = new java.util.LinkedHashMap<>();
        msg.put("secs", m.logTimeNanos() / 1_000_000_000L);
        msg.put("nsecs", m.logTimeNanos() % 1_000_000_000L);
        msg.put("bytes", CdrMessages.encode(m.type(), m.fields()));
        Map<String, Object> op = new java.util.LinkedHashMap<>();
        op.put("op", "publish");
        op.put("topic", m.topic());
        op.put("msg", msg);
        try {
            return CBOR.writeValueAsBytes(op);
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
    }

    private static Object asRosbridge(Object v, String path, List<String> bytes) {
        if (v instanceof Map<?, ?> map) {
            Map<String, Object> out = new java.util.LinkedHashMap<>();
            map.forEach((k, x) -> out.put((String) k, asRosbridge(x, path.isEmpty() ? (String) k : path + "." + k,
                    bytes)));
            return out;
        }
        if (v instanceof List<?> l) {
            if (bytes.contains(path)) {
                byte[] b = new byte[l.size()];
                for (int i = 0; i < b.length; i++) {
                    b[i] = (byte) (long) (Long) l.get(i);
                }
                return Base64.getEncoder().encodeToString(b);
            }
            List<Object> out = new ArrayList<>();
            l.forEach(x -> out.add(asRosbridge(x, path, bytes)));
            return out;
        }
        return v;
    }

    /** Whether some open connection is subscribed to every one of {@code wanted}. */
    public boolean subscribed(List<String> wanted) {
        return topics.entrySet().stream().anyMatch(e -> e.getKey().isOpen() && e.getValue().containsAll(wanted));
    }

    /** Drops every connection, as a network failure or a restarted server does. */
    public void dropAll() {
        getConnections().forEach(c -> c.closeConnection(1006, "dropped by the test"));
    }

    @Override
    public void onOpen(WebSocket conn, ClientHandshake handshake) {
        topics.put(conn, new CopyOnWriteArrayList<>());
    }

    @Override
    public void onClose(WebSocket conn, int code, String reason, boolean remote) {
        topics.remove(conn);
        raw.remove(conn);
    }

    @Override
    public void onMessage(WebSocket conn, String message) {
        JsonNode op;
        try {
            op = JSON.readTree(message);
        } catch (java.io.IOException e) {
            conn.send("{\"op\":\"status\",\"level\":\"error\",\"msg\":\"not JSON\"}");
            return;
        }
        String topic = op.path("topic").asText();
        switch (op.path("op").asText()) {
            case "subscribe" -> {
                topics.computeIfAbsent(conn, k -> new CopyOnWriteArrayList<>()).add(topic);
                subscribes.add(topic + " " + op.path("type").asText());
                String compression = op.path("compression").asText("none");
                compressions.add(compression);
                if (compression.equals("cbor-raw")) {
                    raw.computeIfAbsent(conn, k -> new CopyOnWriteArrayList<>()).add(topic);
                }
            }
            case "unsubscribe" -> topics.getOrDefault(conn, new ArrayList<>()).remove(topic);
            case "advertise" -> advertised.add(topic + " " + op.path("type").asText());
            case "publish" -> published.computeIfAbsent(topic, k -> new CopyOnWriteArrayList<>()).add(op.get("msg"));
            default -> conn.send("{\"op\":\"status\",\"level\":\"error\",\"msg\":\"unknown op\"}");
        }
    }

    @Override
    public void onError(WebSocket conn, Exception ex) {
        // a connection's error closes it
    }

    @Override
    public void onStart() {
        started.countDown();
    }

}
