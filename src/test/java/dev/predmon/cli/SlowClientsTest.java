package dev.predmon.cli;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The live page against clients that send their request slowly or never finish it (the "slowloris" attack), on a
 * real {@code watch --http} process: 100 connections that send headers without the final blank line leave
 * {@code /status} answering within a second, and every descriptor they took is given back, whether the clients close
 * them or the server's time limit for a request head does.
 */
class SlowClientsTest {

    private static final int SLOW = 100;

    @TempDir
    Path tmp;

    @Test
    @Timeout(90)
    void a100SlowClientsDelayNobodyAndLeaveNoDescriptorBehind() throws Exception {
        Path err = tmp.resolve("err.txt");
        Process watch = new ProcessBuilder(Child.command("watch", "--log", tmp.resolve("robot.log").toString(),
                "--models", Path.of("models").toAbsolutePath().toString(), "--http", "127.0.0.1:0"))
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectError(err.toFile()).start();
        try {
            int port = port(err);
            assertEquals(200, status(port), "answers");
            long before = settled(watch);

            List<Socket> slow = slowClients(port);
            long started = System.nanoTime();
            assertEquals(200, status(port), "answers beside " + SLOW + " slow clients");
            long millis = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - started);
            assertTrue(millis < 1000, "/status took " + millis + " ms beside " + SLOW + " slow clients");
            for (Socket s : slow) {
                s.close();
            }
            awaitDescriptors(watch, before, "after the slow clients closed their connections");

            List<Socket> abandoned = slowClients(port); // they never finish and never close
            awaitDescriptors(watch, before, "after the time limit for a request head");
            for (Socket s : abandoned) {
                assertEquals(-1, read(s), "the server closed the connection");
                s.close();
            }
            assertEquals(200, status(port), "still answers");
        } finally {
            watch.destroy();
            watch.waitFor(20, TimeUnit.SECONDS);
        }
    }

    /** The port {@code watch} announces on stderr. */
    private static int port(Path err) throws Exception {
        Pattern announced = Pattern.compile("live view on http://127\\.0\\.0\\.1:(\\d+)/");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (System.nanoTime() < deadline) {
            Matcher m = announced.matcher(Files.readString(err));
            if (m.find()) {
                return Integer.parseInt(m.group(1));
            }
            Thread.sleep(20);
        }
        throw new AssertionError("no live view announced: " + Files.readString(err));
    }

    /** {@value #SLOW} connections that send a request line and a header, and not the blank line that ends them. */
    private static List<Socket> slowClients(int port) throws IOException {
        List<Socket> sockets = new ArrayList<>();
        for (int i = 0; i < SLOW; i++) {
            Socket s = new Socket(InetAddress.getLoopbackAddress(), port);
            OutputStream out = s.getOutputStream();
            out.write(("GET /status HTTP/1.1\r\nHost: 127.0.0.1:" + port + "\r\n").getBytes(StandardCharsets.US_ASCII));
            out.flush();
            sockets.add(s);
        }
        return sockets;
    }

    /** The status code of {@code GET /status}, read with a 10 s limit. */
    private static int status(int port) throws IOException {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
            s.setSoTimeout(10_000);
            s.getOutputStream().write(("GET /status HTTP/1.1\r\nHost: 127.0.0.1:" + port + "\r\n\r\n")
                    .getBytes(StandardCharsets.US_ASCII));
            String answer = new String(s.getInputStream().readAllBytes(), StandardCharsets.US_ASCII);
            return Integer.parseInt(answer.substring("HTTP/1.1 ".length(), "HTTP/1.1 ".length() + 3));
        }
    }

    private static int read(Socket s) throws IOException {
        s.setSoTimeout(10_000);
        InputStream in = s.getInputStream();
        return in.read();
    }

    /**
     * The process's descriptors once their count has not changed for a second (at most 10 s): the fleet opens its
     * file-change notification (an inotify descriptor and its wake-up pipe) on its own thread as it starts.
     */
    private static long settled(Process p) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        long last = descriptors(p);
        long since = System.nanoTime();
        while (System.nanoTime() < deadline && System.nanoTime() - since < TimeUnit.SECONDS.toNanos(1)) {
            Thread.sleep(100);
            long now = descriptors(p);
            if (now != last) {
                last = now;
                since = System.nanoTime();
            }
        }
        return last;
    }

    private static long descriptors(Process p) throws IOException {
        try (var fds = Files.list(Path.of("/proc", Long.toString(p.pid()), "fd"))) {
            return fds.count();
        }
    }

    /** Waits (up to 15 s, beyond the server's 5 s for a request head) for the process to hold {@code before}. */
    private static void awaitDescriptors(Process p, long before, String when) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(15);
        long now = descriptors(p);
        while (now > before && System.nanoTime() < deadline) {
            Thread.sleep(50);
            now = descriptors(p);
        }
        assertTrue(now <= before, "open descriptors " + when + ": " + now + ", before the slow clients: " + before);
    }
}
