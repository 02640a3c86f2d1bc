package dev.predmon.live;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.SynchronousQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The live view's HTTP/1.1 server, bounded so that slow or idle clients cannot take it over. One thread reads every
 * connection's request head without blocking; a complete head is handed to a handler thread, which answers and
 * closes the connection.
 * <ul>
 *   <li>A request head must arrive whole within {@value #HEAD_MILLIS} ms and {@value #MAX_HEAD_BYTES} bytes, else
 *       the connection is closed. Until then a connection costs a buffer and a descriptor, not a thread, so 100
 *       clients that send headers without the final blank line delay nobody.</li>
 *   <li>At most {@value #MAX_CONNECTIONS} connections are open; one more closes the oldest connection still sending
 *       its head (the cheapest to lose, and the likeliest to be an attack), or itself if there is none.</li>
 *   <li>At most {@value #MAX_HANDLERS} requests are answered at once (the event streams among them, each held open);
 *       one more gets 503 at once.</li>
 *   <li>Every descriptor is closed exactly once, whoever closes the connection first.</li>
 * </ul>
 * Why not the JDK's {@code com.sun.net.httpserver}: it reads request heads on its handler threads with no time
 * limit, so that as many slow clients as threads blocked every other request, and it kept the descriptors of such
 * connections after the clients closed them (see the pom).
 */
final class HttpListener implements AutoCloseable {

    /** How long a client has to send its request line and headers. */
    static final long HEAD_MILLIS = 5_000;
    static final int MAX_HEAD_BYTES = 8 * 1024;
    static final int MAX_CONNECTIONS = 256;
    static final int MAX_HANDLERS = EventStream.MAX_CLIENTS + 16;
    /** How often the reading thread looks for heads that took too long. */
    private static final long TICK_MILLIS = 200;

    /** Answers one request; the exchange is closed after it returns. */
    interface Handler {
        void handle(Exchange x) throws IOException;
    }

    /** A connection whose request head is being read. */
    private static final class Reading {
        final Connection connection;
        final long deadline;
        final ByteBuffer head = ByteBuffer.allocate(MAX_HEAD_BYTES);

        Reading(Connection connection, long deadline) {
            this.connection = connection;
            this.deadline = deadline;
        }
    }

    private final ServerSocketChannel server;
    private final InetSocketAddress address;
    private final Selector selector;
    /** Set by {@link #start}, before the thread that reads heads starts. */
    private Handler handler;
    private final ThreadPoolExecutor handlers;
    private final Thread reader;
    private final AtomicInteger open = new AtomicInteger();
    /** Connections still sending their head, oldest first. */
    private final Map<SocketChannel, Reading> reading = new LinkedHashMap<>();
    private volatile boolean closed;

    private HttpListener(ServerSocketChannel server, Selector selector) throws IOException {
        this.server = server;
        this.address = (InetSocketAddress) server.getLocalAddress();
        this.selector = selector;
        AtomicInteger n = new AtomicInteger();
        // No queue: a request that finds every handler busy is refused at once rather than left to wait.
        this.handlers = new ThreadPoolExecutor(0, MAX_HANDLERS, 30, TimeUnit.SECONDS, new SynchronousQueue<>(), r -> {
            Thread t = new Thread(r, "predmon-http-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
        this.reader = new Thread(this::readHeads, "predmon-http-heads");
        this.reader.setDaemon(true);
    }

    /**
     * Binds {@code address}; connections wait there until {@link #start}.
     *
     * @throws IOException when the address cannot be bound
     */
    static HttpListener bind(InetSocketAddress address) throws IOException {
        ServerSocketChannel server = ServerSocketChannel.open();
        Selector selector = null;
        try {
            server.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            server.bind(address, 64);
            server.configureBlocking(false);
            selector = Selector.open();
            server.register(selector, SelectionKey.OP_ACCEPT);
        } catch (IOException e) {
            server.close();
            if (selector != null) {
                selector.close();
            }
            throw e;
        }
        return new HttpListener(server, selector);
    }

    /** Answers every request with {@code handler} from now on. */
    void start(Handler handler) {
        this.handler = handler;
        reader.start();
    }

    /** The address listened at (with the port chosen when 0 was asked for). */
    InetSocketAddress address() {
        return address;
    }

    private void readHeads() {
        try {
            while (!closed) {
                selector.select(TICK_MILLIS);
                List<Reading> complete = new ArrayList<>();
                Iterator<SelectionKey> keys = selector.selectedKeys().iterator();
                while (keys.hasNext()) {
                    SelectionKey key = keys.next();
                    keys.remove();
                    if (!key.isValid()) {
                        continue;
                    }
                    if (key.isAcceptable()) {
                        acceptAll();
                    } else if (key.isReadable() && read((Reading) key.attachment())) {
                        key.cancel();
                        complete.add((Reading) key.attachment());
                    }
                }
                complete.forEach(this::dispatch);
                expire(System.nanoTime());
            }
        } catch (IOException | RuntimeException e) {
            if (!closed) {
                throw new IllegalStateException("the live view's server stopped", e);
            }
        } finally {
            reading.values().forEach(r -> r.connection.close());
            reading.clear();
        }
    }

    private void acceptAll() throws IOException {
        for (SocketChannel channel = server.accept(); channel != null; channel = server.accept()) {
            Connection c = new Connection(channel, open);
            if (open.get() > MAX_CONNECTIONS && !evictOldestReading()) {
                c.close();
                continue;
            }
            try {
                channel.configureBlocking(false);
                channel.setOption(StandardSocketOptions.TCP_NODELAY, true);
                Reading r = new Reading(c, System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(HEAD_MILLIS));
                channel.register(selector, SelectionKey.OP_READ, r);
                reading.put(channel, r);
            } catch (IOException e) {
                c.close();
            }
        }
    }

    private boolean evictOldestReading() {
        Iterator<Reading> oldest = reading.values().iterator();
        if (!oldest.hasNext()) {
            return false;
        }
        Reading r = oldest.next();
        oldest.remove();
        r.connection.close();
        return true;
    }

    /** Reads what has arrived; whether the head is complete. A closed, overlong or broken head closes it. */
    private boolean read(Reading r) {
        try {
            int n = r.connection.channel().read(r.head);
            if (n < 0) {
                drop(r);
                return false;
            }
            if (Exchange.headEnd(r.head) >= 0) {
                reading.remove(r.connection.channel());
                return true;
            }
            if (!r.head.hasRemaining()) {
                drop(r); // no blank line in 8 KiB: no head of this server's requests is that long
            }
        } catch (IOException e) {
            drop(r);
        }
        return false;
    }

    private void drop(Reading r) {
        reading.remove(r.connection.channel());
        r.connection.close();
    }

    private void expire(long now) {
        Iterator<Reading> it = reading.values().iterator();
        while (it.hasNext()) {
            Reading r = it.next();
            if (now - r.deadline < 0) {
                return; // oldest first: the rest have later deadlines
            }
            it.remove();
            r.connection.close();
        }
    }

    private void dispatch(Reading r) {
        Exchange x = Exchange.of(r.connection, r.head);
        try {
            handlers.execute(() -> answer(x));
        } catch (RejectedExecutionException busy) {
            // Every handler is taken (event streams, slow readers): say so without a thread, and close.
            x.refuse(503, "the live view is busy; try again\n");
        }
    }

    private void answer(Exchange x) {
        try {
            if (x.malformed()) {
                x.send(400, "text/plain; charset=utf-8", "a request line and headers, as HTTP/1.1 has them\n");
            } else {
                handler.handle(x);
            }
        } catch (IOException gone) {
            // the client went away or stopped reading: nobody is left to tell
        } finally {
            x.close();
        }
    }

    /** Stops listening, closes every connection still sending its head and ends the handlers. */
    @Override
    public void close() {
        closed = true;
        selector.wakeup();
        try {
            reader.join(2_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        try {
            server.close();
            selector.close();
        } catch (IOException e) {
            // closing: nothing more to do with them
        }
        handlers.shutdownNow();
    }
}
