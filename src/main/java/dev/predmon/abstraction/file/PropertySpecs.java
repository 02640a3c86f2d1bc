package dev.predmon.abstraction.file;

import com.fasterxml.jackson.databind.JsonNode;
import dev.predmon.abstraction.file.AbstractionValidator.Invalid;
import dev.predmon.property.Absence;
import dev.predmon.property.Bound;
import dev.predmon.property.Condition;
import dev.predmon.property.Deadline;
import dev.predmon.property.Event;
import dev.predmon.property.Precedence;
import dev.predmon.property.Property;
import dev.predmon.property.Response;
import dev.predmon.property.Scope;
import dev.predmon.property.UnderWay;
import dev.predmon.property.ValueReader;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Pattern;

import static dev.predmon.abstraction.file.PropertyParts.event;
import static dev.predmon.abstraction.file.PropertyParts.keys;
import static dev.predmon.abstraction.file.PropertyParts.line;
import static dev.predmon.abstraction.file.PropertyParts.need;
import static dev.predmon.abstraction.file.PropertyParts.number;
import static dev.predmon.abstraction.file.PropertyParts.object;
import static dev.predmon.abstraction.file.PropertyParts.scope;
import static dev.predmon.abstraction.file.PropertyParts.text;
import static dev.predmon.abstraction.file.PropertyParts.value;

/**
 * The {@code properties} list of an abstraction file: read into {@link Property} values with each problem at its JSON
 * pointer (so that the caller names its line). {@link SpecWriter#properties} writes a list in canonical form.
 *
 * <p>Each property has an {@code id} (short and stable: lower-case letters, digits, {@code -} and {@code _}), a
 * {@code name} in words, a {@code kind} and optionally an {@code action}, a {@code description} and a
 * {@code scope} ({@code {"from": event, "until": event}}). By kind: {@code bound} has a {@code value} (a reply:
 * {@code protocol}, {@code command}, optional {@code from} and {@code to}), a {@code floor} and/or a
 * {@code ceiling}, and optionally {@code underWay} (messages that say its action is under way); {@code absence} an {@code event}; {@code response} a {@code trigger} (an event, or a condition:
 * a {@code value} with one of {@code below}, {@code atMost}, {@code above}, {@code atLeast}), a {@code response} event
 * and {@code within} ({@code {"ticks": T}}, {@code {"seconds": T}} or {@code {"occurrences": K, "of": event}}),
 * optionally {@code cancelledBy} (an event) or {@code per} ({@code "client"} or {@code "argument"});
 * {@code precedence} a {@code first} and a {@code then} event. An event is a record matcher ({@code kind},
 * {@code protocol}, {@code command}, {@code from}, {@code to}, {@code argument}, {@code reply}; the last two a string
 * or a list of strings) or a list of them, any of which is the event.
 */
final class PropertySpecs {

    private static final Pattern ID = Pattern.compile("[a-z0-9][a-z0-9_-]{0,39}");
    private static final Set<String> COMMON = Set.of("id", "name", "kind", "action", "description", "scope");
    /** Every kind by the name the file gives it: adding a kind is adding it here. */
    private static final Map<String, Kind> KINDS = Map.of(
            "bound", new Kind(Set.of("value", "floor", "ceiling", "underWay"), PropertySpecs::bound),
            "absence", new Kind(Set.of("event"), (node, at, id, name, action, scope) -> new Absence(id, name, action,
                    scope, event(need(node, at, "event"), at + "/event"))),
            "response", new Kind(Set.of("trigger", "response", "cancelledBy", "within", "per"),
                    PropertySpecs::response),
            "precedence", new Kind(Set.of("first", "then"), (node, at, id, name, action, scope) -> new Precedence(id,
                    name, action, scope, event(need(node, at, "first"), at + "/first"),
                    event(need(node, at, "then"), at + "/then"))));

    /** Reads a property of one kind from its own keys, the common ones read already. */
    @FunctionalInterface
    private interface Reader {
        Property read(JsonNode node, String at, String id, String name, String action, Scope scope) throws Invalid;
    }

    /** A kind of property: the keys of its own, and how to read them. */
    private record Kind(Set<String> keys, Reader reader) {
    }

