package dev.predmon.model;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import dev.predmon.abstraction.Abstraction;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.TreeSet;
import java.util.regex.Pattern;

/**
 * The one line that says how the abstraction in use differs from the one a model directory was learned with:
 * which one is which (by name, or by fingerprint when the names are equal), where their definitions differ, and
 * how to fix it.
 */
final class AbstractionMismatch {

    /** At most this many differing places are named. */
    private static final int PLACES = 3;
    private static final ObjectMapper JSON = new ObjectMapper();
    /** The places that hold a property's recommended action, in the older (safety) and newer (properties) form. */
    private static final Pattern ADVICE = Pattern.compile("(safety|properties\\[\\d+])\\.action");

    private AbstractionMismatch() {
    }

    /**
     * @param learned    what the index says the models were learned with
     * @param inUse      the abstraction in use
     * @param storedFile the models' own abstraction file, or null when the directory has none (older models)
     */
    static String describe(ModelIndex.AbstractionInfo learned, Abstraction inUse, Path storedFile) {
        String learnedFp = shortFp(learned.fingerprint());
        String inUseFp = shortFp(inUse.fingerprint());
        StringBuilder b = new StringBuilder();
        if (inUse.name().equals(learned.name())) {
            b.append("the models were learned with another version of abstraction '").append(learned.name())
                    .append("' (").append(learnedFp).append("; the one in use is ").append(inUseFp).append(")");
        } else {
            b.append("the models were learned with abstraction '").append(learned.name()).append("' (")
                    .append(learnedFp).append("), not '").append(inUse.name()).append("' (").append(inUseFp)
                    .append(")");
        }
        List<String> places = places(learned.definition(), inUse);
        if (!places.isEmpty()) {
            b.append("; they differ at ").append(String.join(", ", places));
        }
        b.append(storedFile != null
                ? "; omit --abstraction to use the one they were learned with (" + storedFile
                + "), or relearn with 'predmon learn --abstraction FILE'"
                : "; pass the abstraction they were learned with, or relearn with 'predmon learn --abstraction FILE'");
        return b.toString();
    }

    private static List<String> places(JsonNode learned, Abstraction inUse) {
        List<String> out = new ArrayList<>();
        if (learned == null) {
            return out;
        }
        try {
            diff(learned, JSON.readTree(inUse.canonicalJson()), "", out);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("the abstraction's canonical JSON does not parse", e);
        }
        return out;
    }

    /** Appends the paths ({@code locations.charging_station}, {@code rules[2].replies[0]}) where a and b differ. */
    static void diff(JsonNode a, JsonNode b, String path, List<String> out) {
        // A property's recommended action is advice, outside the fingerprint: it is never why models do not fit.
        if (out.size() >= PLACES || (a != null && a.equals(b)) || ADVICE.matcher(path).matches()) {
            return;
        }
        if (a != null && b != null && a.isObject() && b.isObject()) {
            TreeSet<String> names = new TreeSet<>();
            a.fieldNames().forEachRemaining(names::add);
            for (Iterator<String> it = b.fieldNames(); it.hasNext(); ) {
                names.add(it.next());
            }
            for (String n : names) {
                diff(a.get(n), b.get(n), path.isEmpty() ? n : path + "." + n, out);
            }
        } else if (a != null && b != null && a.isArray() && b.isArray()) {
            for (int i = 0; i < Math.max(a.size(), b.size()); i++) {
                diff(a.get(i), b.get(i), path + "[" + i + "]", out);
            }
        } else if (!(isNothing(a) && isNothing(b))) {
            out.add(path.isEmpty() ? "the top level" : path);
        }
    }

    private static boolean isNothing(JsonNode n) {
        return n == null || n.isNull() || n.isMissingNode();
    }

    private static String shortFp(String fp) {
        return fp == null ? "no fingerprint" : fp.substring(0, Math.min(12, fp.length()));
    }
}
