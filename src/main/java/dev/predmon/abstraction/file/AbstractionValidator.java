package dev.predmon.abstraction.file;

import dev.predmon.abstraction.Band;
import dev.predmon.abstraction.Definition;
import dev.predmon.abstraction.file.AbstractionSpec.DropSpec;
import dev.predmon.abstraction.file.AbstractionSpec.RangeSpec;
import dev.predmon.abstraction.file.AbstractionSpec.ReplySpec;
import dev.predmon.abstraction.file.AbstractionSpec.RuleSpec;
import dev.predmon.abstraction.file.AbstractionSpec.SafetySpec;
import dev.predmon.mealy.MealyMapping;
import dev.predmon.parse.RecordKind;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Checks a bound {@link AbstractionSpec} for what Jackson cannot: required keys, symbol syntax, ambiguity
 * (two messages with one symbol, overlapping bands) and gaps between bands. Each failure names the JSON pointer
 * of the offending value so that the caller can give its line and column.
 */
final class AbstractionValidator {

    /** A symbol must be usable as a DOT label and a LearnLib alphabet entry without quoting. */
    static final Pattern SYMBOL = Pattern.compile("[A-Za-z0-9_]+");
    /** Symbols the I/O-automaton-to-Mealy mapping adds itself (thesis Section 4.2, Figure 4.9). */
    static final Set<String> RESERVED = Set.of(MealyMapping.DELTA, MealyMapping.OK);

    /** The longest recommended action: it must fit one line of a tile. */
    static final int MAX_ACTION = 120;

    private static final Pattern PLACEHOLDER = Pattern.compile("\\{[^}]*}");

    /** A validation failure at {@code pointer}. */
    static final class Invalid extends Exception {
        final String pointer;

        Invalid(String pointer, String reason) {
            super(reason);
            this.pointer = pointer;
        }
    }

    private AbstractionValidator() {
    }

    static void validate(AbstractionSpec spec) throws Invalid {
        required(spec.name(), "", "name");
        if (spec.name().isBlank()) {
            throw new Invalid("/name", "name must not be blank");
        }
        validateDrop(spec.drop());
        Map<String, String> locations = spec.locations() == null ? Map.of() : spec.locations();
        validateLocations(locations);
        required(spec.rules(), "", "rules");
        if (spec.rules().isEmpty()) {
            throw new Invalid("/rules", "rules must not be empty");
        }
        Map<String, String> inputOwner = new HashMap<>();
        Map<String, String> outputOwner = new HashMap<>();
        Map<String, String> ruleOwner = new HashMap<>();
        for (int i = 0; i < spec.rules().size(); i++) {
            validateRule(spec.rules().get(i), "/rules/" + i, locations, inputOwner, outputOwner, ruleOwner);
        }
        for (String symbol : inputOwner.keySet()) {
            if (outputOwner.containsKey(symbol)) {
                throw new Invalid(outputOwner.get(symbol), "symbol '" + symbol + "' is also the input symbol of "
                        + LocatedJson.readable(inputOwner.get(symbol)) + "; inputs and outputs must differ");
            }
        }
        validateSafety(spec.safety());
        if (spec.runs() != null && spec.runs().silence() != null
                && (!(spec.runs().silence() >= 0) || Double.isInfinite(spec.runs().silence()))) {
            throw new Invalid("/runs/silence", "silence must be a finite number of seconds >= 0 (0: off), got "
                    + spec.runs().silence());
        }
        if (spec.warning() != null && spec.warning().confirm() != null && spec.warning().confirm() < 0) {
            throw new Invalid("/warning/confirm", "confirm must be at least 0, got " + spec.warning().confirm());
        }
    }

    private static void validateDrop(List<DropSpec> drop) throws Invalid {
        if (drop == null) {
            return;
        }
        for (int i = 0; i < drop.size(); i++) {
            DropSpec d = drop.get(i);
            String at = "/drop/" + i;
            if (d == null || (d.kind() == null && d.from() == null && d.to() == null && d.protocol() == null
                    && d.command() == null)) {
                throw new Invalid(at, "a drop filter needs at least one of kind, from, to, protocol, command");
            }
            if (d.kind() != null) {
                try {
                    RecordKind.valueOf(d.kind().toUpperCase(Locale.ROOT));
                } catch (IllegalArgumentException e) {
                    throw new Invalid(at + "/kind", "kind '" + d.kind() + "' is not one of COMMAND, REPLY, TICK, UNKNOWN");
                }
            }
        }
    }

