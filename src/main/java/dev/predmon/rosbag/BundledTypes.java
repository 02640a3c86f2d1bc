package dev.predmon.rosbag;

import dev.predmon.rosbag.MsgDefinitions.DefinitionException;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The {@code .msg} definitions predmon carries for recordings without their own (sqlite3 bags of Humble and
 * older have no {@code message_definitions} table): the types nav2 robots publish and those they use, under
 * {@code dev/predmon/rosbag/msg/<pkg>/<Type>.msg}. A type whose fields changed between distributions has its older
 * form beside it as {@code <Type>.humble.msg}.
 */
final class BundledTypes {

    private static final Map<String, Optional<MsgDefinitions.Type>> CACHE = new ConcurrentHashMap<>();

    private BundledTypes() {
    }

    /** The bundled definition of {@code name} ({@code pkg/msg/Type}), its Humble form if {@code humble} and there is one. */
    static MsgDefinitions.Type find(String name, boolean humble) {
        if (humble) {
            MsgDefinitions.Type older = load(name, ".humble.msg");
            if (older != null) {
                return older;
            }
        }
        return load(name, ".msg");
    }

    /** Whether {@code name} has a Humble form of its own. */
    static boolean hasHumbleForm(String name) {
        return load(name, ".humble.msg") != null;
    }

    private static MsgDefinitions.Type load(String name, String suffix) {
        return CACHE.computeIfAbsent(name + suffix, k -> Optional.ofNullable(read(name, suffix))).orElse(null);
    }

    private static MsgDefinitions.Type read(String name, String suffix) {
        String[] parts = name.split("/", -1);
        if (parts.length != 3 || !parts[1].equals("msg")) {
            return null;
        }
        String resource = "msg/" + parts[0] + "/" + parts[2] + suffix;
        try (InputStream in = BundledTypes.class.getResourceAsStream(resource)) {
            if (in == null) {
                return null;
            }
            return MsgDefinitions.parse(name, new String(in.readAllBytes(), StandardCharsets.UTF_8)).get(name);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (DefinitionException e) {
            throw new IllegalStateException("bundled " + resource + ": " + e.getMessage(), e);
        }
    }

    /** The full {@code ros2msg} text of {@code type} with its dependencies, as a recording embeds it. */
    static String text(String type) {
        return BundledText.of(type);
    }
}
