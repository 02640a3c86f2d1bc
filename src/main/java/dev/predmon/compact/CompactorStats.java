package dev.predmon.compact;

/**
 * What a {@link Compactor} has seen so far.
 *
 * @param answeredPairs      commands answered by a reply, in command order, whether kept or not
 * @param keptPairs          pairs emitted because their output differs from the query's previous one
 * @param unansweredDropped  commands never answered: superseded on their channel, or pending at the end
 * @param orphanReplies      replies with no pending command on their channel
 */
public record CompactorStats(long answeredPairs, long keptPairs, long unansweredDropped, long orphanReplies) {
}