    private static void validateLocations(Map<String, String> locations) throws Invalid {
        Map<String, String> byAbbreviation = new HashMap<>();
        for (Map.Entry<String, String> e : locations.entrySet()) {
            String at = "/locations/" + LocatedJson.escape(e.getKey());
            if (e.getKey().isBlank()) {
                throw new Invalid(at, "a location name must not be blank");
            }
            if (e.getValue() == null || !SYMBOL.matcher(e.getValue()).matches()) {
                throw new Invalid(at, "abbreviation '" + e.getValue() + "' of location '" + e.getKey()
                        + "' must be non-empty and use only [A-Za-z0-9_]");
            }
            String other = byAbbreviation.putIfAbsent(e.getValue(), e.getKey());
            if (other != null) {
                throw new Invalid(at, "locations '" + other + "' and '" + e.getKey()
                        + "' have the same abbreviation '" + e.getValue() + "'");
            }
        }
    }

    private static void validateRule(RuleSpec rule, String at, Map<String, String> locations,
                                     Map<String, String> inputOwner, Map<String, String> outputOwner,
                                     Map<String, String> ruleOwner) throws Invalid {
        if (rule == null) {
            throw new Invalid(at, "a rule must be an object");
        }
        required(rule.protocol(), at, "protocol");
        required(rule.command(), at, "command");
        required(rule.input(), at, "input");
        required(rule.replies(), at, "replies");
        // A rule is never used when an earlier rule for the same message matches every client, or the same one.
        if (rule.client() != null && rule.client().isBlank()) {
            throw new Invalid(at + "/client", "client must be a port pattern such as '/ArmServiceIsFetchedClient'");
        }
        String message = rule.protocol() + "/" + rule.command();
        String client = rule.client() == null ? "*" : rule.client();
        String previous = ruleOwner.getOrDefault(message + " client *", ruleOwner.get(message + " client " + client));
        if (previous != null) {
            throw new Invalid(at, "a second rule for " + message + (rule.client() == null ? "" : " from client " + client)
                    + " (the first is " + LocatedJson.readable(previous) + ") would never be used");
        }
        ruleOwner.put(message + " client " + client, at);
        for (String symbol : expand(rule.input(), at + "/input", locations)) {
            String owner = inputOwner.putIfAbsent(symbol, at);
            if (owner != null && !owner.equals(at)) {
                throw new Invalid(at + "/input", "input symbol '" + symbol + "' is already given by "
                        + LocatedJson.readable(owner) + " to a different message");
            }
        }
        if (rule.replies().isEmpty()) {
            throw new Invalid(at + "/replies", "replies must not be empty");
        }
        List<Band> bands = new ArrayList<>();
        Map<Band, Integer> bandIndex = new HashMap<>();
        for (int j = 0; j < rule.replies().size(); j++) {
            ReplySpec reply = rule.replies().get(j);
            String rat = at + "/replies/" + j;
            if (reply == null) {
                throw new Invalid(rat, "a reply must be an object");
            }
            required(reply.symbol(), rat, "symbol");
            int kinds = (reply.any() != null ? 1 : 0) + (reply.values() != null ? 1 : 0) + (reply.range() != null ? 1 : 0);
            if (kinds != 1) {
                throw new Invalid(rat, "a reply needs exactly one of 'any', 'equals', 'range'");
            }
            if (reply.any() != null && !reply.any()) {
                throw new Invalid(rat + "/any", "'any' can only be true");
            }
            if (reply.any() != null && j < rule.replies().size() - 1) {
                throw new Invalid(rat + "/any", "'any' matches every reply, so the replies after it would never be used");
            }
            if (reply.values() != null && (reply.values().isEmpty() || reply.values().contains(null))) {
                throw new Invalid(rat + "/equals", "'equals' needs a non-empty list of strings");
            }
            if (reply.range() != null) {
                Band band = band(reply.range(), rat + "/range");
                bands.add(band);
                bandIndex.put(band, j);
            }
            // Reply entries of one rule may share a symbol (a union of values); across rules they may not.
            for (String symbol : expand(reply.symbol(), rat + "/symbol", locations)) {
                String owner = outputOwner.putIfAbsent(symbol, rat);
                if (owner != null && !owner.startsWith(at + "/")) {
                    throw new Invalid(rat + "/symbol", "output symbol '" + symbol + "' is already given by "
                            + LocatedJson.readable(owner) + " to a different message");
                }
            }
        }
        if (Boolean.TRUE.equals(rule.continuous()) && bands.size() != rule.replies().size()) {
            throw new Invalid(at + "/continuous", "a continuous quantity needs every reply to be a 'range' band");
        }
        if (rule.hysteresis() != null && (!(rule.hysteresis() >= 0) || Double.isInfinite(rule.hysteresis()))) {
            throw new Invalid(at + "/hysteresis", "hysteresis must be a finite number >= 0, got " + rule.hysteresis());
        }
        if (rule.hysteresis() != null && !Boolean.TRUE.equals(rule.continuous())) {
            throw new Invalid(at + "/hysteresis", "hysteresis applies to a 'continuous' rule only");
        }
        if (Boolean.FALSE.equals(rule.carry())) {
            throw new Invalid(at + "/carry", "'carry' can only be true (leave it out otherwise)");
        }
        if (Boolean.FALSE.equals(rule.continuous())) {
            throw new Invalid(at + "/continuous", "'continuous' can only be true (leave it out otherwise)");
        }
        bands.sort(Band.BY_LOWER);
        for (int k = 1; k < bands.size(); k++) {
            Band a = bands.get(k - 1);
            Band b = bands.get(k);
            String where = at + "/replies/" + bandIndex.get(b) + "/range";
            if (a.overlaps(b)) {
                throw new Invalid(where, "bands " + a + " and " + b + " overlap");
            }
            if (a.leavesGapBefore(b)) {
                throw new Invalid(where, "bands " + a + " and " + b + " leave a gap");
            }
        }
    }

