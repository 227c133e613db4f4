package org.scenes.api;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Objects;

/**
 * One option of a plugin that {@code scenes tune} may search: the option's key (one of the
 * provider's {@link NamedProvider#options()}), the values tried and the scale they are spread on.
 * The random search draws one of the values, each equally likely (a value listed twice is drawn
 * twice as often); a 0 among the values of a {@link Scale#LOG log} dimension means the option is
 * left out. Declaring a dimension is how a plugin's option becomes searchable.
 *
 * @param option the option's key, e.g. {@code distance-weight}
 * @param values the values tried, in the order the search draws from, at least one
 * @param scale how the values are spread between the smallest and the largest
 */
public record TuneDimension(String option, List<Double> values, Scale scale) {
    /** How a dimension's values are spread over its range. */
    public enum Scale {
        /** evenly spaced: counts, cycles, shares */
        LINEAR,
        /** evenly spaced ratios (1, 3, 10, 30...): weights and costs that matter by their order of magnitude */
        LOG
    }

    /**
     * Checks the dimension: an option key, finite values, positive ones on a log scale (or 0, for off).
     *
     * @param option the option's key
     * @param values the values tried
     * @param scale how the values are spread
     */
    public TuneDimension {
        Objects.requireNonNull(option, "option");
        Objects.requireNonNull(scale, "scale");
        values = List.copyOf(values);
        if (values.isEmpty()) {
            throw new IllegalArgumentException("tune dimension " + option + " has no values");
        }
        for (double value : values) {
            if (!Double.isFinite(value) || scale == Scale.LOG && value < 0) {
                throw new IllegalArgumentException("tune dimension " + option + ": " + value
                        + " is not a value of a " + scale.name().toLowerCase(Locale.ROOT) + " scale");
            }
        }
    }

    /**
     * A dimension of weights or costs that matter by their order of magnitude.
     *
     * @param option the option's key
     * @param values the values tried, 0 for off
     * @return the dimension
     */
    public static TuneDimension log(String option, double... values) {
        return new TuneDimension(option, Arrays.stream(values).boxed().toList(), Scale.LOG);
    }

    /**
     * A dimension of evenly spaced values.
     *
     * @param option the option's key
     * @param values the values tried
     * @return the dimension
     */
    public static TuneDimension linear(String option, double... values) {
        return new TuneDimension(option, Arrays.stream(values).boxed().toList(), Scale.LINEAR);
    }

    /** @return the values as an array, in order */
    public double[] valueArray() {
        return values.stream().mapToDouble(Double::doubleValue).toArray();
    }

    /** @return the smallest value tried */
    public double min() {
        return values.stream().mapToDouble(Double::doubleValue).min().orElseThrow();
    }

    /** @return the largest value tried */
    public double max() {
        return values.stream().mapToDouble(Double::doubleValue).max().orElseThrow();
    }
}
