package dev.predmon;

import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The packages of the main code form layers: no package depends on another that depends back on it, however
 * indirectly. A dependency is an import of, or a qualified name in code for, a class of another package (comments
 * and string literals do not count); a sub-package such as {@code abstraction.file} is a package of its own.
 */
class PackageLayeringTest {

    private static final Path MAIN = Path.of("src/main/java/dev/predmon");
    private static final Pattern REFERENCE = Pattern.compile("\\bdev\\.predmon\\.((?:[a-z][a-z0-9]*\\.)*)(?:[A-Z*])");

    /** Package (relative to {@code dev.predmon}, the root as {@code ""}) to the packages its code uses. */
    static Map<String, Set<String>> dependencies() throws IOException {
        Map<String, Set<String>> graph = new TreeMap<>();
        List<Path> sources;
        try (Stream<Path> files = Files.walk(MAIN)) {
            sources = files.filter(f -> f.toString().endsWith(".java")).sorted().toList();
        }
        for (Path source : sources) {
            String from = MAIN.relativize(source.getParent()).toString().replace('/', '.');
            Set<String> uses = graph.computeIfAbsent(from, k -> new TreeSet<>());
            Matcher m = REFERENCE.matcher(code(Files.readString(source, StandardCharsets.UTF_8)));
            while (m.find()) {
                String to = m.group(1).isEmpty() ? "" : m.group(1).substring(0, m.group(1).length() - 1);
                if (!to.equals(from)) {
                    uses.add(to);
                }
            }
        }
        return graph;
    }

    /** Java text without comments and without the contents of string and character literals. */
    static String code(String text) {
        StringBuilder b = new StringBuilder(text.length());
        int i = 0;
        while (i < text.length()) {
            char c = text.charAt(i);
            if (text.startsWith("//", i)) {
                i = text.indexOf('\n', i) < 0 ? text.length() : text.indexOf('\n', i);
            } else if (text.startsWith("/*", i)) {
                i = text.indexOf("*/", i + 2) < 0 ? text.length() : text.indexOf("*/", i + 2) + 2;
                b.append(' ');
            } else if (text.startsWith("\"\"\"", i)) {
                i = text.indexOf("\"\"\"", i + 3) < 0 ? text.length() : text.indexOf("\"\"\"", i + 3) + 3;
                b.append("\"\"");
            } else if (c == '"' || c == '\'') {
                int j = i + 1;
                while (j < text.length() && text.charAt(j) != c) {
                    j += text.charAt(j) == '\\' ? 2 : 1;
                }
                i = j + 1;
                b.append(c).append(c);
            } else {
                b.append(c);
                i++;
            }
        }
        return b.toString();
    }

    /** A cycle of packages, as {@code a -> b -> a}, or null if there is none. */
    static String cycle(Map<String, Set<String>> graph) {
        Map<String, Integer> state = new TreeMap<>(); // absent: unvisited, 1: on the path, 2: done
        for (String start : graph.keySet()) {
            List<String> path = new ArrayList<>();
            String found = visit(start, graph, state, path);
            if (found != null) {
                return found;
            }
        }
        return null;
    }

    private static String visit(String p, Map<String, Set<String>> graph, Map<String, Integer> state,
                                List<String> path) {
        Integer s = state.get(p);
        if (s != null && s == 2) {
            return null;
        }
        if (s != null) {
            List<String> loop = new ArrayList<>(path.subList(path.indexOf(p), path.size()));
            loop.add(p);
            return String.join(" -> ", loop.stream().map(x -> x.isEmpty() ? "(root)" : x).toList());
        }
        state.put(p, 1);
        path.add(p);
        for (String q : graph.getOrDefault(p, Set.of())) {
            String found = visit(q, graph, state, path);
            if (found != null) {
                return found;
            }
        }
        path.remove(path.size() - 1);
        state.put(p, 2);
        return null;
    }

    @Test
    void packagesHaveNoCycle() throws IOException {
        Map<String, Set<String>> graph = dependencies();
        assertTrue(graph.size() > 10, "found the main packages: " + graph.keySet());
        assertEquals(null, cycle(graph), "a cycle of package dependencies");
    }

    @Test
    void theAbstractionKnowsNeitherItsFileFormatNorTheMealyEncoding() throws IOException {
        Map<String, Set<String>> graph = dependencies();
        // What a record means is below both: the file format builds an abstraction, the Mealy encoding reads one.
        assertFalse(graph.get("abstraction").contains("abstraction.file"), graph.get("abstraction").toString());
        assertFalse(graph.get("abstraction").contains("mealy"), graph.get("abstraction").toString());
        assertFalse(graph.get("mealy").contains("pipeline"), graph.get("mealy").toString());
    }

    @Test
    void propertiesSitOnTheRecordsAndBelowEveryStageThatChecksThem() throws IOException {
        Map<String, Set<String>> graph = dependencies();
        // A property speaks of log records: it knows the parser only, and the abstraction file carries properties.
        assertEquals(Set.of("parse"), graph.get("property"), "what property uses");
        assertTrue(graph.get("abstraction").contains("property"), graph.get("abstraction").toString());
        for (String above : List.of("monitor", "learn", "forecast", "pipeline", "abstraction.file")) {
            assertFalse(graph.get("property").contains(above), above);
        }
    }

    @Test
    void theCheckSeesImportsAndQualifiedNamesOnly() {
        Map<String, Set<String>> graph = new TreeMap<>(Map.of("a", Set.of("b"), "b", Set.of("c"), "c", Set.of("a")));
        assertEquals("a -> b -> c -> a", cycle(graph));
        assertEquals(null, cycle(Map.of("a", Set.of("b"), "b", Set.of())));
        String text = "import dev.predmon.x.Y;\n// dev.predmon.c.D\n/* dev.predmon.e.F */ String s = \"dev.predmon.g.H\";"
                + " dev.predmon.i.j.K.run();";
        Matcher m = REFERENCE.matcher(code(text));
        List<String> found = new ArrayList<>();
        while (m.find()) {
            found.add(m.group(1));
        }
        assertEquals(List.of("x.", "i.j."), found);
    }
}