    private PropertySpecs() {
    }

    /** The properties of the list at {@code /properties}. */
    static List<Property> read(JsonNode list) throws Invalid {
        String at = "/properties";
        if (!list.isArray()) {
            throw new Invalid(at, "expected a list of properties, each an object with id, name and kind");
        }
        Map<String, String> ids = new HashMap<>();
        List<Property> properties = new ArrayList<>();
        for (int i = 0; i < list.size(); i++) {
            Property p = property(list.get(i), at + "/" + i);
            String other = ids.putIfAbsent(p.id(), at + "/" + i);
            if (other != null) {
                throw new Invalid(at + "/" + i + "/id", "id '" + p.id() + "' is also the id of "
                        + LocatedJson.readable(other) + "; each property needs its own");
            }
            properties.add(p);
        }
        return properties;
    }

    private static Property property(JsonNode node, String at) throws Invalid {
        object(node, at, "a property: an object with id, name and kind");
        String kind = text(node, at, "kind", true);
        Kind own = KINDS.get(kind);
        if (own == null) {
            throw new Invalid(at + "/kind", "kind '" + kind + "' is not one of " + new TreeSet<>(KINDS.keySet()));
        }
        Set<String> allowed = new TreeSet<>(COMMON);
        allowed.addAll(own.keys());
        keys(node, at, allowed);
        String id = text(node, at, "id", true);
        if (!ID.matcher(id).matches()) {
            throw new Invalid(at + "/id", "id '" + id + "' must be 1 to 40 of [a-z0-9_-], starting with a letter or"
                    + " digit: it names the property in events, hooks and truth files");
        }
        String name = line(node, at, "name", 200);
        String action = node.has("action") ? line(node, at, "action", AbstractionValidator.MAX_ACTION) : null;
        text(node, at, "description", false);
        Scope scope = node.has("scope") ? scope(node.get("scope"), at + "/scope") : Scope.GLOBAL;
        return own.reader().read(node, at, id, name, action, scope);
    }

    private static Bound bound(JsonNode node, String at, String id, String name, String action, Scope scope)
            throws Invalid {
        ValueReader value = value(need(node, at, "value"), at + "/value");
        Double floor = number(node, at, "floor");
        Double ceiling = number(node, at, "ceiling");
        if (floor == null && ceiling == null) {
            throw new Invalid(at, "a bound needs a 'floor' (the least value that holds) or a 'ceiling' (the greatest)");
        }
        if (floor != null && ceiling != null && floor > ceiling) {
            throw new Invalid(at + "/ceiling", "the ceiling " + ceiling + " is below the floor " + floor);
        }
        return new Bound(id, name, action, scope, value, floor == null ? Double.NEGATIVE_INFINITY : floor,
                ceiling == null ? Double.POSITIVE_INFINITY : ceiling, underWay(node.get("underWay"), at + "/underWay"));
    }

    /** The messages that say a bound's action is under way: each a skill alone, or a command. */
    private static List<UnderWay> underWay(JsonNode list, String at) throws Invalid {
        if (list == null || list.isNull()) {
            return List.of();
        }
        if (!list.isArray()) {
            throw new Invalid(at, "expected a list of messages that say the action is under way");
        }
        List<UnderWay> messages = new ArrayList<>();
        for (int i = 0; i < list.size(); i++) {
            JsonNode m = list.get(i);
            String here = at + "/" + i;
            object(m, here, "{\"skill\": NAME} or {\"command\": NAME}");
            keys(m, here, Set.of("skill", "protocol", "command", "argument"));
            String skill = text(m, here, "skill", false);
            String command = text(m, here, "command", false);
            String protocol = text(m, here, "protocol", false);
            String argument = text(m, here, "argument", false);
            // A skill alone, or a command (with its protocol and argument if need be): never both, never neither.
            if ((skill == null) == (command == null) || (skill != null && (protocol != null || argument != null))) {
                throw new Invalid(here, "expected {\"skill\": NAME} (the tree starts that skill) or {\"command\": NAME}"
                        + " with an optional \"protocol\" and \"argument\" (a component is called so), e.g. "
                        + "{\"protocol\": \"GoTo\", \"command\": \"goTo\", \"argument\": \"charging_station\"}");
            }
            messages.add(new UnderWay(skill, protocol, command, argument));
        }
        return messages;
    }

