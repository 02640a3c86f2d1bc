package dev.predmon.files;

import dev.predmon.BadInputException;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

/**
 * Where a command may write its output, checked before it starts its work: a safety tool's report or export must
 * never cost the user a file. An output may not be one of the command's inputs or lie inside an input directory,
 * and may replace only a file of the same kind that predmon wrote, known by how every such file begins (its
 * signature). Everything else is refused with one line naming the file, and nothing is changed.
 */
public final class OutputFiles {

    /**
     * An input of the command: a file or a directory, and the option that named it (for the message).
     *
     * @param path   as given
     * @param option {@code --logs}
     */
    public record Input(Path path, String option) {
    }

    private OutputFiles() {
    }

    /** The absolute path, with the part that exists resolved to its real path (links followed). */
    public static Path resolved(Path p) {
        Path abs = p.toAbsolutePath().normalize();
        Path existing = abs;
        while (existing != null && !Files.exists(existing)) {
            existing = existing.getParent();
        }
        if (existing == null) {
            return abs;
        }
        try {
            return existing.toRealPath().resolve(existing.relativize(abs));
        } catch (IOException e) {
            return abs;
        }
    }

    /**
     * Checks that the directory {@code dir} may receive output files: it is no input and not inside one, it is a
     * directory if it exists, and it can be written or created.
     */
    public static void requireOutputDirectory(Path dir, String option, List<Input> inputs) throws BadInputException {
        requireApartFrom(dir, option, inputs);
        if (Files.exists(dir) && !Files.isDirectory(dir)) {
            throw new BadInputException(dir + ": not a directory; " + option + " names the directory to write to");
        }
        requireWritableDirectory(dir, dir);
    }

    /**
     * Checks that {@code file} may be replaced by a file predmon writes: it is no input and not inside one, and it
     * is new or a regular file that begins with {@code signature} (one predmon wrote), in a directory that can be
     * written or created.
     *
     * @param kind what predmon writes there, in words, for the message ("an evaluate report")
     */
    public static void requireReplaceable(Path file, String option, String signature, String kind, List<Input> inputs)
            throws BadInputException {
        requireApartFrom(file, option, inputs);
        if (Files.exists(file)) {
            if (Files.isDirectory(file)) {
                throw new BadInputException(file + ": is a directory; " + option + " names the file to write");
            }
            if (!Files.isRegularFile(file)) {
                throw new BadInputException(file + ": not a regular file; choose another " + option);
            }
            if (!beginsWith(file, signature)) {
                throw new BadInputException(file + ": exists and is not " + kind + " predmon wrote; predmon replaces "
                        + "only its own: choose another " + option + " or move the file away");
            }
        }
        Path parent = file.toAbsolutePath().getParent();
        requireWritableDirectory(parent == null ? file : parent, file);
    }

    private static void requireApartFrom(Path output, String option, List<Input> inputs) throws BadInputException {
        Path out = resolved(output);
        for (Input in : inputs) {
            Path input = resolved(in.path());
            if (out.equals(input)) {
                throw new BadInputException(output + ": is the input given as " + in.option() + "; choose another "
                        + option);
            }
            if (out.startsWith(input)) {
                throw new BadInputException(output + ": is inside " + in.path() + ", the input given as " + in.option()
                        + "; choose another " + option + " outside it");
            }
        }
    }

    /**
     * Checks that the nearest existing directory at or above {@code dir} can be written, so that {@code what} can be
     * written in {@code dir} (made first if need be).
     */
    public static void requireWritableDirectory(Path dir, Path what) throws BadInputException {
        Path existing = dir.toAbsolutePath();
        while (existing != null && !Files.exists(existing)) {
            existing = existing.getParent();
        }
        if (existing == null || !Files.isDirectory(existing) || !Files.isWritable(existing)) {
            throw new BadInputException((existing == null ? dir : existing) + ": not a writable directory, so "
                    + what + " cannot be written; nothing was changed");
        }
    }

    /** Whether the file's first bytes are exactly {@code signature} in UTF-8. */
    private static boolean beginsWith(Path file, String signature) throws BadInputException {
        byte[] expected = signature.getBytes(StandardCharsets.UTF_8);
        try (InputStream in = Files.newInputStream(file)) {
            return Arrays.equals(in.readNBytes(expected.length), expected);
        } catch (IOException e) {
            throw BadInputException.cannotRead(file, e);
        }
    }
}
