package dev.predmon.pipeline;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.Classification;
import dev.predmon.abstraction.RunRule;
import dev.predmon.abstraction.UnmappedMessage;
import dev.predmon.compact.Compactor;
import dev.predmon.mealy.CarryEncoder;
import dev.predmon.parse.LogRecord;

import java.util.List;
import java.util.Map;

/**
 * The one path every log takes, offline ({@code learn}, {@code classify}, {@code evaluate}) and live
 * ({@code watch}): records are abstracted to symbols, interface messages are compacted into query/reply
 * pairs, and each pair is handed to the listener. Sharing this class is what makes a log abstract
 * identically in both modes.
 */
public final class TracePipeline {

    private final Abstraction abstraction;
    private final PipelineListener listener;
    private final Compactor compactor;
    private final CarryEncoder encoder;
    private final Hysteresis hysteresis;
    private final RunSplitter runs;
    private final QuietRestart restart;
    private int run;
    private final UnmappedCounts unmapped = new UnmappedCounts();
    private LogRecord current;
    private long records;
    private long interfaceRecords;
    /** The lines of the first and of the last record taken; {@code firstLine} is 0 before any. */
    private long firstLine;
    private long lastLine;

    public TracePipeline(Abstraction abstraction, PipelineListener listener) {
        this.abstraction = abstraction;
        this.listener = listener;
        this.encoder = new CarryEncoder(abstraction);
        this.hysteresis = new Hysteresis(abstraction);
        this.runs = new RunSplitter(abstraction.runs());
        this.restart = new QuietRestart(abstraction.runs().quiet());
        this.compactor = new Compactor(pair -> listener.pair(encoder.encode(pair), current), abstraction::bandPath);
    }

    /**
     * Takes the next record of the log. A record that begins a new run ({@link RunRule})
     * first ends the run before it, as the end of a log would, and starts matching over.
     */
    public void accept(LogRecord record) {
        boolean starts = runs.startsRun(record) && records > 0;
        Classification c = abstraction.classify(record);
        // after a quiet pause, records are held until the commands say whether the tree started over
        if (restart.holding() || (!starts && records > 0 && restart.quietBefore(record))) {
            QuietRestart.Decision d = restart.hold(record, c, starts);
            if (d != QuietRestart.Decision.PENDING) {
                release(d == QuietRestart.Decision.RESTART);
            }
            return;
        }
        process(record, c, starts);
    }

    /** Processes the records held after a quiet pause, the first of them beginning a run if the tree restarted. */
    private void release(boolean restarted) {
        List<QuietRestart.Held> held = restart.release();
        for (int i = 0; i < held.size(); i++) {
            QuietRestart.Held h = held.get(i);
            process(h.record(), h.classification(), h.starts() || (i == 0 && restarted));
        }
    }

    private void process(LogRecord record, Classification c, boolean starts) {
        if (starts) {
            compactor.endOfInput();
            compactor.reset();
            encoder.reset();
            hysteresis.reset();
            listener.runStarted(++run, record);
        }
        restart.processed(record, c, starts);
        current = record;
        records++;
        if (firstLine == 0) {
            firstLine = record.line();
        }
        lastLine = record.line();
        listener.record(record);
        if (c instanceof Classification.Mapped m) {
            interfaceRecords++;
            listener.mapped(record, m);
            compactor.push(hysteresis.settle(m.event()));
        } else if (c instanceof Classification.Unmapped u) {
            interfaceRecords++;
            UnmappedMessage first = unmapped.add(u.message(), 1);
            if (first != null) {
                listener.unmapped(first, record);
            }
            if (UnmappedMessages.novelty(u.message(), abstraction)) {
                listener.gap(record);
            }
        }
    }

    /** The log is complete: commands still waiting for replies are dropped, pending pairs are flushed. */
    public void endOfInput() {
        if (restart.holding()) {
            release(false); // the log ended before the commands after its last pause said the tree restarted
        }
        compactor.endOfInput();
    }

    /** Forgets the log read so far (it was truncated or replaced); counters restart too. */
    public void reset() {
        compactor.reset();
        encoder.reset();
        hysteresis.reset();
        runs.reset();
        restart.reset();
        run = 0;
        unmapped.clear();
        current = null;
        records = 0;
        interfaceRecords = 0;
        firstLine = 0;
        lastLine = 0;
    }

    /**
     * The lines from the first record to the end of the last one (0 before any): how much of the file the records
     * are spread over, whatever lies between them.
     */
    public long span() {
        return firstLine == 0 ? 0 : lastLine - firstLine + Evidence.RECORD_LINES;
    }

    /**
     * Interface messages no rule maps, by key, sorted: reported to the user, never silently dropped; beyond
     * {@value UnmappedCounts#KINDS} kinds, counted by command ({@link UnmappedCounts}).
     */
    public Map<UnmappedMessage, Long> unmapped() {
        return unmapped.toMap();
    }

    /** The run being read: 0, then 1, 2, ... in a log that holds several. */
    public int run() {
        return run;
    }

    /** Records seen. */
    public long records() {
        return records;
    }

    /** Records of the skill-component interface (mapped or not). */
    public long interfaceRecords() {
        return interfaceRecords;
    }

    public Abstraction abstraction() {
        return abstraction;
    }
}
