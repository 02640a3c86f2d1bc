package dev.predmon.cli;

import dev.predmon.support.HandRuns;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * learn never destroys a user's files: it replaces only a model directory it wrote (or an empty one), refuses
 * anything else with exit 3 and one line, touching nothing, and a learn that fails leaves exactly the previous
 * state. Every case with real files in a temporary workspace; the cases a user types literally ({@code --models .},
 * the default {@code models/}) in a real child process started in that workspace.
 */
class LearnModelsDirTest {

    @TempDir
    Path tmp;
    Path workspace;
    Path runs;

    @BeforeEach
    void logs() throws Exception {
        workspace = Files.createDirectories(tmp.resolve("workspace"));
        runs = workspace.resolve("runs");
        CliEndToEndTest.scenario(runs, "recharge", false, HandRuns.recharge().text());
        CliEndToEndTest.scenario(runs, "depleted", true, HandRuns.depleted().text());
    }

    private Cli learn(Path models) {
        return Cli.run("learn", "--logs", runs.toString(), "--models", models.toString());
    }

    /** Every file under {@code dir} with its content: what must not change. */
    private static Map<String, String> snapshot(Path dir) throws IOException {
        Map<String, String> m = new TreeMap<>();
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted().toList()) {
                String rel = dir.relativize(p).toString();
                m.put(rel, Files.isRegularFile(p) ? Files.readString(p, StandardCharsets.ISO_8859_1)
                        : Files.isDirectory(p) ? "<dir " + permissions(p) + ">" : "<other>");
            }
        }
        return m;
    }

    private static String permissions(Path p) throws IOException {
        return PosixFilePermissions.toString(Files.getPosixFilePermissions(p));
    }

    /** Refused: exit 3, one line naming {@code named} and saying {@code what}, and the workspace exactly as before. */
    private void refused(Cli r, Map<String, String> before, Path named, String what) throws IOException {
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.out() + r.err());
        List<String> lines = r.err().strip().lines().toList();
        assertEquals(1, lines.size(), r.err());
        assertTrue(lines.get(0).contains(named.toString()) && lines.get(0).contains(what), r.err());
        assertEquals("", r.out(), "nothing learned before refusing");
        assertEquals(before, snapshot(tmp), "nothing touched");
    }

    @Test
    void aDirectoryWithAUsersFileIsRefusedAndKept() throws Exception {
        Path x = Files.createDirectories(tmp.resolve("x"));
        Files.writeString(x.resolve("thesis.tex"), "\\chapter{Introduction}\n");
        refused(learn(x), snapshot(tmp), x, "thesis.tex");
    }

    @Test
    void anEmptyLookingDirectoryWithHiddenFilesIsRefused() throws Exception {
        Path x = Files.createDirectories(tmp.resolve("x"));
        Files.writeString(x.resolve(".DS_Store"), "finder");
        refused(learn(x), snapshot(tmp), x, ".DS_Store");
    }

    @Test
    void aGazeboModelsDirectoryIsRefused() throws Exception {
        Path models = Files.createDirectories(workspace.resolve("models/my_robot"));
        Files.writeString(models.resolve("model.urdf"), "<robot name=\"my_robot\"/>\n");
        refused(learn(workspace.resolve("models")), snapshot(tmp), workspace.resolve("models"), "my_robot/");
    }

    @Test
    void theLogDirectoryItselfIsRefused() throws Exception {
        refused(learn(runs), snapshot(tmp), runs, "--logs");
    }

    @Test
    void aDirectoryInsideTheLogsIsRefused() throws Exception {
        Path inside = runs.resolve("models");
        refused(learn(inside), snapshot(tmp), inside, "inside the log directory");
    }

    @Test
    void aDirectoryHoldingTheLogsIsRefused() throws Exception {
        refused(learn(workspace), snapshot(tmp), workspace, "holds the log directory");
    }

    /** A model directory learn wrote, with a file the user added: replacing it would delete that file. */
    @Test
    void aModelDirectoryWithAnAddedFileIsRefused() throws Exception {
        Path models = workspace.resolve("models");
        assertEquals(ExitCodes.OK, learn(models).code());
        Files.writeString(models.resolve("depleted.svg"), "<svg/>");
        refused(learn(models), snapshot(tmp), models, "depleted.svg");
    }

    /**
     * An index edited to name a user's file as a model ({@code "file": "notes.txt"}): only a DOT file can be a
     * model learn wrote, so the directory is not learn's to replace and the file stays.
     */
    @Test
    void aFileTheIndexNamesAsAModelThatIsNoDotFileIsKept() throws Exception {
        Path models = workspace.resolve("models");
        assertEquals(ExitCodes.OK, learn(models).code());
        Path index = models.resolve("index.json");
        Files.writeString(index, Files.readString(index).replace("\"depleted.dot\"", "\"notes.txt\""));
        Files.delete(models.resolve("depleted.dot"));
        Files.writeString(models.resolve("notes.txt"), "my notes\n");
        refused(learn(models), snapshot(tmp), models, "notes.txt");
    }

    @Test
    void aModelDirectoryLearnWroteIsReplacedAndAnEmptyOneIsFilled() throws Exception {
        Path models = workspace.resolve("models");
        assertEquals(ExitCodes.OK, learn(models).code());
        Cli again = learn(models);
        assertEquals(ExitCodes.OK, again.code(), again.err());
        assertTrue(Files.isRegularFile(models.resolve("abstraction.json")));
        Path empty = Files.createDirectories(tmp.resolve("empty"));
        Cli r = learn(empty);
        assertEquals(ExitCodes.OK, r.code(), r.err());
        assertTrue(Files.isRegularFile(empty.resolve("index.json")));
    }

    /** A user's own models.old backup and a directory named like a staging one are not learn's to delete. */
    @Test
    void directoriesBesideTheModelsNamedLikeLearnsAreKept() throws Exception {
        Path models = workspace.resolve("models");
        assertEquals(ExitCodes.OK, learn(models).code());
        Path backup = Files.createDirectories(workspace.resolve("models.old"));
        Files.writeString(backup.resolve("index.json"), "yesterday's models\n");
        Path staging = Files.createDirectories(workspace.resolve("models.new-1-2"));
        Files.writeString(staging.resolve("plan.txt"), "mine\n");
        Files.move(models, workspace.resolve("models.bak"));
        assertEquals(ExitCodes.OK, learn(models).code());
        assertEquals(ExitCodes.OK, learn(models).code());
        assertEquals("yesterday's models\n", Files.readString(backup.resolve("index.json")));
        assertEquals("mine\n", Files.readString(staging.resolve("plan.txt")));
    }

    /** New model directories follow the umask, like any directory the user creates (not 0700). */
    @Test
    void aNewModelDirectoryFollowsTheUmask() throws Exception {
        Path probe = Files.createDirectory(tmp.resolve("probe")); // created with 0777 minus the umask
        Path models = tmp.resolve("models");
        assertEquals(ExitCodes.OK, learn(models).code());
        assertEquals(permissions(probe), permissions(models));
        Set<PosixFilePermission> fileMode = Files.getPosixFilePermissions(Files.createFile(tmp.resolve("probe.txt")));
        assertEquals(fileMode, Files.getPosixFilePermissions(models.resolve("index.json")));
    }

    @Test
    void aReplacedModelDirectoryKeepsItsPermissions() throws Exception {
        Path models = tmp.resolve("models");
        assertEquals(ExitCodes.OK, learn(models).code());
        Files.setPosixFilePermissions(models, PosixFilePermissions.fromString("rwxr-x---"));
        assertEquals(ExitCodes.OK, learn(models).code());
        assertEquals("rwxr-x---", permissions(models));
    }

    /** {@code cd workspace; predmon learn --logs runs --models .}: the current directory is not replaced. */
    @Test
    void modelsDotInARealProcessIsRefused() throws Exception {
        Map<String, String> before = snapshot(tmp);
        Child r = Child.run(workspace, "learn", "--logs", "runs", "--models", ".");
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.err());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertEquals(before, snapshot(tmp));
    }

    /** {@code cd workspace; predmon learn --logs runs} where {@code models/} is someone else's. */
    @Test
    void theDefaultModelsDirectoryOfAnotherToolInARealProcessIsRefused() throws Exception {
        Path gazebo = Files.createDirectories(workspace.resolve("models/my_robot"));
        Files.writeString(gazebo.resolve("model.urdf"), "<robot name=\"my_robot\"/>\n");
        Map<String, String> before = snapshot(tmp);
        Child r = Child.run(workspace, "learn", "--logs", "runs");
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.err());
        assertTrue(r.err().strip().lines().count() == 1 && r.err().contains("my_robot/"), r.err());
        assertEquals(before, snapshot(tmp));
    }

    /**
     * A model directory the user cannot write: learn is refused before it changes anything (today it installed
     * the new models, reported a failure and left models.old behind, and failed again on every later run), and
     * it works again once the directory is writable. As root the child drops the capability that ignores
     * permissions.
     */
    @Test
    void aReadOnlyModelDirectoryIsRefusedBeforeAnythingChanges() throws Exception {
        Path models = workspace.resolve("models");
        assertEquals(ExitCodes.OK, learn(models).code());
        CliEndToEndTest.scenario(runs, "direct", false, HandRuns.recharge().text()); // the next learn differs
        Files.setPosixFilePermissions(models, PosixFilePermissions.fromString("r-xr-xr-x"));
        try {
            Map<String, String> before = snapshot(tmp);
            for (int attempt = 1; attempt <= 2; attempt++) {
                Child r = Child.runBoundByPermissions(workspace, "learn", "--logs", "runs", "--models", "models");
                assertEquals(ExitCodes.BAD_INPUT, r.code(), "attempt " + attempt + ": " + r.err());
                assertTrue(r.err().strip().lines().count() == 1 && r.err().contains("not writable"), r.err());
                assertEquals(before, snapshot(tmp), "attempt " + attempt + ": exactly the previous state");
            }
        } finally {
            Files.setPosixFilePermissions(models, PosixFilePermissions.fromString("rwxr-xr-x"));
        }
        Child r = Child.runBoundByPermissions(workspace, "learn", "--logs", "runs", "--models", "models");
        assertEquals(ExitCodes.OK, r.code(), r.err());
        assertTrue(Files.isRegularFile(models.resolve("direct.dot")));
    }
}
