package dev.predmon.live;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import dev.predmon.abstraction.Abstraction;
import dev.predmon.event.LogEvent;
import dev.predmon.forecast.ForecastFile;
import dev.predmon.forecast.Scorecard;
import dev.predmon.model.LearnedModel;
import dev.predmon.model.ModelSet;
import dev.predmon.monitor.DeletedLogs;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.WarningRule;
import dev.predmon.property.Bound;
import dev.predmon.property.Property;

import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.LongSupplier;

import static dev.predmon.live.TileJson.JSON;

/**
 * The live view's state: one {@link Tile} per watched log, named after its robot, and the stream of events sent to
 * {@code /events}. The monitor's thread feeds it; the server's threads read it.
 */
public final class Board {

    /**
     * How long the tile of a deleted log stays, saying so: then it leaves the page and {@code /metrics}, so that a
     * fleet whose logs come and go does not keep every log it ever watched.
     */
    public static final Duration DELETED_KEPT = DeletedLogs.KEPT;

    /** The order of {@code /status} and of the page: worst first (see {@link TileState}), then by robot. */
    private static final List<String> ORDER = List.of("violation", "warning", "unknown", "no-verdict", "ok", "waiting",
            "ended");

    private final List<LearnedModel> models;
    private final Optional<Bound> safety;
    private final List<Property> properties;
    private final List<Scorecard> scorecards;
    private final long staleMillis;
    private final LongSupplier clock;
    private final RobotNames names;
    private final Map<String, Tile> tiles = new LinkedHashMap<>();
    /** When each tile's log was first seen deleted (clock millis), for the tiles whose log is gone. */
    private final Map<Tile, Long> deletedSince = new HashMap<>();
    private final EventStream stream = new EventStream();
    private final Metrics metrics;
    private volatile List<String> watching = List.of();
    private volatile Double warnsAt;

    /** @param staleAfter a log that has not grown for this long is marked STALE (or its run ended, see Tile) */
    public Board(ModelSet models, Abstraction abstraction, Duration staleAfter, RobotNames names) {
        this(models.models(), abstraction.safety(), abstraction.properties(), staleAfter, System::currentTimeMillis,
                names, models.forecast() == null ? List.of() : models.forecast().allScorecards());
        warnsAt(PredictiveMonitor.defaultRule(models), models);
    }

    /**
     * The monitors warn by {@code rule}: with the forecast rule, a tile below the threshold says how far it is from a
     * warning ({@code P 0.23, warning at 0.86}).
     */
    public void warnsAt(WarningRule rule, ModelSet models) {
        warnsAt = rule == WarningRule.FORECAST && models.forecast() != null ? models.forecast().threshold() : null;
    }

    Board(List<LearnedModel> models, Optional<Bound> safety, Duration staleAfter, LongSupplier clock) {
        this(models, safety, staleAfter, clock, RobotNames.byFile());
    }

    Board(List<LearnedModel> models, Optional<Bound> safety, Duration staleAfter, LongSupplier clock,
          RobotNames names) {
        this(models, safety, staleAfter, clock, names, List.of());
    }

    Board(List<LearnedModel> models, Optional<Bound> safety, Duration staleAfter, LongSupplier clock,
          RobotNames names, List<Scorecard> scorecards) {
        this(models, safety, safety.<List<Property>>map(List::of).orElse(List.of()), staleAfter, clock, names,
                scorecards);
    }

    /** @param properties every property of the abstraction, each with its light on every tile */
    Board(List<LearnedModel> models, Optional<Bound> safety, List<Property> properties, Duration staleAfter,
          LongSupplier clock, RobotNames names, List<Scorecard> scorecards) {
        this.models = List.copyOf(models);
        this.safety = safety;
        this.properties = List.copyOf(properties);
        this.scorecards = List.copyOf(scorecards);
        this.staleMillis = staleAfter.toMillis();
        this.clock = clock;
        this.names = names;
        this.metrics = new Metrics(() -> status(null), safety.map(Bound::name).orElse(""),
                this.properties.stream().map(Property::id).toList(), safety.map(Bound::id).orElse(null), names::of);
    }

    /** The tile of {@code log}, made on first use. */
    public synchronized Tile tile(String log) {
        return tiles.computeIfAbsent(log, l -> {
            Tile t = new Tile(l, names.of(l), models, safety, properties, clock.getAsLong());
            metrics.added(t);
            return t;
        });
    }

    /** {@code tile}'s log was deleted long ago and is forgotten: the tile and its series leave for good. */
    public synchronized void forget(Tile tile) {
        deletedSince.remove(tile);
        if (tiles.remove(tile.log(), tile)) {
            metrics.removed(tile);
        }
    }

    /** A tile that left the board with its deleted log comes back when the log does. */
    private synchronized void shown(Tile tile) {
        if (tiles.putIfAbsent(tile.log(), tile) == null) {
            metrics.added(tile);
        }
    }

    /**
     * Each tile whose log was deleted: since when, as {@code deleted} seconds in its snapshot; a tile deleted longer
     * than {@link #DELETED_KEPT} leaves the board and its series leave {@code /metrics}. A log that never had a
     * record is waited for, not deleted.
     */
    private synchronized Map<Tile, Long> sweepDeleted(long now) {
        for (Tile t : new ArrayList<>(tiles.values())) {
            if (t.empty() || exists(t)) {
                deletedSince.remove(t);
                continue;
            }
            long since = deletedSince.computeIfAbsent(t, k -> now);
            if (now - since > DELETED_KEPT.toMillis()) {
                tiles.remove(t.log());
                deletedSince.remove(t);
                metrics.removed(t);
            }
        }
        return new HashMap<>(deletedSince);
    }

