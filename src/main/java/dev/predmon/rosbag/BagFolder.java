package dev.predmon.rosbag;

import org.snakeyaml.engine.v2.api.Load;
import org.snakeyaml.engine.v2.api.LoadSettings;
import org.snakeyaml.engine.v2.exceptions.YamlEngineException;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * The data files of a rosbag2 folder, in order: those {@code metadata.yaml} lists ({@code
 * rosbag2_bagfile_information.relative_file_paths}), or, without it (a recording still under way writes it last),
 * every MCAP and sqlite3 file of the folder ordered by the split number rosbag2 appends ({@code name_0.mcap},
 * {@code name_1.mcap}, ..., {@code name_10.mcap}).
 */
final class BagFolder {

    /** How a data file stores its messages, recognised by its first bytes. */
    enum Storage { MCAP, SQLITE3 }

    static final String METADATA = "metadata.yaml";
    private static final byte[] SQLITE = "SQLite format 3\0".getBytes(StandardCharsets.US_ASCII);
    private static final Pattern SPLIT = Pattern.compile("^(.*?)(\\d+)\\.(mcap|db3)$");

    /**
     * @param files    the data files in order
     * @param problems what the folder's metadata says that the folder does not have, one line each
     */
    record Contents(List<Path> files, List<String> problems) {
    }

    private BagFolder() {
    }

    /** The storage of {@code file} by its content, or null if it is neither (or is too short to tell). */
    static Storage storage(Path file) {
        byte[] head = new byte[SQLITE.length];
        int n;
        try (InputStream in = Files.newInputStream(file)) {
            n = in.readNBytes(head, 0, head.length);
        } catch (IOException e) {
            return null;
        }
        if (n >= McapScanner.MAGIC.length && Arrays.equals(head, 0, McapScanner.MAGIC.length,
                McapScanner.MAGIC, 0, McapScanner.MAGIC.length)) {
            return Storage.MCAP;
        }
        return n == SQLITE.length && Arrays.equals(head, SQLITE) ? Storage.SQLITE3 : null;
    }

    /** Whether {@code file} is a data file: recognised by content, or by name while it is still empty. */
    static boolean isDataFile(Path file) {
        if (!Files.isRegularFile(file)) {
            return false;
        }
        String name = file.getFileName().toString();
        return storage(file) != null || name.endsWith(".mcap") || name.endsWith(".db3");
    }

    /** The data files of {@code folder} in order. */
    static Contents contents(Path folder) throws IOException {
        Path metadata = folder.resolve(METADATA);
        List<String> problems = new ArrayList<>();
        if (Files.isRegularFile(metadata)) {
            List<String> listed = listed(metadata, problems);
            if (listed != null && !listed.isEmpty()) {
                List<Path> files = new ArrayList<>();
                for (String name : listed) {
                    Path f = folder.resolve(name);
                    if (Files.isRegularFile(f)) {
                        files.add(f);
                    } else {
                        problems.add(metadata + ": relative_file_paths lists " + name
                                + ", which the folder does not have (a compressed or moved file?): its messages "
                                + "are missing");
                    }
                }
                return new Contents(files, problems);
            }
        }
        try (Stream<Path> all = Files.list(folder)) {
            return new Contents(all.filter(BagFolder::isDataFile).sorted(BY_SPLIT).toList(), problems);
        }
    }

    /** Orders split files by name with their trailing number compared as a number (2 before 10). */
    static final Comparator<Path> BY_SPLIT = Comparator.comparing((Path p) -> split(p, 1))
            .thenComparingInt(p -> number(p).length())
            .thenComparing(BagFolder::number)
            .thenComparing(p -> p.getFileName().toString());

    private static String number(Path p) {
        return split(p, 2).replaceFirst("^0+", "");
    }

    private static String split(Path p, int group) {
        Matcher m = SPLIT.matcher(p.getFileName().toString());
        if (!m.matches()) {
            return group == 1 ? p.getFileName().toString() : "";
        }
        return m.group(group);
    }

    @SuppressWarnings("unchecked")
    private static List<String> listed(Path metadata, List<String> problems) throws IOException {
        String text = Files.readString(metadata, StandardCharsets.UTF_8);
        try {
            Object root = new Load(LoadSettings.builder().build()).loadFromString(text);
            if (root instanceof Map<?, ?> m && m.get("rosbag2_bagfile_information") instanceof Map<?, ?> info
                    && info.get("relative_file_paths") instanceof List<?> paths) {
                List<String> out = new ArrayList<>();
                for (Object o : paths) {
                    out.add(String.valueOf(o));
                }
                return out;
            }
            problems.add(metadata + ": expected rosbag2_bagfile_information.relative_file_paths, found none: the "
                    + "folder's data files are read in name order");
            return null;
        } catch (YamlEngineException e) {
            problems.add(metadata + ": expected YAML, " + e.getMessage().replaceAll("\\s+", " ")
                    + ": the folder's data files are read in name order");
            return null;
        }
    }
}
