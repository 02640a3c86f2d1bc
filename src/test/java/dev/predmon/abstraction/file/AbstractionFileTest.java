package dev.predmon.abstraction.file;

import dev.predmon.abstraction.Abstraction;
import dev.predmon.abstraction.AbstractionException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;

import static dev.predmon.abstraction.AbstractionTest.command;
import static dev.predmon.abstraction.AbstractionTest.mapped;
import static dev.predmon.abstraction.AbstractionTest.reply;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** User abstraction files: editing JSON only, and one-line errors with position and reason for broken ones. */
class AbstractionFileTest {

    @TempDir
    Path dir;

    private String defaultJson() throws IOException {
        try (var in = Abstraction.class.getResourceAsStream("default-abstraction.json")) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    private Path write(String json) throws IOException {
        Path f = dir.resolve("user.json");
        Files.writeString(f, json);
        return f;
    }

    /** Loads {@code json}, expects failure and checks the message is one line with file, position and reason. */
    private String failure(String json, String position, String reason) throws IOException {
        Path f = write(json);
        AbstractionException e = assertThrows(AbstractionException.class, () -> AbstractionFiles.load(f));
        String m = e.getMessage();
        assertFalse(m.contains("\n"), m);
        // position is "line:column" or "line:" when only the line is pinned down by the test
        String at = position.endsWith(":") ? position + "\\d+" : position;
        assertTrue(m.matches(Pattern.quote(f.toString()) + ":" + at + ": .*"), m);
        assertTrue(m.contains(reason), m);
        return m;
    }

    @Test
    void addingALocationIsOneLineOfJson() throws Exception {
        Abstraction a = AbstractionFiles.load(write(defaultJson().replace("\"kitchen\": \"ki\",",
                "\"kitchen\": \"ki\", \"bedroom\": \"be\",")));
        assertEquals("goTo_be_i", mapped(a, command("/GoToGoToClient/bedroom", "/GoToComponent", "GoTo", "goTo", "bedroom")).symbol());
        assertEquals("o_getStatus_be_suc", mapped(a, reply("/GoToComponent", "/GoToGoToClient/bedroom", "GoTo",
                "getStatus", "bedroom", "2")).symbol());
        assertTrue(a.inputAlphabet().containsAll(List.of("goTo_be_i", "getStatus_be_i", "isAt_be_i", "halt_be_i")));
        assertTrue(a.outputAlphabet().contains("o_isAt_be_true"));
        assertEquals(AbstractionFiles.defaults().name(), a.name());
        assertFalse(a.fingerprint().equals(AbstractionFiles.defaults().fingerprint()));
    }

    @Test
    void defaultsLoadThroughTheSamePathAsFiles() throws Exception {
        Abstraction fromFile = AbstractionFiles.load(write(defaultJson()));
        assertEquals(AbstractionFiles.defaults().canonicalJson(), fromFile.canonicalJson());
    }

    @Test
    void invalidJson() throws IOException {
        failure("{\n  \"name\": \"x\",\n  \"rules\": [ }\n", "3:14", "invalid JSON");
        failure("", "1:1", "invalid JSON: empty file");
        failure("{\"name\": \"a\", \"name\": \"b\"}", "1:", "Duplicate field 'name'");
    }

    @Test
    void unknownKey() throws IOException {
        String m = failure("{\"name\": \"x\",\n \"rules\": [{\"protocol\": \"P\", \"command\": \"c\", \"input\": \"c_i\",\n"
                + "   \"replies\": [{\"any\": true, \"symbol\": \"o_c\", \"colour\": 1}]}]}", "3:", "unknown key 'colour'");
        assertTrue(m.contains("rules[0].replies[0]"), m);
        failure("{\"nmae\": \"x\", \"rules\": []}", "1:2", "unknown key 'nmae'");
    }

    @Test
    void missingRequiredKeys() throws IOException {
        failure("{\"rules\": []}", "1:1", "missing required key 'name'");
        failure("{\"name\": \"x\",\n \"rules\": [{\"protocol\": \"P\", \"command\": \"c\",\n \"replies\": []}]}", "2:12",
                "rules[0]: missing required key 'input'");
        failure("{\"name\": \"x\", \"rules\": [{\"protocol\": \"P\", \"command\": \"c\", \"input\": \"c_i\",\n"
                + " \"replies\": [{\"any\": true}]}]}", "2:14", "missing required key 'symbol'");
    }

    @Test
    void wrongType() throws IOException {
        failure("{\"name\": \"x\", \"rules\": [{\"protocol\": \"P\", \"command\": \"c\", \"input\": \"c_i\",\n"
                + " \"replies\": [{\"range\": {\"above\": \"ten\"}, \"symbol\": \"o\"}]}]}", "2:", "rules[0].replies[0].range.above: expected a number");
    }

    private static String levelRule(String ranges) {
        return "{\"name\": \"x\", \"rules\": [{\"protocol\": \"B\", \"command\": \"level\", \"input\": \"level_i\",\n"
                + " \"replies\": [" + ranges + "]}]}";
    }

    @Test
    void overlappingOrGappedBands() throws IOException {
        failure(levelRule("{\"range\": {\"atMost\": 20}, \"symbol\": \"o_low\"},\n {\"range\": {\"atLeast\": 20}, \"symbol\": \"o_high\"}"),
                "3:", "bands (-inf, 20] and [20, +inf) overlap");
        failure(levelRule("{\"range\": {\"below\": 20}, \"symbol\": \"o_low\"},\n {\"range\": {\"above\": 20}, \"symbol\": \"o_high\"}"),
                "3:", "bands (-inf, 20) and (20, +inf) leave a gap");
        failure(levelRule("{\"range\": {\"above\": 0, \"atMost\": 10}, \"symbol\": \"o_a\"},\n {\"range\": {\"above\": 12}, \"symbol\": \"o_b\"}"),
                "3:", "leave a gap");
        failure(levelRule("{\"range\": {\"above\": 30, \"atMost\": 10}, \"symbol\": \"o_a\"}"), "2:", "contains no value");
        failure(levelRule("{\"range\": {\"above\": 3, \"atLeast\": 3}, \"symbol\": \"o_a\"}"), "2:", "at most one of 'above' and 'atLeast'");
        failure(levelRule("{\"range\": {}, \"symbol\": \"o_a\"}"), "2:", "needs at least one");
        failure(levelRule("{\"any\": true, \"equals\": [\"1\"], \"symbol\": \"o_a\"}"), "2:", "exactly one of");
    }

    @Test
    void sameSymbolForDifferentMessages() throws IOException {
        failure("{\"name\": \"x\", \"rules\": [\n"
                + " {\"protocol\": \"P\", \"command\": \"a\", \"input\": \"a_i\", \"replies\": [{\"any\": true, \"symbol\": \"o_same\"}]},\n"
                + " {\"protocol\": \"P\", \"command\": \"b\", \"input\": \"b_i\", \"replies\": [{\"any\": true, \"symbol\": \"o_same\"}]}]}",
                "3:", "output symbol 'o_same' is already given by rules[0].replies[0]");
        failure("{\"name\": \"x\", \"rules\": [\n"
                + " {\"protocol\": \"P\", \"command\": \"a\", \"input\": \"same_i\", \"replies\": [{\"any\": true, \"symbol\": \"o_a\"}]},\n"
                + " {\"protocol\": \"P\", \"command\": \"b\", \"input\": \"same_i\", \"replies\": [{\"any\": true, \"symbol\": \"o_b\"}]}]}",
                "3:", "input symbol 'same_i' is already given by rules[0]");
        // A template collides with a literal once expanded.
        failure("{\"name\": \"x\", \"locations\": {\"kitchen\": \"ki\"}, \"rules\": [\n"
                + " {\"protocol\": \"P\", \"command\": \"a\", \"input\": \"a_{loc}_i\", \"replies\": [{\"any\": true, \"symbol\": \"o_a\"}]},\n"
                + " {\"protocol\": \"P\", \"command\": \"b\", \"input\": \"a_ki_i\", \"replies\": [{\"any\": true, \"symbol\": \"o_b\"}]}]}",
                "3:", "input symbol 'a_ki_i'");
        failure("{\"name\": \"x\", \"rules\": [\n"
                + " {\"protocol\": \"P\", \"command\": \"a\", \"input\": \"a_i\", \"replies\": [{\"any\": true, \"symbol\": \"o_a\"}]},\n"
                + " {\"protocol\": \"P\", \"command\": \"a\", \"input\": \"b_i\", \"replies\": [{\"any\": true, \"symbol\": \"o_b\"}]}]}",
                "3:2", "a second rule for P/a");
    }

    private static String oneRule(String input, String symbol) {
        return "{\"name\": \"x\", \"rules\": [{\"protocol\": \"P\", \"command\": \"c\", \"input\": \"" + input + "\",\n"
                + " \"replies\": [{\"any\": true, \"symbol\": \"" + symbol + "\"}]}]}";
    }

    @Test
    void unsafeOrReservedSymbols() throws IOException {
        failure(oneRule("go/to_i", "o_c"), "1:", "symbol 'go/to_i' may use only letters, digits and '_'");
        failure(oneRule("c_i", "o c"), "2:", "symbol 'o c' may use only");
        failure(oneRule("c_i", "o_\\\"c"), "2:", "may use only");
        failure(oneRule("Delta", "o_c"), "1:", "reserved");
        failure(oneRule("c_i", "OK"), "2:", "reserved");
        failure(oneRule("c_{where}_i", "o_c"), "1:", "unknown placeholder '{where}'");
    }

    @Test
    void locationProblems() throws IOException {
        failure(oneRule("c_{loc}_i", "o_c"), "1:", "uses {loc} but no locations are defined");
        failure("{\"name\": \"x\", \"locations\": {\"kitchen\": \"k\",\n \"kiosk\": \"k\"}, \"rules\": []}", "2:2",
                "locations 'kitchen' and 'kiosk' have the same abbreviation 'k'");
        failure("{\"name\": \"x\", \"locations\": {\"kitchen\": \"k/i\"}, \"rules\": []}", "1:29", "abbreviation 'k/i'");
    }

    @Test
    void unreadableFile() {
        Path missing = dir.resolve("missing.json");
        AbstractionException e = assertThrows(AbstractionException.class, () -> AbstractionFiles.load(missing));
        assertTrue(e.getMessage().startsWith(missing + ": cannot read"), e.getMessage());
    }
}
