package dev.predmon.live;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;

import java.net.InetAddress;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

class LiveServerTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    /** What a raw request gets back, whole: the server closes every connection after its answer. */
    private static String ask(URI url, String request) throws Exception {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), url.getPort())) {
            s.setSoTimeout(10_000);
            s.getOutputStream().write(request.getBytes(StandardCharsets.ISO_8859_1));
            return new String(s.getInputStream().readAllBytes(), StandardCharsets.ISO_8859_1);
        }
    }

    /** HTTP as the page and scripts speak it, and no more: anything else is a short answer, never a hang. */
    @Test
    void headIsGetWithoutItsBodyAndWhatIsNoRequestGets400() throws Exception {
        Board board = new Board(List.of(), Optional.empty(), Duration.ofSeconds(10), System::currentTimeMillis);
        try (LiveServer server = LiveServer.start(HttpAddress.parse("0"), board)) {
            String host = "Host: 127.0.0.1:" + server.url().getPort() + "\r\n";
            String get = ask(server.url(), "GET /status HTTP/1.1\r\n" + host + "\r\n");
            String head = ask(server.url(), "HEAD /status HTTP/1.1\r\n" + host + "\r\n");
            assertTrue(get.startsWith("HTTP/1.1 200 OK\r\n") && get.endsWith("}"), get);
            assertEquals(get.substring(0, get.indexOf("\r\n\r\n") + 4), head, "the same head, no body");
            assertTrue(ask(server.url(), "\u0016\u0003\u0001 binary\r\n\r\n").startsWith("HTTP/1.1 400 "));
            assertTrue(ask(server.url(), "GET /a b c HTTP/1.1\r\n" + host + "\r\n").startsWith("HTTP/1.1 400 "));
            String post = ask(server.url(), "POST /status HTTP/1.1\r\n" + host + "Content-Length: 2000\r\n\r\n"
                    + "x".repeat(2000));
            assertTrue(post.startsWith("HTTP/1.1 405 "), "the answer arrives though the body was not read: " + post);
        }
    }

    /**
     * The loopback check reads the Host header: a second Host header, or a target that names its own host, would
     * get past it (the first Host was taken, and an absolute URI was answered as its path). Both are 400.
     */
    @Test
    void twoHostHeadersAndTargetsWithAHostGet400() throws Exception {
        Board board = new Board(List.of(), Optional.empty(), Duration.ofSeconds(10), System::currentTimeMillis);
        try (LiveServer server = LiveServer.start(HttpAddress.parse("0"), board)) {
            String host = "Host: 127.0.0.1:" + server.url().getPort() + "\r\n";
            for (String request : List.of(
                    "GET /status HTTP/1.1\r\n" + host + "Host: evil.com\r\n\r\n",
                    "GET /status HTTP/1.1\r\nHost: evil.com\r\n" + host + "\r\n",
                    "GET /status HTTP/1.1\r\n" + host + "HOST: 127.0.0.1\r\n\r\n",
                    "GET http://evil.com/status HTTP/1.1\r\n" + host + "\r\n",
                    "GET http://127.0.0.1:" + server.url().getPort() + "/status HTTP/1.1\r\n" + host + "\r\n",
                    "GET //evil.com/status HTTP/1.1\r\n" + host + "\r\n",
                    "GET * HTTP/1.1\r\n" + host + "\r\n")) {
                String answer = ask(server.url(), request);
                assertTrue(answer.startsWith("HTTP/1.1 400 "), request + " got " + answer);
            }
            assertTrue(ask(server.url(), "GET /status?log=a HTTP/1.1\r\n" + host + "\r\n").startsWith("HTTP/1.1 200 "));
        }
    }

    /** A head of blank lines alone is no request: it gets a 400, and the server goes on answering. */
    @Test
    void blankLinesAloneGet400AndTheServerStaysUp() throws Exception {
        Board board = new Board(List.of(), Optional.empty(), Duration.ofSeconds(10), System::currentTimeMillis);
        try (LiveServer server = LiveServer.start(HttpAddress.parse("0"), board)) {
            String host = "Host: 127.0.0.1:" + server.url().getPort() + "\r\n";
            assertTrue(ask(server.url(), "\r\n\r\n").startsWith("HTTP/1.1 400 "));
            assertTrue(ask(server.url(), "\n\n").startsWith("HTTP/1.1 400 "));
            assertTrue(ask(server.url(), "GET /status HTTP/1.1\r\n" + host + "\r\n").startsWith("HTTP/1.1 200 OK\r\n"));
        }
    }

    /** The page carries the state it was served with, and no log name can break out of it. */
    @Test
    void thePageCarriesTheCurrentStatusSafely() throws Exception {
        Board board = new Board(List.of(), Optional.empty(), Duration.ofSeconds(10), System::currentTimeMillis);
        String hostile = "robot</script><script>alert(1)</script>.log";
        board.tile(hostile);
        try (LiveServer server = LiveServer.start(HttpAddress.parse("0"), board)) {
            URI url = server.url();
            String page = HttpClient.newHttpClient().send(HttpRequest.newBuilder(url).build(),
                    HttpResponse.BodyHandlers.ofString()).body();
            assertFalse(page.contains("<script>alert"), page);
            Matcher m = Pattern.compile("<script type=\"application/json\" id=\"initial-status\">(.*?)</script>",
                    Pattern.DOTALL).matcher(page);
            assertTrue(m.find(), page);
            JsonNode status = JSON.readTree(m.group(1));
            assertEquals(hostile, status.get("logs").get(0).get("log").asText());
        }
    }
}
