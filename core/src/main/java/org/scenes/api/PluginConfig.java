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
    /** The default object and action weights, no options, seed 1, no argument. */
    public static final PluginConfig DEFAULT = new PluginConfig(ObjectWeights.DEFAULT, ActionWeights.DEFAULT,
            Map.of(), 1L, "");

    /**
     * Copies the options, sorted; a null argument becomes empty.
     *
     * @param objectWeights weights of the object classes
     * @param actionWeights weights of the action types
     * @param options plugin-specific options
     * @param seed seed of every random choice
     * @param argument text after the colon in {@code name:argument}, or null
     */
    public PluginConfig {
        options = Map.copyOf(new TreeMap<>(options));
        argument = argument == null ? "" : argument;
    }

    /**
     * @param newOptions the options instead of these
     * @return this configuration with them
     */
    public PluginConfig withOptions(Map<String, String> newOptions) {
        return new PluginConfig(objectWeights, actionWeights, newOptions, seed, argument);
    }

    /**
     * @param newArgument the argument instead of this one
     * @return this configuration with it
     */
    public PluginConfig withArgument(String newArgument) {
        return new PluginConfig(objectWeights, actionWeights, options, seed, newArgument);
    }

    /**
     * @param weights the object weights instead of these
     * @return this configuration with them
     */
    public PluginConfig withObjectWeights(ObjectWeights weights) {
        return new PluginConfig(weights, actionWeights, options, seed, argument);
    }

    /**
     * @param weights the action weights instead of these
     * @return this configuration with them
     */
    public PluginConfig withActionWeights(ActionWeights weights) {
        return new PluginConfig(objectWeights, weights, options, seed, argument);
    }

    /**
     * @param newSeed the seed instead of this one
     * @return this configuration with it
     */
    public PluginConfig withSeed(long newSeed) {
        return new PluginConfig(objectWeights, actionWeights, options, newSeed, argument);
    }

    /**
     * @param name an option the provider lists
     * @param fallback the value when the option is not given
     * @return the option's text or the fallback
     */
    public String option(String name, String fallback) {
        return options.getOrDefault(name, fallback);
    }

    /**
     * @param name an option the provider lists
     * @param fallback the value when the option is not given
     * @return the option as a number, or the fallback
     * @throws PluginException when the option is given but is not a number
     */
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
