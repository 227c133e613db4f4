package org.scenes.spark;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.scenes.api.ActionWeights;
import org.scenes.api.ObjectWeights;
import org.scenes.internal.validate.MatchConfig;

/**
 * A {@link MatchConfig} as it travels to the executors: the same fields in serializable form,
 * weights as their exact numbers (not their text), so an executor validates exactly the driver's
 * configuration.
 */
record ConfigSpec(String metric, TreeMap<String, String> metricOptions, double[] objectWeights, double[] actionWeights,
                  int k, String selector, TreeMap<String, String> selectorOptions, ArrayList<String> transforms,
                  long seed) implements Serializable {

    static ConfigSpec of(MatchConfig config) {
        return new ConfigSpec(config.metric(), new TreeMap<>(config.metricOptions()), config.objectWeights().toArray(),
                config.actionWeights().weights().clone(), config.k(), config.selector(),
                new TreeMap<>(config.selectorOptions()), new ArrayList<>(config.transforms()), config.seed());
    }

    MatchConfig config() {
        return new MatchConfig(metric, Map.copyOf(metricOptions), ObjectWeights.of(objectWeights.clone()),
                new ActionWeights(actionWeights.clone()), k, selector, Map.copyOf(selectorOptions), List.copyOf(transforms),
                seed);
    }

    /**
     * What the transformed scene sequences (and so the knowledge bases) depend on: nothing when
     * there is no transform, otherwise the transforms and what a transform is configured with.
     */
    static String transformKey(MatchConfig config) {
        if (config.transforms().isEmpty()) {
            return "";
        }
        return String.join("+", config.transforms()) + " w=" + Arrays.toString(config.objectWeights().toArray())
                + " a=" + Arrays.toString(config.actionWeights().weights()) + " seed=" + config.seed();
    }
}
