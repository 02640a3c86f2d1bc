package dev.predmon.cli;

import dev.predmon.model.ModelSet;
import dev.predmon.monitor.PredictiveMonitor;
import dev.predmon.monitor.WarningRule;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;

import java.util.Locale;

/** {@code --rule forecast|match}, shared by the commands that raise the predictive warning. */
final class RuleOption {

    @Spec(Spec.Target.MIXEE)
    CommandSpec mixee;

    private WarningRule value;

    @Option(names = "--rule", paramLabel = "forecast|match",
            description = "When to warn. forecast (the default with models learned with a forecast): when the "
                    + "probability of a violation reaches the threshold learned with the models. match: the thesis's "
                    + "Algorithm 8, when every nominal model is eliminated while a faulty one matches.")
    void set(String rule) {
        try {
            value = WarningRule.valueOf(rule.toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new ParameterException(mixee.commandLine(), "--rule must be forecast or match, got '" + rule + "'");
        }
    }

    /** The rule asked for, else the models' default; the forecast rule on models without one is a usage error. */
    WarningRule value(ModelSet models) {
        if (value == WarningRule.FORECAST && models.forecast() == null) {
            throw new ParameterException(mixee.commandLine(), (models.dir() == null ? "the models" : models.dir()
                    .toString()) + " were learned without a forecast: run 'predmon learn' again, or use --rule match");
        }
        return value != null ? value : PredictiveMonitor.defaultRule(models);
    }

    /** The rule asked for, or null for the models' default. */
    WarningRule asked() {
        return value;
    }
}
