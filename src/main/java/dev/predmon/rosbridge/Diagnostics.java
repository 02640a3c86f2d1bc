package dev.predmon.rosbridge;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.monitor.FleetListener;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.PropertyStatus;
import dev.predmon.monitor.WatchedLog;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.ParseProblem;
import dev.predmon.property.Verdict;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;

/**
 * Publishes each property's verdict on {@code /diagnostics} as a {@code diagnostic_msgs/DiagnosticArray}, one
 * status per property, which {@code rqt_robot_monitor} shows: OK (0) while it holds, WARN (1) once warned, ERROR (2)
 * once violated, STALE (3) while there is no evidence (nothing received since the connection was made) and never
 * anything better while disconnected. Sent once a second, as diagnostics are, and at once when a warning or a
 * violation comes. A listener of the fleet in front of the watch session, to which it passes everything on.
 */
public final class Diagnostics implements FleetListener {

    public static final String TOPIC = "/diagnostics";
    public static final String TYPE = "diagnostic_msgs/msg/DiagnosticArray";
    static final long PERIOD_NANOS = 1_000_000_000L;
    private static final ObjectMapper JSON = new ObjectMapper();

    private final FleetListener next;
    private final RosbridgeClient client;
    private final List<WatchedLog> logs = new ArrayList<>();
    private long lastSent;
    private long recordsAtConnect = -1;
    private boolean wasConnected;

    public Diagnostics(FleetListener next, RosbridgeClient client) {
        this.next = next;
        this.client = client;
        client.sendOnOpen(JSON.createObjectNode().put("op", "advertise").put("topic", TOPIC).put("type", TYPE)
                .toString());
    }

    /** The {@code publish} op of the array for {@code monitor}'s properties, as connected or not. */
    static String array(PredictiveMonitor monitor, boolean evidence, Instant at) {
        ObjectNode msg = JSON.createObjectNode();
        msg.putObject("header").put("frame_id", "").putObject("stamp").put("sec", at.getEpochSecond())
                .put("nanosec", at.getNano());
        ArrayNode status = msg.putArray("status");
        for (PropertyStatus p : monitor.properties()) {
            int level;
            String message;
            if (!evidence) {
                level = 3;
                message = "no evidence: " + (monitor.records() == 0 ? "nothing received yet" : "not connected");
            } else if (p.verdict() instanceof Verdict.Violated) {
                level = 2;
                message = p.verdict().describe();
            } else if (p.warned()) {
                level = 1;
                message = "warned; " + p.verdict().describe();
            } else {
                level = 0;
                message = p.verdict().describe();
            }
            ObjectNode s = status.addObject().put("level", level).put("name", "predmon: " + p.property().name())
                    .put("message", message).put("hardware_id", "predmon");
            ArrayNode values = s.putArray("values");
            values.addObject().put("key", "property").put("value", p.property().id());
            values.addObject().put("key", "verdict").put("value", evidence ? p.verdict().id() : "unknown");
            values.addObject().put("key", "run").put("value", Integer.toString(monitor.run()));
        }
        ObjectNode op = JSON.createObjectNode().put("op", "publish").put("topic", TOPIC);
        op.set("msg", msg);
        return op.toString();
    }

    private void publish() {
        boolean connected = client.connected();
        if (!connected) {
            wasConnected = false;
            return; // nothing can be sent; the next array after the connection is back says STALE first
        }
        for (WatchedLog log : logs) {
            long records = log.watcher().lines();
            if (!wasConnected) {
                recordsAtConnect = records;
            }
            client.send(array(log.monitor(), records > recordsAtConnect, Instant.now()));
        }
        wasConnected = true;
        lastSent = System.nanoTime();
    }

    @Override
    public void added(WatchedLog log) {
        logs.add(log);
        next.added(log);
    }

    @Override
    public void event(WatchedLog log, MonitorEvent event) {
        next.event(log, event);
        if (event instanceof MonitorEvent.Warning || event instanceof MonitorEvent.Violation) {
            publish();
        }
    }

    @Override
    public void pulse() {
        next.pulse();
        if (System.nanoTime() - lastSent >= PERIOD_NANOS || !wasConnected) {
            publish();
        }
    }

    @Override
    public void record(WatchedLog log, LogRecord record) {
        next.record(log, record);
    }

    @Override
    public void problem(WatchedLog log, ParseProblem problem) {
        next.problem(log, problem);
    }

    @Override
    public void grew(WatchedLog log) {
        next.grew(log);
    }

    @Override
    public void rescanFailed(IOException e) {
        next.rescanFailed(e);
    }

    @Override
    public void unnotified(Path dir, String why, long pauseNanos) {
        next.unnotified(dir, why, pauseNanos);
    }

    @Override
    public void caughtUp() {
        next.caughtUp();
    }

    @Override
    public long beat() {
        return next.beat();
    }

    @Override
    public void notice(String line) {
        next.notice(line);
    }
}
