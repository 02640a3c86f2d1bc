package dev.predmon.live;

import java.io.IOException;
import java.util.Set;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;

/**
 * {@code /events}: Server-Sent Events, one {@code data:} line per monitor event. {@link #publish} never blocks the
 * monitor: each client has a bounded queue, and a client that falls that far behind is disconnected (its browser
 * reconnects by itself and reloads {@code /status}). Each connected client holds one of the server's threads, so
 * their number is capped.
 */
final class EventStream implements AutoCloseable {

    static final int MAX_CLIENTS = 16;
    static final int QUEUE = 1024;
    /** A comment line this often keeps proxies from closing the stream and finds clients that went away. */
    static final long KEEPALIVE_MILLIS = 15_000;

    /** Ends a client's stream; compared by identity, so no event can be mistaken for it. */
    @SuppressWarnings("StringOperationCanBeSimplified")
    private static final String CLOSE = new String("close");

    private final Set<BlockingQueue<String>> clients = ConcurrentHashMap.newKeySet();
    private volatile boolean closed;

    /** Sends {@code json} (one line) to every connected client. */
    // clients is a concurrent set: its iteration is weakly consistent and allows removing while iterating.
    @SuppressWarnings("ModifyCollectionInEnhancedForLoop")
    void publish(String json) {
        for (BlockingQueue<String> q : clients) {
            if (!q.offer(json)) {
                clients.remove(q);
                q.clear();
                q.offer(CLOSE);
            }
        }
    }

    int clients() {
        return clients.size();
    }

    /** Serves one client until it goes away or the stream is closed; returns then. */
    // CLOSE is compared by identity on purpose: an event with the same text must not end the stream.
    @SuppressWarnings("ReferenceEquality")
    void serve(Exchange x) throws IOException {
        if (closed || clients.size() >= MAX_CLIENTS) {
            x.send(503, "text/plain; charset=utf-8", "too many event streams open (" + MAX_CLIENTS + ")\n");
            return;
        }
        BlockingQueue<String> queue = new ArrayBlockingQueue<>(QUEUE);
        clients.add(queue);
        try {
            x.answerHeader("Cache-Control", "no-store");
            x.stream(200, "text/event-stream; charset=utf-8");
            x.write("retry: 1000\n\n");
            while (!closed) {
                String next = queue.poll(KEEPALIVE_MILLIS, TimeUnit.MILLISECONDS);
                if (next == CLOSE) {
                    break;
                }
                // Events are single-line JSON; a line break would end the data line, so it is split as SSE says.
                x.write(next == null ? ": keep-alive\n\n" : "data: " + next.replace("\n", "\ndata: ") + "\n\n");
            }
        } catch (IOException gone) {
            // the client went away: nothing to tell anyone
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            clients.remove(queue);
        }
    }

    /** Ends every client's stream. */
    @Override
    public void close() {
        closed = true;
        for (BlockingQueue<String> q : clients) {
            q.clear();
            q.offer(CLOSE);
        }
    }
}
