package dev.predmon.cli;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A Java {@link Error} is no exception picocli hands to the error handler: a stack overflow or an exhausted heap
 * printed a stack trace and ended the JVM with exit 1, the code of a warning, on a nominal log. In a real child
 * process (only there does {@code main} decide the exit code) it is one line and exit 4.
 */
class JavaErrorsTest {

    private static final Path LOG = Path.of("sample-logs", "direct", "direct-1.log").toAbsolutePath();

    @TempDir
    Path tmp;

    /** A DOT file of 100,000 nested braces overflows the DOT parser's stack. */
    @Test
    void aStackOverflowIsOneLineAndExit4() throws Exception {
        Path models = ModelFilesCliTest.copyOfShippedModels(tmp);
        Files.writeString(models.resolve("direct.dot"), "digraph g {" + "{".repeat(100_000) + "}".repeat(100_000) + "}\n");
        Child r = Child.run(tmp, "classify", "--models", "models", "--log", LOG.toString());
        assertEquals(ExitCodes.INTERNAL, r.code(), r.err());
        assertEquals(List.of("predmon: internal error: the call stack overflowed (an input nested far too deep?) "
                + "(rerun with --verbose for details)"), r.err().strip().lines().toList());
        assertEquals("", r.out());
    }

    @Test
    void outOfMemoryIsOneLineAndExit4() throws Exception {
        List<String> command = new ArrayList<>(Child.command("classify", "--models",
                Path.of("models").toAbsolutePath().toString(), "--log", LOG.toString()));
        command.add(1, "-Xmx6m");
        Path err = tmp.resolve("err.txt");
        Process p = new ProcessBuilder(command).redirectError(err.toFile())
                .redirectOutput(tmp.resolve("out.txt").toFile()).start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        String text = Files.readString(err);
        assertEquals(ExitCodes.INTERNAL, p.exitValue(), text);
        List<String> lines = text.strip().lines().toList();
        assertEquals(1, lines.size(), text);
        assertTrue(lines.get(0).startsWith("predmon: internal error: out of memory ("), text);
        assertFalse(text.contains("\tat "), "no stack trace: " + text);
    }
}
