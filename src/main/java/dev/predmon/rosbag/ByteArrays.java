package dev.predmon.rosbag;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/**
 * Which fields of a type are arrays of {@code uint8} or {@code char}: what rosbridge's JSON sends as base64 text
 * rather than a list of numbers (a goal's UUID, an image's data), to be decoded back into the numbers a recording
 * gives. Known for the types predmon bundles.
 */
public final class ByteArrays {

    private static final Set<String> BYTES = Set.of("uint8", "char");

    private ByteArrays() {
    }

    /**
     * The paths of {@code type}'s byte arrays, as field names joined by {@code .} ({@code status_list.goal_info.
     * goal_id.uuid}; a list's elements share their list's path); empty for a type predmon does not bundle.
     */
    public static List<String> paths(String type) {
        List<String> out = new ArrayList<>();
        collect(type, "", out, 0);
        return out;
    }

    private static void collect(String type, String prefix, List<String> out, int depth) {
        MsgDefinitions.Type t = type == null || depth > 16 ? null : BundledTypes.find(normalised(type), false);
        if (t == null) {
            return;
        }
        for (MsgDefinitions.Field f : t.fields()) {
            String path = prefix + f.name();
            if (BYTES.contains(f.type()) && f.shape() != MsgDefinitions.Shape.SINGLE) {
                out.add(path);
            } else if (!MsgDefinitions.PRIMITIVES.contains(f.type())) {
                collect(f.type(), path + ".", out, depth + 1);
            }
        }
    }

    private static String normalised(String type) {
        String[] p = type.split("/", -1);
        return p.length == 2 ? p[0] + "/msg/" + p[1] : type;
    }
}
