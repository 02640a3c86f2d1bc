package dev.predmon.live;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.SafetyRule;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.MonitorEvent;

import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.LongSupplier;

/**
 * The live view's state: one {@link Tile} per watched log, in the order the logs were added, and the stream of
 * events sent to {@code /events}. The monitor's thread feeds it; the server's threads read it.
 */
public final class Board {

    private static final ObjectMapper JSON = new ObjectMapper();

    private final List<LearnedModel> models;
    private final Optional<SafetyRule> safety;
    private final long staleMillis;
    private final LongSupplier clock;
    private final Map<String, Tile> tiles = new LinkedHashMap<>();
    private final EventStream stream = new EventStream();

    /** @param staleAfter a log that has not grown for this long is marked STALE */
    public Board(ModelSet models, Abstraction abstraction, Duration staleAfter) {
        this(models.models(), abstraction.safety(), staleAfter, System::currentTimeMillis);
    }

    Board(List<LearnedModel> models, Optional<SafetyRule> safety, Duration staleAfter, LongSupplier clock) {
        this.models = List.copyOf(models);
        this.safety = safety;
        this.staleMillis = staleAfter.toMillis();
        this.clock = clock;
    }

    /** The tile of {@code log}, made on first use. */
    public synchronized Tile tile(String log) {
        return tiles.computeIfAbsent(log, l -> new Tile(l, models, safety, clock.getAsLong()));
    }

    /** An event of {@code tile}'s log: the tile takes it, and {@code /events} sends its JSON (which names the log). */
    public void event(Tile tile, MonitorEvent e, String json) {
        tile.event(e, json);
        stream.publish(json);
    }

    /** {@code tile}'s log grew now. */
    public void grew(Tile tile) {
        tile.grew(clock.getAsLong());
    }

    /**
     * {@code /status}: {@code {"staleAfter": seconds, "logs": [tile, ...]}}, every tile, or only {@code log}'s
     * ({@code logs} is then empty for a log not watched).
     */
    public ObjectNode status(String log) {
        List<Tile> all;
        synchronized (this) {
            all = log == null ? new ArrayList<>(tiles.values())
                    : tiles.containsKey(log) ? List.of(tiles.get(log)) : List.of();
        }
        long now = clock.getAsLong();
        ObjectNode o = JSON.createObjectNode();
        o.put("staleAfter", staleMillis / 1000.0);
        ArrayNode logs = o.putArray("logs");
        for (Tile t : all) {
            logs.add(t.snapshot(now, staleMillis));
        }
        return o;
    }

    /** How many pages are connected to {@code /events} now. */
    public int viewers() {
        return stream.clients();
    }

    EventStream stream() {
        return stream;
    }
}
