/**
 * Compaction (the thesis's Algorithm 5): pairs each reply with its command and keeps a query/reply pair only when
 * the query's answer changed.
 */
package dev.predmon.compact;
