package dev.predmon.live;

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
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The page's script modules are served from the jar, as scripts, and refer to nothing elsewhere. */
class PageFilesTest {

    @Test
    void theModulesArePartOfThePageAndNothingElse() throws Exception {
        Board board = new Board(List.of(), Optional.empty(), Duration.ofSeconds(10), System::currentTimeMillis);
        HttpClient http = HttpClient.newHttpClient();
        try (LiveServer server = LiveServer.start(HttpAddress.parse("0"), board)) {
            URI url = server.url();
            String page = http.send(HttpRequest.newBuilder(url.resolve("/?view=compact")).build(),
                    HttpResponse.BodyHandlers.ofString()).body();
            assertTrue(page.contains("<script type=\"module\" src=\"/live.js\">"), page);
            for (String module : List.of("/live.js", "/words.js", "/tile.js", "/plot.js")) {
                HttpResponse<String> r = http.send(HttpRequest.newBuilder(url.resolve(module)).build(),
                        HttpResponse.BodyHandlers.ofString());
                assertEquals(200, r.statusCode(), module);
                assertEquals("text/javascript; charset=utf-8", r.headers().firstValue("Content-Type").orElse(""));
                Matcher imports = Pattern.compile("from '([^']+)'").matcher(r.body());
                while (imports.find()) {
                    assertTrue(imports.group(1).matches("\\./[a-z]+\\.js"), module + " imports " + imports.group(1));
                }
            }
        }
    }
}
