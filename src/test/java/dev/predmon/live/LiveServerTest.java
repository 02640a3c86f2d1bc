package dev.predmon.live;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
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
