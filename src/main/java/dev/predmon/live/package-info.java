/**
 * The live view of {@code watch} and {@code demo} with {@code --http}: a small bounded HTTP server of predmon's
 * own that serves a page with one tile per watched robot, its status as JSON and its events as Server-Sent Events.
 */
package dev.predmon.live;
