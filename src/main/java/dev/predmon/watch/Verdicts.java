package dev.predmon.watch;

import dev.predmon.BadInputException;
import dev.predmon.Terminal;
import dev.predmon.monitor.WatchedLog;
import dev.predmon.pipeline.Evidence;

import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * The end of a watch session: each log's verdict with its summary ({@link Summary}), or why it gets none, and the
 * session's exit code ({@link ExitRule}): a log with nothing to judge is 3 (with {@code --no-follow}, or when it is
 * the only log, an error that says why), a file beside the logs of a directory that holds no record is skipped when
 * another log was judged, and several logs combine by {@link ExitRule#ofLogs}.
 */
final class Verdicts {

    private final WatchSession session;
    private final Summary summary;
    private final boolean noFollow;
    private final boolean several;

    Verdicts(WatchSession session, Summary summary, WatchSettings settings) {
        this.session = session;
        this.summary = summary;
        this.noFollow = settings.noFollow();
        this.several = settings.several();
    }

    /** Every log's summary, in order, and the exit code; {@code stop} is why the watch ended. */
    int of(List<WatchedLog> logs, String stop) throws BadInputException {
        List<Integer> codes = new ArrayList<>();
        boolean anyJudged = logs.stream().anyMatch(l -> whyNoVerdict(session.evidence(l)).isEmpty());
        for (WatchedLog l : logs) {
            Evidence evidence = session.evidence(l);
            Optional<String> refused = refusal(evidence);
            Optional<String> misfit = refused.isPresent() ? Optional.empty() : evidence.misfit();
            boolean beside = session.besideTheLogs(l);
            if (beside && anyJudged) {
                continue; // not a log, beside one that was judged: skipped silently
            }
            if ((noFollow || beside) && refused.isPresent()) { // said once, and no summary of nothing
                codes.add(noVerdict(refused.get()));
                continue;
            }
            if (noFollow && misfit.isPresent()) { // which messages, by command, then why there is no verdict
                ProblemLines.unmapped(summary.err(), l.path(), l.monitor().unmapped());
                codes.add(noVerdict(misfit.get()));
                continue;
            }
            if (noFollow) {
                session.flushProblems(l);
            }
            Optional<String> why = refused.or(() -> misfit);
            int code = summary.print(l, stop, why.isEmpty(), run -> session.restartBefore(l, run));
            if (why.isPresent()) {
                summary.err().println("predmon: " + Terminal.line(Files.exists(l.path()) ? why.get()
                        : l.name() + ": stopped before the file appeared; no verdict"));
                code = ExitRule.BAD_INPUT;
            }
            codes.add(code);
        }
        summary.err().flush();
        return codes.size() == 1 ? codes.get(0) : ExitRule.ofLogs(codes);
    }

    /**
     * A log forgotten once deleted: its summary ({@code stop} {@code deleted}) and its code, or nothing for a file that
     * gave nothing to judge (notes beside the logs).
     */
    Optional<Integer> forgotten(WatchedLog l) {
        if (whyNoVerdict(session.evidence(l)).isPresent()) {
            return Optional.empty();
        }
        return Optional.of(summary.print(l, "deleted", true, run -> session.restartBefore(l, run)));
    }

    /** A log without a verdict: the error of a single log, or a line among several and 3. */
    private int noVerdict(String why) throws BadInputException {
        if (!several) {
            throw new BadInputException(why);
        }
        summary.err().println("predmon: " + Terminal.line(why));
        return ExitRule.BAD_INPUT;
    }

    /**
     * Why a log can be given no verdict at all: nothing to judge, or (with {@code --no-follow}, where the whole file
     * is known) a file that is mostly not records.
     */
    private Optional<String> refusal(Evidence evidence) {
        Optional<String> missing = evidence.missing();
        return noFollow ? missing.or(evidence::fragment) : missing;
    }

    /** Why a log gets no verdict: {@link #refusal}, or models that do not fit it; empty when it gets one. */
    private Optional<String> whyNoVerdict(Evidence evidence) {
        return refusal(evidence).or(evidence::misfit);
    }
}