    private static Response response(JsonNode node, String at, String id, String name, String action, Scope scope)
            throws Invalid {
        JsonNode trigger = need(node, at, "trigger");
        Event event = null;
        Condition condition = null;
        if (trigger.isObject() && trigger.has("value")) {
            condition = condition(trigger, at + "/trigger");
        } else {
            event = event(trigger, at + "/trigger");
        }
        Event response = event(need(node, at, "response"), at + "/response");
        Event cancelledBy = node.has("cancelledBy") ? event(node.get("cancelledBy"), at + "/cancelledBy") : null;
        Response.Per per = per(node, at, event != null, cancelledBy != null);
        return new Response(id, name, action, scope, event, condition, response, cancelledBy,
                deadline(need(node, at, "within"), at + "/within"), per);
    }

    /** A response's {@code per}: what tells the instances of its trigger apart, or null. */
    private static Response.Per per(JsonNode node, String at, boolean triggerEvent, boolean cancelled) throws Invalid {
        String per = text(node, at, "per", false);
        if (per == null) {
            return null;
        }
        for (Response.Per p : Response.Per.values()) {
            if (p.key.equals(per)) {
                if (!triggerEvent || cancelled) {
                    throw new Invalid(at + "/per", "'per' tells the instances of a trigger event apart: it needs a"
                            + " trigger that is an event and no 'cancelledBy'");
                }
                return p;
            }
        }
        throw new Invalid(at + "/per", "expected \"client\" (the client's port) or \"argument\" (the first argument),"
                + " got \"" + per + "\"");
    }

    private static Condition condition(JsonNode node, String at) throws Invalid {
        Set<String> allowed = new TreeSet<>(Set.of("value"));
        for (Condition.Op op : Condition.Op.values()) {
            allowed.add(op.key);
        }
        keys(node, at, allowed);
        Condition.Op op = null;
        for (Condition.Op o : Condition.Op.values()) {
            if (node.has(o.key)) {
                if (op != null) {
                    throw new Invalid(at + "/" + o.key, "a condition compares with one number: '" + op.key
                            + "' or '" + o.key + "', not both");
                }
                op = o;
            }
        }
        if (op == null) {
            throw new Invalid(at, "a condition needs one of 'below', 'atMost', 'above', 'atLeast' (a number)");
        }
        Double number = number(node, at, op.key);
        if (number == null) {
            throw new Invalid(at + "/" + op.key, "expected a finite number");
        }
        return new Condition(value(node.get("value"), at + "/value"), op, number);
    }

    private static Deadline deadline(JsonNode node, String at) throws Invalid {
        object(node, at, "a deadline: {\"ticks\": T}, {\"seconds\": T} or {\"occurrences\": K, \"of\": event}");
        keys(node, at, Set.of("ticks", "seconds", "occurrences", "of"));
        List<Deadline.Unit> given = new ArrayList<>();
        for (Deadline.Unit u : Deadline.Unit.values()) {
            if (node.has(u.key)) {
                given.add(u);
            }
        }
        if (given.size() != 1) {
            throw new Invalid(at, "expected exactly one of 'ticks', 'seconds' or 'occurrences'");
        }
        Deadline.Unit unit = given.get(0);
        Double amount = number(node, at, unit.key);
        if (amount == null || amount < 0) {
            throw new Invalid(at + "/" + unit.key, "expected a number >= 0, got " + amount);
        }
        if (unit == Deadline.Unit.OCCURRENCES) {
            if (amount != Math.rint(amount)) {
                throw new Invalid(at + "/occurrences", "expected a whole number of occurrences, got " + amount);
            }
            return new Deadline(amount, unit, event(need(node, at, "of"), at + "/of"));
        }
        if (node.has("of")) {
            throw new Invalid(at + "/of", "'of' names the event counted by 'occurrences' only");
        }
        return new Deadline(amount, unit, null);
    }

}