    private static Band band(RangeSpec r, String at) throws Invalid {
        if (r.above() != null && r.atLeast() != null) {
            throw new Invalid(at, "give at most one of 'above' and 'atLeast'");
        }
        if (r.below() != null && r.atMost() != null) {
            throw new Invalid(at, "give at most one of 'below' and 'atMost'");
        }
        for (Double d : new Double[]{r.above(), r.atLeast(), r.below(), r.atMost()}) {
            if (d != null && !Double.isFinite(d)) {
                throw new Invalid(at, "bounds must be finite numbers; leave a side out for no bound");
            }
        }
        if (r.above() == null && r.atLeast() == null && r.below() == null && r.atMost() == null) {
            throw new Invalid(at, "a range needs at least one of 'above', 'atLeast', 'below', 'atMost'");
        }
        Band band = r.band();
        if (band.isEmpty()) {
            throw new Invalid(at, "range " + band + " contains no value");
        }
        return band;
    }

    private static void validateSafety(SafetySpec s) throws Invalid {
        if (s == null) {
            return;
        }
        required(s.name(), "/safety", "name");
        required(s.protocol(), "/safety", "protocol");
        required(s.command(), "/safety", "command");
        required(s.below(), "/safety", "below");
        if (!Double.isFinite(s.below())) {
            throw new Invalid("/safety/below", "'below' must be a finite number");
        }
        String action = s.action();
        // The action is shown to operators on one line of the live view: words, not a blank or a paragraph.
        if (action != null && (action.isBlank() || action.length() > MAX_ACTION
                || action.chars().anyMatch(Character::isISOControl))) {
            throw new Invalid("/safety/action", "'action' must say in one line of at most " + MAX_ACTION
                    + " characters what an operator should do, e.g. \"send the robot to the charging station\"");
        }
        if (s.underWay() == null) {
            return;
        }
        for (int i = 0; i < s.underWay().size(); i++) {
            AbstractionSpec.UnderWaySpec u = s.underWay().get(i);
            String at = "/safety/underWay/" + i;
            // A skill alone, or a command (with its protocol and argument if need be): never both, never neither.
            if (u == null || (u.skill() == null) == (u.command() == null)
                    || (u.skill() != null && (u.protocol() != null || u.argument() != null))
                    || (u.skill() != null && u.skill().isBlank()) || (u.command() != null && u.command().isBlank())) {
                throw new Invalid(at, "expected {\"skill\": NAME} (the tree starts that skill) or {\"command\": NAME}"
                        + " with an optional \"protocol\" and \"argument\" (a component is called so), e.g. "
                        + "{\"protocol\": \"GoTo\", \"command\": \"goTo\", \"argument\": \"charging_station\"}");
            }
        }
    }

    /**
     * Every symbol {@code template} stands for: one per location if it contains {@code {loc}}, else itself.
     * Each must be a safe, unreserved symbol.
     */
    static List<String> expand(String template, String at, Map<String, String> locations) throws Invalid {
        Matcher m = PLACEHOLDER.matcher(template);
        while (m.find()) {
            if (!m.group().equals(Definition.LOC)) {
                throw new Invalid(at, "unknown placeholder '" + m.group() + "' in '" + template + "'; only {loc} exists");
            }
        }
        List<String> symbols = new ArrayList<>();
        if (template.contains(Definition.LOC)) {
            if (locations.isEmpty()) {
                throw new Invalid(at, "'" + template + "' uses {loc} but no locations are defined");
            }
            locations.values().stream().sorted(Comparator.naturalOrder())
                    .forEach(abbreviation -> symbols.add(template.replace(Definition.LOC, abbreviation)));
        } else {
            symbols.add(template);
        }
        for (String s : symbols) {
            if (!SYMBOL.matcher(s).matches()) {
                throw new Invalid(at, "symbol '" + s + "' may use only letters, digits and '_' (it must be safe in DOT and LearnLib)");
            }
            if (RESERVED.contains(s)) {
                throw new Invalid(at, "symbol '" + s + "' is reserved for the Mealy mapping (Delta/OK)");
            }
        }
        return symbols;
    }

    private static void required(Object value, String at, String key) throws Invalid {
        if (value == null) {
            throw new Invalid(at, "missing required key '" + key + "'");
        }
    }
}
