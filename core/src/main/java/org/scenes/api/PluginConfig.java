package org.scenes.api;

import java.util.Map;
import java.util.TreeMap;

/**
 * What a plugin is configured with.
 *
 * @param objectWeights weights of the eight object classes, for metrics
 * @param actionWeights weights of action types, for selectors
 * @param options plugin-specific options ({@code matching=optimal}), checked against the provider's list
 * @param seed seed of every random choice, so runs repeat exactly
 * @param argument text after the colon in {@code name:argument} (e.g. a script path), empty when none
 */
public record PluginConfig(ObjectWeights objectWeights, ActionWeights actionWeights,
                           Map<String, String> options, long seed, String argument) {
    public static final PluginConfig DEFAULT = new PluginConfig(ObjectWeights.DEFAULT, ActionWeights.DEFAULT,
            Map.of(), 1L, "");

    public PluginConfig {
        options = Map.copyOf(new TreeMap<>(options));
        argument = argument == null ? "" : argument;
    }

    public PluginConfig withOptions(Map<String, String> newOptions) {
        return new PluginConfig(objectWeights, actionWeights, newOptions, seed, argument);
    }

    public PluginConfig withArgument(String newArgument) {
        return new PluginConfig(objectWeights, actionWeights, options, seed, newArgument);
    }

    public PluginConfig withObjectWeights(ObjectWeights weights) {
        return new PluginConfig(weights, actionWeights, options, seed, argument);
    }

    public PluginConfig withActionWeights(ActionWeights weights) {
        return new PluginConfig(objectWeights, weights, options, seed, argument);
    }

    public PluginConfig withSeed(long newSeed) {
        return new PluginConfig(objectWeights, actionWeights, options, newSeed, argument);
    }

    public String option(String name, String fallback) {
        return options.getOrDefault(name, fallback);
    }

    public double doubleOption(String name, double fallback) {
        String value = options.get(name);
        if (value == null) {
            return fallback;
        }
        try {
            return Double.parseDouble(value);
        } catch (NumberFormatException e) {
            throw new PluginException("option " + name + "=" + value + " is not a number");
        }
    }
}
