package dev.predmon.live;

import java.io.IOException;
import java.nio.channels.SocketChannel;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * One client connection of the live view's server: its socket, closed exactly once whichever side ends it first
 * (the client, a timeout, an eviction, the answer), and counted while open.
 */
final class Connection {

    private final SocketChannel channel;
    private final AtomicInteger open;
    private final AtomicBoolean closed = new AtomicBoolean();

    /** @param open the server's count of open connections; this one is counted from now until {@link #close()} */
    Connection(SocketChannel channel, AtomicInteger open) {
        this.channel = channel;
        this.open = open;
        open.incrementAndGet();
    }

    SocketChannel channel() {
        return channel;
    }

    /** Closes the socket, once; later calls do nothing. */
    void close() {
        if (closed.compareAndSet(false, true)) {
            try {
                channel.close();
            } catch (IOException e) {
                // the descriptor is released whatever close reports
            } finally {
                open.decrementAndGet();
            }
        }
    }
}
