package dev.predmon.abstraction;

import dev.predmon.abstraction.Definition.Reply;
import dev.predmon.abstraction.Definition.Rule;
import dev.predmon.parse.LogFormat;
import dev.predmon.parse.LogRecord;
import dev.predmon.property.Bound;
import dev.predmon.property.Property;
import dev.predmon.ros2.Recordings;
import dev.predmon.ros2.TopicRule;

import java.util.ArrayList;
import java.util.Collections;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * The abstraction of the skill-component interface (thesis Tables 4.1/4.2, Section 5.2): what a log record means.
 *
 * <p>It maps each log record to one of three outcomes (see {@link #classify}): dropped on purpose (ticks,
 * BT-to-skill traffic), mapped to an input symbol (a command) or an output symbol (a reply), or unmapped
 * (interface traffic no rule covers, which the caller reports instead of losing). Everything is data: adding a
 * location, changing the battery bands or adding a component means editing the JSON file only
 * ({@code dev.predmon.abstraction.file} reads, checks and writes the files, and holds the built-in ones).
 *
 * <p>Instances are immutable and thread-safe.
 */
public final class Abstraction {

    private final Definition definition;
    private final Map<String, String> locations;
    /** The compiled drop filters and rules: what {@link #classify} decides. */
    private final Rules rules;
    private final Optional<Bound> safety;
    private final Map<String, Double> learnedHysteresis;
    /** Each continuous rule's band symbols, expanded, to the rule's input template. */
    private final Map<String, String> continuousInputOf;
    private final List<String> inputAlphabet;
    private final List<String> outputAlphabet;
    private final String canonicalJson;
    private final String fingerprint;
    /** For each band symbol of a continuous rule: its rule's bands in ascending order. */
    private final Map<String, List<String>> continuousBands;
    /** For each band symbol of a continuous rule with hysteresis: its band and the rule's hysteresis. */
    private final Map<String, Band> bandOf;
    private final Map<String, Double> hysteresisOf;
    /** Each input of a rule with {@code carry: true}, {@code {loc}} replaced, to the answers its rule gives. */
    private final Map<String, Set<String>> carriedAnswers;
    private final LogFormat format;

    /**
     * The abstraction {@code definition} defines, which its caller has validated ({@code abstraction.file} does).
     *
     * @param canonicalJson the definition's file in canonical form, stored beside models
     * @param fingerprint   what tells whether models were learned with this abstraction (see {@link #fingerprint()})
     */
    public Abstraction(Definition definition, String canonicalJson, String fingerprint) {
        this(definition, canonicalJson, fingerprint, Map.of());
    }

    /** @param learned the hysteresis learned per continuous rule input, already in {@code definition} */
    private Abstraction(Definition definition, String canonicalJson, String fingerprint, Map<String, Double> learned) {
        this.definition = definition;
        this.canonicalJson = canonicalJson;
        this.fingerprint = fingerprint;
        this.learnedHysteresis = Map.copyOf(learned);
        this.locations = definition.locations();
        this.rules = new Rules(definition);
        this.format = Recordings.format(definition.topics());
        this.safety = definition.properties().stream().filter(p -> p instanceof Bound b && b.hasFloor())
                .map(p -> (Bound) p).findFirst();
        Set<String> inputs = new TreeSet<>();
        Set<String> outputs = new TreeSet<>();
        for (Rule r : definition.rules()) {
            for (Reply p : r.replies()) {
                outputs.addAll(expand(p.symbol()));
            }
            inputs.addAll(expand(r.input()));
        }
        Map<String, List<String>> ordered = new HashMap<>();
        for (Rule r : definition.rules()) {
            if (r.continuous()) {
                List<String> ascending = r.replies().stream()
                        .sorted(Comparator.comparing(Reply::range, Band.BY_LOWER))
                        .map(Reply::symbol).distinct().toList();
                for (String loc : abbreviations()) {
                    List<String> family = ascending.stream().map(t -> t.replace(Definition.LOC, loc)).toList();
                    family.forEach(band -> ordered.put(band, family));
                }
            }
        }
        this.continuousBands = Map.copyOf(ordered);
        Map<String, String> inputOfBand = new HashMap<>();
        for (Rule r : definition.rules()) {
            if (r.continuous()) {
                r.replies().forEach(p -> expand(p.symbol()).forEach(band -> inputOfBand.put(band, r.input())));
            }
        }
        this.continuousInputOf = Map.copyOf(inputOfBand);
        Map<String, Band> bands = new HashMap<>();
        Map<String, Double> hysteresis = new HashMap<>();
        for (Rule r : definition.rules()) {
            if (r.hysteresis() != null && r.hysteresis() > 0) {
                for (Reply p : r.replies()) {
                    for (String symbol : expand(p.symbol())) {
                        bands.put(symbol, p.range());
                        hysteresis.put(symbol, r.hysteresis());
                    }
                }
            }
        }
        this.bandOf = Map.copyOf(bands);
        this.hysteresisOf = Map.copyOf(hysteresis);
        Map<String, Set<String>> carries = new TreeMap<>();
        for (Rule r : definition.rules()) {
            if (r.carry()) {
                for (String loc : abbreviations()) {
                    String in = r.input().replace(Definition.LOC, loc);
                    Set<String> answers = new TreeSet<>(carries.getOrDefault(in, Set.of()));
                    for (Reply p : r.replies()) {
                        answers.add(p.symbol().replace(Definition.LOC, loc));
                    }
                    carries.put(in, Collections.unmodifiableSet(answers));
                }
            }
        }
        this.carriedAnswers = Collections.unmodifiableMap(carries);
        this.inputAlphabet = List.copyOf(inputs);
        this.outputAlphabet = List.copyOf(outputs);
    }

    /**
     * The output symbols a reply passes through when a query's answer changes from {@code from} to {@code to}:
     * for the bands of a {@code continuous} rule, every band strictly between them, in order, then {@code to}
     * (a battery going from 52% to 41% crossed medium_six before reaching medium_five, whether or not it was
     * read there); otherwise just {@code to}. This keeps traces independent of how often a robot polls.
     */
    public List<String> bandPath(String from, String to) {
        List<String> bands = continuousBands.get(to);
        if (from == null || bands == null || !bands.contains(from)) {
            return List.of(to);
        }
        int i = bands.indexOf(from);
        int j = bands.indexOf(to);
        List<String> path = new ArrayList<>();
        for (int k = i + Integer.signum(j - i); k != j + Integer.signum(j - i); k += Integer.signum(j - i)) {
            path.add(bands.get(k));
        }
        return path.isEmpty() ? List.of(to) : List.copyOf(path);
    }

    /**
     * The band a new reading of a continuous quantity settles in, given the band it was in: for a rule with
     * {@code hysteresis: h}, a reading that left {@code previous} by at most {@code h} stays in {@code previous};
     * otherwise, and for every other rule, {@code next}. A battery sensor hovering at 50% (50.1, 49.9, 50.2)
     * then gives one band, not a flip on every reading that no learned model has seen.
     *
     * @param previous the band the query was last in, or null
     * @param next     the band of the new reading, by the rule's ranges
     * @param value    the new reading
     */
    public String settle(String previous, String next, double value) {
        Double h = hysteresisOf.get(next);
        if (previous == null || h == null || previous.equals(next) || !bandOf.containsKey(previous)) {
            return next;
        }
        return bandOf.get(previous).distance(value) <= h ? previous : next;
    }

    /** Whether some rule with {@code hysteresis} gives {@code symbol}. */
    public boolean hasHysteresis(String symbol) {
        return hysteresisOf.containsKey(symbol);
    }

    /**
     * What a user configures about carrying: each input of a rule with {@code carry: true} ({@code {loc}} replaced),
     * sorted, to every answer its rule can give, sorted. The Mealy symbols made of them are
     * {@code dev.predmon.mealy}'s ({@code CarryEncoder}, {@code MealyAlphabet}).
     */
    public Map<String, Set<String>> carriedAnswers() {
        return carriedAnswers;
    }

    /** The location abbreviations, sorted, or one empty one when there are none (for templates without {@code {loc}}). */
    private List<String> abbreviations() {
        return locations.isEmpty() ? List.of("") : List.copyOf(new TreeSet<>(locations.values()));
    }

    private List<String> expand(String template) {
        if (!template.contains(Definition.LOC)) {
            return List.of(template);
        }
        return locations.values().stream().map(a -> template.replace(Definition.LOC, a)).toList();
    }

    /**
     * Decides whether {@code r} belongs to the interface and, if so, which symbol it is.
     *
     * <p>Ticks, unknown records and records matching a drop filter are {@link Classification.Dropped}. Other
     * records are matched to the rule with their command and protocol (a record without protocol, from the
     * older log format, matches by command alone, first rule in file order). A command gives the rule's input
     * symbol, a reply the symbol of its first matching reply entry. {@code {loc}} is the abbreviation of the
     * location named by the arguments, else by the reply, else by the last segment of the client port.
     */
    public Classification classify(LogRecord r) {
        return rules.classify(r);
    }

    /** Whether some rule maps messages of {@code protocol}: the abstraction knows that component. */
    public boolean mapsProtocol(String protocol) {
        return definition.rules().stream().anyMatch(r -> r.protocol().equals(protocol));
    }

    /** Every input symbol the rules can produce, sorted. */
    public List<String> inputAlphabet() {
        return inputAlphabet;
    }

    /** Every output symbol the rules can produce, sorted. */
    public List<String> outputAlphabet() {
        return outputAlphabet;
    }

    /** The location names this abbreviation knows, each with its abbreviation, sorted by name. */
    public Map<String, String> locations() {
        return new TreeMap<>(locations);
    }

    /**
     * Pairs a faulty model must still match after the last nominal model is eliminated before the predictive
     * warning, unless the user says otherwise: 0 (the thesis's Algorithm 8) unless the file's {@code warning} sets it.
     */
    public int confirm() {
        return definition.confirm();
    }

    /**
     * The input (as the file writes it, e.g. {@code level_i}) of the continuous rule whose reply {@code c} is, or
     * null for any other classification. The learner estimates a sensor's noise from these replies' values
     * ({@link AbstractEvent#value()}).
     */
    public String continuousInput(Classification.Mapped c) {
        AbstractEvent e = c.event();
        return e.direction() == Direction.OUTPUT ? continuousInputOf.get(e.symbol()) : null;
    }

    /**
     * This abstraction with hysteresis learned from training runs ({@code input -> h}) on the continuous rules that
     * do not set their own. It keeps this one's name and fingerprint: it is the same abstraction, tuned to a sensor's
     * noise, and {@code models/index.json} records the values beside the fingerprint. An empty map gives this one.
     */
    public Abstraction withLearnedHysteresis(Map<String, Double> byInput) {
        Map<String, Double> applied = new TreeMap<>();
        List<Rule> tuned = new ArrayList<>();
        for (Rule r : definition.rules()) {
            Double h = byInput.get(r.input());
            if (r.continuous() && r.hysteresis() == null && h != null && h > 0) {
                applied.put(r.input(), h);
                tuned.add(r.withHysteresis(h));
            } else {
                tuned.add(r);
            }
        }
        if (applied.isEmpty()) {
            return this;
        }
        Definition d = definition;
        return new Abstraction(new Definition(d.name(), d.locations(), d.drop(), tuned, d.properties(), d.confirm(),
                d.runs(), d.topics()), canonicalJson, fingerprint, applied);
    }

    /** The hysteresis learned from training runs that this abstraction applies, by rule input; empty if none. */
    public Map<String, Double> learnedHysteresis() {
        return learnedHysteresis;
    }

    /**
     * How logs are read with this abstraction: a YARP monitor log as always, and a ROS 2 recording (recognised by its
     * content) mapped to records by the file's {@code ros2} section ({@link #topicRules()}).
     */
    public LogFormat format() {
        return format;
    }

    /** The rules of the file's {@code ros2} section, in file order; empty when it has none. */
    public List<TopicRule> topicRules() {
        return definition.topics();
    }

    /** Where runs begin in a log that holds several ({@link RunRule#DEFAULT} unless the file's {@code runs} says). */
    public RunRule runs() {
        return definition.runs();
    }

    /**
     * The property the forecast follows and that labels a run violated or not when learning: the first bound
     * property with a floor, if the file defines one (a value falling to a floor is what the forecast predicts).
     */
    public Optional<Bound> safety() {
        return safety;
    }

    /** Every safety property of the file, in file order: what the safety monitor checks on every run. */
    public List<Property> properties() {
        return definition.properties();
    }

    /** The abstraction's name from the file. */
    public String name() {
        return definition.name();
    }

    /** Canonical JSON text of this abstraction (stable key order), stored in models/index.json. */
    public String canonicalJson() {
        return canonicalJson;
    }

    /**
     * SHA-256 hex of {@link #canonicalJson()} without the properties' {@code action}s (advice, which changes no trace)
     * and without the properties other than {@link #safety()} (which change no learned model): tells whether models
     * were learned with this abstraction.
     */
    public String fingerprint() {
        return fingerprint;
    }

    @Override
    public String toString() {
        return "Abstraction[" + definition.name() + ", " + fingerprint.substring(0, 12) + "]";
    }
}
