package dev.predmon.cli;

import dev.predmon.live.Board;
import dev.predmon.live.LiveServer;

import java.io.PrintWriter;
import java.util.Locale;

/** The demo's live view: it waits for a browser before the first run and stays up a while after the last. */
final class LiveDemo {

    private LiveDemo() {
    }

    /** Waits until a page is open on {@code board} (its event stream connected), at most {@code seconds}. */
    static void awaitViewer(PrintWriter out, Board board, LiveServer server, double seconds) throws InterruptedException {
        if (seconds <= 0 || board.viewers() > 0) {
            return;
        }
        out.printf(Locale.ROOT, "open %s in a browser: the first run starts when the page is open (at most %.0f s)%n",
                server.url(), seconds);
        out.flush();
        long deadline = System.nanoTime() + (long) (seconds * 1e9);
        while (board.viewers() == 0 && System.nanoTime() < deadline) {
            Thread.sleep(50);
        }
    }

    /** Keeps the page up {@code seconds} after the runs, so that they can still be looked at. */
    static void linger(PrintWriter out, LiveServer server, double seconds) throws InterruptedException {
        if (seconds <= 0) {
            return;
        }
        out.printf(Locale.ROOT, "the live view stays up at %s for %.0f s (Ctrl-C ends it sooner)%n", server.url(), seconds);
        out.flush();
        Thread.sleep((long) (seconds * 1000));
    }
}
