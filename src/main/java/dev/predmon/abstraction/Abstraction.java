package dev.predmon.abstraction;

import dev.predmon.abstraction.AbstractionSpec.ReplySpec;
import dev.predmon.abstraction.AbstractionSpec.RuleSpec;
import dev.predmon.parse.LogRecord;
import dev.predmon.parse.RecordKind;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * The abstraction of the skill-component interface, loaded from JSON (thesis Tables 4.1/4.2, Section 5.2).
 *
 * <p>It maps each log record to one of three outcomes (see {@link #classify}): dropped on purpose (ticks,
 * BT-to-skill traffic), mapped to an input symbol (a command) or an output symbol (a reply), or unmapped
 * (interface traffic no rule covers, which the caller reports instead of losing). Everything is data: adding a
 * location, changing the battery bands or adding a component means editing the JSON file only.
 *
 * <p>The file has the keys {@code name} (required), {@code description}, {@code drop} (filters, where {@code *}
 * matches any characters, on
 * {@code kind}/{@code from}/{@code to}/{@code protocol}/{@code command}), {@code locations} (name to
 * abbreviation, used for {@code {loc}} in symbols), {@code rules} (required: {@code protocol}, {@code command},
 * {@code input}, {@code replies}, optional {@code description}; each reply has a {@code symbol} and exactly one
 * of {@code any: true}, {@code equals: [strings]}, {@code range: {above|atLeast, below|atMost}}) and
 * {@code safety} (see {@link SafetyRule}).
 *
 * <p>Band boundaries of the default: bands are upper-inclusive, {@code (lower, upper]}, like the thesis's
 * notation and the behaviour tree's {@code level > 50} early-warning condition, so exactly 50.0 is already
 * {@code o_level_medium_six} and exactly 45.0 {@code o_level_medium_five}; the exception is
 * {@code o_level_medium_one = [20, 25]}, so that {@code o_level_low = (0, 20)} coincides exactly with the safety
 * monitor's violation {@code level < 20.0}. {@code o_level_zero} is 0 and below. Validation guarantees the
 * bands of one rule neither overlap nor leave gaps.
 *
 * <p>Instances are immutable and thread-safe.
 */
public final class Abstraction {



    private final String name;
    private final Map<String, String> locations;
    /** The compiled drop filters and rules: what {@link #classify} decides. */
    private final Rules rules;
    private final Optional<SafetyRule> safety;
    private final int confirm;
    private final RunRule runs;
    private final AbstractionSpec spec;
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

    private Abstraction(AbstractionSpec spec) {
        this(spec, null, Map.of());
    }

    /**
     * @param fingerprintOf the abstraction whose identity this one keeps (its canonical JSON and fingerprint), or
     *                      null for the spec's own
     * @param learned       the hysteresis learned per continuous rule input, already in {@code spec}
     */
    private Abstraction(AbstractionSpec spec, Abstraction fingerprintOf, Map<String, Double> learned) {
        this.spec = spec;
        this.learnedHysteresis = Map.copyOf(learned);
        this.name = spec.name();
        this.locations = spec.locations() == null ? Map.of() : Map.copyOf(spec.locations());
        this.rules = new Rules(spec);
        Set<String> inputs = new TreeSet<>();
        Set<String> outputs = new TreeSet<>();
        for (RuleSpec r : spec.rules()) {
            for (ReplySpec p : r.replies()) {
                outputs.addAll(expand(p.symbol()));
            }
            inputs.addAll(expand(r.input()));
        }
        Map<String, List<String>> ordered = new HashMap<>();
        for (RuleSpec r : spec.rules()) {
            if (Boolean.TRUE.equals(r.continuous())) {
                List<String> ascending = r.replies().stream()
                        .sorted(java.util.Comparator.comparing(p -> Band.of(p.range()), Band.BY_LOWER))
                        .map(ReplySpec::symbol).distinct().toList();
                for (String loc : abbreviations()) {
                    List<String> family = ascending.stream().map(t -> t.replace(AbstractionValidator.LOC, loc)).toList();
                    family.forEach(band -> ordered.put(band, family));
                }
            }
        }
        this.continuousBands = Map.copyOf(ordered);
        Map<String, String> inputOfBand = new HashMap<>();
        for (RuleSpec r : spec.rules()) {
            if (Boolean.TRUE.equals(r.continuous())) {
                r.replies().forEach(p -> expand(p.symbol()).forEach(band -> inputOfBand.put(band, r.input())));
            }
        }
        this.continuousInputOf = Map.copyOf(inputOfBand);
        Map<String, Band> bands = new HashMap<>();
        Map<String, Double> hysteresis = new HashMap<>();
        for (RuleSpec r : spec.rules()) {
            if (r.hysteresis() != null && r.hysteresis() > 0) {
                for (ReplySpec p : r.replies()) {
                    for (String symbol : expand(p.symbol())) {
                        bands.put(symbol, Band.of(p.range()));
                        hysteresis.put(symbol, r.hysteresis());
                    }
                }
            }
        }
        this.bandOf = Map.copyOf(bands);
        this.hysteresisOf = Map.copyOf(hysteresis);
        Map<String, Set<String>> carries = new TreeMap<>();
        for (RuleSpec r : spec.rules()) {
            if (Boolean.TRUE.equals(r.carry())) {
                for (String loc : abbreviations()) {
                    String in = r.input().replace(AbstractionValidator.LOC, loc);
                    Set<String> answers = new TreeSet<>(carries.getOrDefault(in, Set.of()));
                    for (ReplySpec p : r.replies()) {
                        answers.add(p.symbol().replace(AbstractionValidator.LOC, loc));
                    }
                    carries.put(in, Collections.unmodifiableSet(answers));
                }
            }
        }
        this.carriedAnswers = Collections.unmodifiableMap(carries);
        this.inputAlphabet = List.copyOf(inputs);
        this.outputAlphabet = List.copyOf(outputs);
        this.runs = spec.runs() == null ? RunRule.DEFAULT : new RunRule(
                spec.runs().tickRestart() == null || spec.runs().tickRestart(),
                spec.runs().silence() == null ? RunRule.DEFAULT_SILENCE : spec.runs().silence());
        this.confirm = spec.warning() == null || spec.warning().confirm() == null ? 0 : spec.warning().confirm();
        if (fingerprintOf != null) {
            this.canonicalJson = fingerprintOf.canonicalJson;
            this.fingerprint = fingerprintOf.fingerprint;
        } else {
            this.canonicalJson = SpecWriter.canonical(spec);
            // The recommended action is advice to operators: it changes no trace, so models stay valid when it does.
            this.fingerprint = AbstractionFiles.sha256(spec.safety() == null || spec.safety().action() == null
                    ? canonicalJson : SpecWriter.canonical(spec.withoutAction()));
        }
        this.safety = Optional.ofNullable(spec.safety()).map(s -> new SafetyRule(s.name(), s.protocol(), s.command(),
                s.from() == null ? "" : s.from(), s.to() == null ? "" : s.to(), s.below(),
                s.action() != null ? s.action() : AbstractionFiles.builtinAction(fingerprint)));
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
        if (!template.contains(AbstractionValidator.LOC)) {
            return List.of(template);
        }
        return locations.values().stream().map(a -> template.replace(AbstractionValidator.LOC, a)).toList();
    }

    /**
     * The built-in abstractions by name: {@code thesis}, the default (Tables 4.1/4.2 with the battery bands of
     * Section 5.2, for the thesis's tree), and {@code scope-fetch} (the R1 fetch-and-carry tree whose monitor the
     * public SCOPE recordings show).
     */
    public static final List<String> BUILTIN_NAMES = List.of("thesis", "scope-fetch");

    /** The embedded default: the built-in {@code thesis}. */
    public static Abstraction defaults() {
        return builtin("thesis").orElseThrow();
    }

    /** The built-in abstraction of that name, if there is one. */
    public static Optional<Abstraction> builtin(String name) {
        return AbstractionFiles.builtin(name);
    }

    /** The JSON text of a built-in abstraction, as shipped, for users to start their own from. */
    public static Optional<String> builtinJson(String name) {
        return AbstractionFiles.builtinJson(name);
    }

    /** Loads and validates an abstraction file. */
    public static Abstraction load(Path file) throws AbstractionException {
        return AbstractionFiles.load(file);
    }

    /**
     * Parses and validates abstraction JSON text.
     *
     * @param source names the text in error messages, usually its file
     * @throws AbstractionException one line, {@code source:line:column: reason}, on the first problem
     */
    public static Abstraction fromJson(String source, String json) throws AbstractionException {
        return AbstractionFiles.fromJson(source, json);
    }

    /** The abstraction of a validated spec. */
    static Abstraction of(AbstractionSpec spec) {
        return new Abstraction(spec);
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
        return spec.rules().stream().anyMatch(r -> r.protocol().equals(protocol));
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

    /** The built-in safety monitor's property, if the file defines one. */
    /**
     * Pairs a faulty model must still match after the last nominal model is eliminated before the predictive
     * warning, unless the user says otherwise: 0 (the thesis's Algorithm 8) unless the file's {@code warning} sets it.
     */
    public int confirm() {
        return confirm;
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
        Map<String, Double> applied = new java.util.TreeMap<>();
        List<RuleSpec> rules = new ArrayList<>();
        for (RuleSpec r : spec.rules()) {
            Double h = byInput.get(r.input());
            if (Boolean.TRUE.equals(r.continuous()) && r.hysteresis() == null && h != null && h > 0) {
                applied.put(r.input(), h);
                rules.add(new RuleSpec(r.protocol(), r.command(), r.client(), r.input(), r.description(),
                        r.continuous(), r.carry(), h, r.replies()));
            } else {
                rules.add(r);
            }
        }
        if (applied.isEmpty()) {
            return this;
        }
        AbstractionSpec tuned = new AbstractionSpec(spec.name(), spec.description(), spec.drop(), spec.locations(),
                List.copyOf(rules), spec.safety(), spec.warning(), spec.runs());
        return new Abstraction(tuned, this, applied);
    }

    /** The hysteresis learned from training runs that this abstraction applies, by rule input; empty if none. */
    public Map<String, Double> learnedHysteresis() {
        return learnedHysteresis;
    }

    /** Where runs begin in a log that holds several ({@link RunRule#DEFAULT} unless the file's {@code runs} says). */
    public RunRule runs() {
        return runs;
    }

    public Optional<SafetyRule> safety() {
        return safety;
    }

    /** The abstraction's name from the file. */
    public String name() {
        return name;
    }

    /** Canonical JSON text of this abstraction (stable key order), stored in models/index.json. */
    public String canonicalJson() {
        return canonicalJson;
    }

    /**
     * SHA-256 hex of {@link #canonicalJson()} (without the safety property's {@code action}, which is advice and
     * changes no trace): tells whether models were learned with this abstraction.
     */
    public String fingerprint() {
        return fingerprint;
    }

    @Override
    public String toString() {
        return "Abstraction[" + name + ", " + fingerprint.substring(0, 12) + "]";
    }
}
