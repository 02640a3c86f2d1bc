/**
 * The one event format: each monitor event of a watched log as the JSON object that {@code watch --json} prints,
 * the live page receives and the hook commands read, made once from the typed event ({@link dev.predmon.event.LogEvent}).
 */
package dev.predmon.event;
