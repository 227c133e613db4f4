package org.scenes.internal.experiment;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The numbers one configuration's validation produced, by measure name, in the validator's
 * order ({@code accuracy}, ...).
 */
public record Result(Configuration configuration, Map<String, Double> measures) {
    public Result {
        measures = Collections.unmodifiableMap(new LinkedHashMap<>(measures));
    }

    public double measure(String name) {
        Double value = measures.get(name);
        if (value == null) {
            throw new IllegalArgumentException("no measure '" + name + "'; measures: " + String.join(", ", measures.keySet()));
        }
        return value;
    }
}
