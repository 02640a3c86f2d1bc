/**
 * The one path every log takes, offline and live: records are abstracted, settled by hysteresis, compacted into
 * query/reply pairs and cut into runs, the same way for {@code learn}, {@code evaluate} and {@code watch}.
 */
package dev.predmon.pipeline;
