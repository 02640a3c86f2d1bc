package dev.predmon.cli;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.monitor.Fleet;
import dev.predmon.monitor.FleetListener;
import dev.predmon.rosbridge.Diagnostics;
import dev.predmon.rosbridge.RosbridgeClient;
import dev.predmon.rosbridge.RosbridgeFormat;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;

import java.io.PrintWriter;
import java.net.URI;
import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.List;

/**
 * {@code watch --rosbridge URL [--rosbridge-compression none|cbor-raw] [--publish-diagnostics]}: a live robot instead
 * of logs.
 */
final class RosbridgeOptions {

    @Option(names = "--rosbridge", paramLabel = "URL",
            description = "Watch a live robot instead of a log: subscribe to the abstraction's ROS 2 topics through "
                    + "a rosbridge server (ws://HOST:9090, rosbridge v2 protocol, JSON) and judge its messages as a "
                    + "recording's. Connects again with a growing pause when the connection drops; nothing is judged "
                    + "across the gap.")
    String url;

    @Option(names = "--rosbridge-compression", paramLabel = "none|cbor-raw", defaultValue = "none",
            description = "With --rosbridge: how the server sends each message: none (JSON text, the default), or "
                    + "cbor-raw (the message's CDR bytes in a CBOR binary frame, decoded with predmon's bundled "
                    + "definition of the topic's type; lighter for the robot).")
    String compression;

    @Option(names = "--publish-diagnostics", description = "With --rosbridge: publish each property's verdict on "
            + "/diagnostics (diagnostic_msgs/DiagnosticArray, once a second: OK holds, WARN warned, ERROR violated, "
            + "STALE no evidence), as rqt_robot_monitor shows it.")
    boolean diagnostics;

    boolean given() {
        return url != null;
    }

    /** Checks the options against the rest of the command line, before anything starts. */
    void check(CommandSpec spec, boolean logs, boolean noFollow, Abstraction abstraction) {
        if (!compression.equals("none") && !compression.equals("cbor-raw")) {
            throw new ParameterException(spec.commandLine(), "--rosbridge-compression must be none or cbor-raw, got '"
                    + compression + "'");
        }
        if (url == null) {
            if (!compression.equals("none")) {
                throw new ParameterException(spec.commandLine(), "--rosbridge-compression is how a rosbridge server "
                        + "sends: give --rosbridge ws://HOST:9090");
            }
            if (diagnostics) {
                throw new ParameterException(spec.commandLine(), "--publish-diagnostics publishes to the robot of "
                        + "--rosbridge: give --rosbridge ws://HOST:9090");
            }
            return;
        }
        if (logs) {
            throw new ParameterException(spec.commandLine(), "--rosbridge watches a live robot: not with --log");
        }
        if (noFollow) {
            throw new ParameterException(spec.commandLine(), "--rosbridge watches a live robot, which has no end: "
                    + "not with --no-follow");
        }
        uri(spec);
        if (RosbridgeFormat.subscriptions(abstraction.topicRules()).isEmpty()) {
            throw new ParameterException(spec.commandLine(), "--rosbridge: the abstraction " + abstraction.name()
                    + " names no ROS 2 topic to subscribe to: give --abstraction nav2, or an abstraction file "
                    + "with a ros2 section");
        }
        if (cborRaw()) {
            try {
                RosbridgeClient.decoders(RosbridgeFormat.subscriptions(abstraction.topicRules()));
            } catch (IllegalArgumentException e) {
                throw new ParameterException(spec.commandLine(), "--rosbridge-compression cbor-raw: " + e.getMessage());
            }
        }
    }

    private boolean cborRaw() {
        return compression.equals("cbor-raw");
    }

    private URI uri(CommandSpec spec) {
        try {
            URI uri = new URI(url);
            if ((!"ws".equals(uri.getScheme()) && !"wss".equals(uri.getScheme())) || uri.getHost() == null) {
                throw new URISyntaxException(url, "expected ws://HOST:PORT or wss://HOST:PORT");
            }
            return uri;
        } catch (URISyntaxException e) {
            throw new ParameterException(spec.commandLine(), "--rosbridge " + url + ": expected ws://HOST:PORT "
                    + "(rosbridge's default port is 9090)");
        }
    }

    /** Starts the client: its topics subscribed to as soon as the connection is made. */
    RosbridgeClient start(CommandSpec spec, Abstraction abstraction, PrintWriter err) {
        List<String> patterns = RosbridgeFormat.patterns(abstraction.topicRules());
        if (!patterns.isEmpty()) {
            err.println("predmon: note: rosbridge cannot subscribe to a pattern; not watched: "
                    + String.join(", ", patterns) + " (name the topics in the abstraction file)");
        }
        return new RosbridgeClient(uri(spec), RosbridgeFormat.subscriptions(abstraction.topicRules()), cborRaw());
    }

    /** The fleet's listener: {@code session}, with the diagnostics published in front of it when asked. */
    FleetListener listener(FleetListener session, RosbridgeClient client) {
        return client != null && diagnostics ? new Diagnostics(session, client) : session;
    }

    /** Adds the robot to {@code fleet} as its one log, named by the URL. */
    void add(Fleet fleet, Abstraction abstraction, RosbridgeClient client) {
        fleet.add(Path.of("rosbridge", client.uri().getHost() + "_" + client.uri().getPort()), url,
                new RosbridgeFormat(abstraction.topicRules(), client));
        client.start();
    }
}