    /**
     * What is watched, in words ({@code logs (*.log, *.txt) in /robots}): the page says it while no log is there
     * yet.
     */
    public void watching(List<String> what) {
        watching = List.copyOf(what);
    }

    /** An event of {@code tile}'s log: the tile takes it, and {@code /events} sends its JSON (which names the log). */
    public void event(Tile tile, LogEvent e) {
        shown(tile);
        tile.event(e);
        metrics.event(tile, e.event());
        stream.publish(e.line());
    }

    /** {@code tile}'s log grew now. */
    public void grew(Tile tile) {
        shown(tile);
        tile.grew(clock.getAsLong());
    }

    /**
     * {@code /status}: {@code {"staleAfter": seconds, "watching": [...], "scorecards": [...], "logs": [tile, ...]}},
     * every tile worst first, or only {@code log}'s ({@code "logs"} is then empty for a log not watched). The
     * scorecards are the models' own ({@link Scorecard}), one per property, each with its {@code summary} in words and
     * whether the forecast has {@code skill}.
     */
    public ObjectNode status(String log) {
        List<Tile> all;
        Map<Tile, Long> deleted = sweepDeleted(clock.getAsLong());
        synchronized (this) {
            all = log == null ? new ArrayList<>(tiles.values())
                    : tiles.containsKey(log) ? List.of(tiles.get(log)) : List.of();
        }
        long now = clock.getAsLong();
        String action = safety.map(Bound::action).orElse(null);
        Map<Tile, String> shown = shownNames();
        String property = safety.map(Bound::name).orElse(null);
        Boolean skill = scorecards.stream().filter(c -> c.property().equals(property)).findFirst()
                .map(Scorecard::skill).orElse(null);
        Map<String, Boolean> skills = new HashMap<>(); // every scorecard's, by the property's name
        scorecards.forEach(c -> skills.putIfAbsent(c.property(), c.skill()));
        List<ObjectNode> snapshots = new ArrayList<>();
        for (Tile t : all) {
            String name = shown.getOrDefault(t, t.name());
            ObjectNode snapshot = t.snapshot(now, staleMillis, new Tile.Shown(name, action, warnsAt,
                    !t.empty() || exists(t), skill, skills));
            Long gone = deleted.get(t);
            if (gone != null) {
                snapshot.put("deleted", (now - gone) / 1000.0); // seconds since the log was found deleted
                snapshot.put("leavesIn", Math.max(0, (DELETED_KEPT.toMillis() - (now - gone)) / 1000.0));
            }
            snapshots.add(snapshot);
        }
        snapshots.sort(Comparator.comparingInt(Board::rank).thenComparing(s -> s.get("name").asText())
                .thenComparing(s -> s.get("log").asText()));
        ObjectNode o = JSON.createObjectNode();
        o.put("staleAfter", staleMillis / 1000.0);
        ArrayNode w = o.putArray("watching");
        watching.forEach(w::add);
        ArrayNode cards = o.putArray("scorecards");
        for (Scorecard c : scorecards) {
            ObjectNode n = ForecastFile.scorecard(c);
            n.put("skill", c.skill());
            n.put("summary", c.summary());
            cards.add(n);
        }
        ArrayNode logs = o.putArray("logs");
        snapshots.forEach(logs::add);
        return o;
    }

    /** Every tile's robot name as shown: by default without the part the names of all logs share. */
    private synchronized Map<Tile, String> shownNames() {
        List<Tile> every = new ArrayList<>(tiles.values());
        List<String> shown = names.shown(every.stream().map(Tile::name).toList());
        Map<Tile, String> byTile = new HashMap<>();
        for (int i = 0; i < every.size(); i++) {
            byTile.put(every.get(i), shown.get(i));
        }
        return byTile;
    }

    /** Whether a log's file exists (asked only of logs that never had a record). */
    private static boolean exists(Tile t) {
        try {
            return Files.exists(Path.of(t.log()));
        } catch (InvalidPathException e) {
            return false;
        }
    }

    /**
     * Where a tile sorts: by its state, a log quiet mid-run with the unknown ones (nobody knows what it does now), and
     * a tile one of whose other properties is violated or warned with the violations or the warnings.
     */
    static int rank(ObjectNode tile) {
        int r = ORDER.indexOf(tile.get("state").asText());
        r = tile.get("stale").asBoolean() && r > ORDER.indexOf("unknown") ? ORDER.indexOf("unknown") : r;
        String worst = tile.path("worst").path("state").asText("");
        int w = worst.equals("violated") ? ORDER.indexOf("violation") : worst.equals("warning")
                ? ORDER.indexOf("warning") : r;
        return Math.min(r, w);
    }

    /** How many pages are connected to {@code /events} now. */
    public int viewers() {
        return stream.clients();
    }

    EventStream stream() {
        return stream;
    }

    /** {@code /metrics}. */
    Metrics metrics() {
        return metrics;
    }
}
