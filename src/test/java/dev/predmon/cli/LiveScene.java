package dev.predmon.cli;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.file.AbstractionFiles;
import dev.predmon.event.LogEvent;
import dev.predmon.live.Board;
import dev.predmon.live.HttpAddress;
import dev.predmon.live.LiveServer;
import dev.predmon.live.RobotNames;
import dev.predmon.live.Tile;
import dev.predmon.model.ModelSet;
import dev.predmon.model.ModelStore;
import dev.predmon.monitor.LogWatcher;
import dev.predmon.monitor.MonitorEvent;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.parse.LogRecord;

import java.io.IOException;
import java.net.URI;
import java.nio.file.Path;
import java.time.Duration;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A live view served in-process, its tiles fed as {@code watch} feeds them (each log through its own monitor, each event
 * as {@code watch --json} prints it), so that a test decides what each robot has shown and when its log last grew.
 */
final class LiveScene implements AutoCloseable {

    final ModelSet models;
    final Abstraction abstraction;
    final Board board;
    private final Map<Path, LogWatcher> watchers = new HashMap<>();
    private final Map<Tile, PredictiveMonitor> monitors = new HashMap<>();
    final LiveServer server;

    LiveScene(Path modelsDir, Duration staleAfter, RobotNames names, List<String> watching) throws Exception {
        this(AbstractionFiles.load(ModelStore.storedAbstraction(modelsDir).orElseThrow()), modelsDir, staleAfter,
                names, watching);
    }

    private LiveScene(Abstraction abstraction, Path modelsDir, Duration staleAfter, RobotNames names,
                      List<String> watching) throws Exception {
        this(ModelStore.read(modelsDir, abstraction), abstraction, staleAfter, names, watching);
    }

    /** A scene of models as given (read from a directory, then changed by the test). */
    LiveScene(ModelSet models, Abstraction abstraction, Duration staleAfter, RobotNames names, List<String> watching)
            throws Exception {
        this.abstraction = abstraction;
        this.models = models;
        board = new Board(models, abstraction, staleAfter, names);
        board.watching(watching);
        server = LiveServer.start(HttpAddress.parse("0"), board);
    }

    /**
     * Reads what {@code log} holds beyond what was read of it before into its tile, as a followed log: pending pairs
     * wait for more.
     */
    Tile follow(Path log) throws Exception {
        Tile tile = board.tile(log.toString());
        LogWatcher w = watchers.get(log);
        if (w == null) {
            PredictiveMonitor monitor = new PredictiveMonitor(models, abstraction, 0, e -> event(tile, e));
            w = LogWatcher.withRecords(log, monitor, p -> { }, r -> {
                tile.record(r, monitor.judged());
                tile.properties(monitor.properties());
            });
            watchers.put(log, w);
        }
        while (w.poll()) {
            board.grew(tile);
        }
        return tile;
    }

    /**
     * Hands {@code records} to {@code tile} as watch does, each followed by every property's status as a monitor of
     * the tile's log sees it (the monitor's own events are left out: the test gives the tile the events it shows).
     */
    void records(Tile tile, List<LogRecord> records) {
        PredictiveMonitor m = monitors.computeIfAbsent(tile, t -> new PredictiveMonitor(models, abstraction, 0, e -> { }));
        for (LogRecord r : records) {
            m.accept(r);
            tile.record(r, m.judged());
            tile.properties(m.properties());
        }
    }

    /** As {@link #records}, with the monitor's events too: the tile shows what watch would show of these records. */
    void feed(Tile tile, List<LogRecord> records) {
        PredictiveMonitor m = monitors.computeIfAbsent(tile, t -> new PredictiveMonitor(models, abstraction, 0,
                e -> event(t, e)));
        for (LogRecord r : records) {
            m.accept(r);
            tile.record(r, m.judged());
            tile.properties(m.properties());
        }
    }

    /** {@code e} of {@code tile}'s log, as watch gives it to the live view. */
    void event(Tile tile, MonitorEvent e) {
        if (!(e instanceof MonitorEvent.Unmapped)) {
            board.event(tile, LogEvent.of(tile.log(), e));
        }
    }

    /** Until closed, the logs of {@code tiles} look as if they kept growing (as live robots' logs do). */
    AutoCloseable growing(List<Tile> tiles) {
        Thread beat = new Thread(() -> {
            while (!Thread.currentThread().isInterrupted()) {
                tiles.forEach(board::grew);
                try {
                    Thread.sleep(300);
                } catch (InterruptedException e) {
                    return;
                }
            }
        }, "live-scene-growing");
        beat.start();
        return () -> {
            beat.interrupt();
            beat.join();
        };
    }

    URI url() {
        return server.url();
    }

    @Override
    public void close() throws IOException {
        server.close();
        for (LogWatcher w : watchers.values()) {
            w.close();
        }
    }
}
