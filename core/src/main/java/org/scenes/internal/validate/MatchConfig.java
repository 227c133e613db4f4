package org.scenes.internal.validate;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Supplier;
import org.scenes.api.ActionSelector;
import org.scenes.api.ActionWeights;
import org.scenes.api.ObjectWeights;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginKind;
import org.scenes.api.PluginRegistry;
import org.scenes.api.SceneMetric;
import org.scenes.api.SceneTransform;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.protocol.ViewWidth;
import org.scenes.internal.target.Replay;

/**
 * Everything that decides how scenes are matched and an action chosen: what {@code scenes tune}
 * writes, {@code scenes validate --config} and the agent read.
 *
 * @param metric metric name (spec)
 * @param metricOptions the metric's options
 * @param objectWeights object class weights
 * @param actionWeights action type weights
 * @param k neighbours searched
 * @param selector selector name
 * @param selectorOptions the selector's options ({@code params=average})
 * @param transforms scene transforms applied to every scene sequence, in order
 * @param seed seed of every random choice
 * @param replay how the chosen scene's action is carried out: as recorded, or as its target
 * @param view the view width a playing imitator asks for (with synchronous vision on a synchronous
 *             server), or null to keep the server's
 */
public record MatchConfig(String metric, Map<String, String> metricOptions, ObjectWeights objectWeights,
                          ActionWeights actionWeights, int k, String selector, Map<String, String> selectorOptions,
                          List<String> transforms, long seed, Replay replay, ViewWidth view) {

    public static final MatchConfig DEFAULT = new MatchConfig("ball-goal", Map.of(), ObjectWeights.DEFAULT,
            ActionWeights.DEFAULT, 1, "first-valid", Map.of(), List.of(), 1L, Replay.RAW, null);

    /** A configuration that keeps the server's view. */
    public MatchConfig(String metric, Map<String, String> metricOptions, ObjectWeights objectWeights,
                       ActionWeights actionWeights, int k, String selector, Map<String, String> selectorOptions,
                       List<String> transforms, long seed, Replay replay) {
        this(metric, metricOptions, objectWeights, actionWeights, k, selector, selectorOptions, transforms, seed,
                replay, null);
    }

    /** A configuration replaying recorded commands as they are. */
    public MatchConfig(String metric, Map<String, String> metricOptions, ObjectWeights objectWeights,
                       ActionWeights actionWeights, int k, String selector, Map<String, String> selectorOptions,
                       List<String> transforms, long seed) {
        this(metric, metricOptions, objectWeights, actionWeights, k, selector, selectorOptions, transforms, seed,
                Replay.RAW);
    }

    public MatchConfig {
        metricOptions = Map.copyOf(new TreeMap<>(metricOptions));
        selectorOptions = Map.copyOf(new TreeMap<>(selectorOptions));
        transforms = List.copyOf(transforms);
        replay = replay == null ? Replay.RAW : replay;
        if (k < 1) {
            throw new IllegalArgumentException("k must be at least 1, not " + k);
        }
    }

    public MatchConfig withMetric(String name, Map<String, String> options) {
        return new MatchConfig(name, options, objectWeights, actionWeights, k, selector, selectorOptions, transforms, seed, replay, view);
    }

    /** The same metric with one option set to {@code value}, or left out when {@code value} is null. */
    public MatchConfig withMetricOption(String key, String value) {
        Map<String, String> options = new HashMap<>(metricOptions);
        if (value == null) {
            options.remove(key);
        } else {
            options.put(key, value);
        }
        return withMetric(metric, options);
    }

    public MatchConfig withObjectWeights(ObjectWeights weights) {
        return new MatchConfig(metric, metricOptions, weights, actionWeights, k, selector, selectorOptions, transforms, seed, replay, view);
    }

    public MatchConfig withActionWeights(ActionWeights weights) {
        return new MatchConfig(metric, metricOptions, objectWeights, weights, k, selector, selectorOptions, transforms, seed, replay, view);
    }

    public MatchConfig withK(int newK) {
        return new MatchConfig(metric, metricOptions, objectWeights, actionWeights, newK, selector, selectorOptions, transforms, seed, replay, view);
    }

    public MatchConfig withSelector(String name, Map<String, String> options) {
        return new MatchConfig(metric, metricOptions, objectWeights, actionWeights, k, name, options, transforms, seed, replay, view);
    }

    public MatchConfig withTransforms(List<String> names) {
        return new MatchConfig(metric, metricOptions, objectWeights, actionWeights, k, selector, selectorOptions, names, seed, replay, view);
    }

    public MatchConfig withSeed(long newSeed) {
        return new MatchConfig(metric, metricOptions, objectWeights, actionWeights, k, selector, selectorOptions, transforms, newSeed, replay, view);
    }

    public MatchConfig withReplay(Replay newReplay) {
        return new MatchConfig(metric, metricOptions, objectWeights, actionWeights, k, selector, selectorOptions, transforms, seed,
                newReplay, view);
    }

    public MatchConfig withView(ViewWidth newView) {
        return new MatchConfig(metric, metricOptions, objectWeights, actionWeights, k, selector, selectorOptions, transforms, seed,
                replay, newView);
    }

    private PluginConfig base() {
        return new PluginConfig(objectWeights, actionWeights, Map.of(), seed, "");
    }

    /** Fails early, naming the plugin or option, when the registry cannot build this configuration. */
    public void check(PluginRegistry registry) {
        registry.check(PluginKind.METRIC, metric, base().withOptions(metricOptions));
        registry.check(PluginKind.SELECTOR, selector, base().withOptions(selectorOptions));
        for (String transform : transforms) {
            registry.check(PluginKind.TRANSFORM, transform, base());
        }
        metricFactory(registry).get();
        selectorFactory(registry).get();
    }

    public Supplier<SceneMetric> metricFactory(PluginRegistry registry) {
        PluginConfig config = base().withOptions(metricOptions);
        return () -> registry.metric(metric, config);
    }

    public Supplier<ActionSelector> selectorFactory(PluginRegistry registry) {
        PluginConfig config = base().withOptions(selectorOptions);
        return () -> registry.selector(selector, config);
    }

    /** The recognizer of this configuration on a knowledge base (with the transforms' query image, if any). */
    public Recognizer recognizer(KnowledgeBase knowledge, PluginRegistry registry, int neighbours) {
        return new Recognizer(knowledge, metricFactory(registry), neighbours,
                SceneTransform.queryImage(transformFactory(registry).get()));
    }

    /** Fresh transforms for one sequence of scenes. */
    public Supplier<List<SceneTransform>> transformFactory(PluginRegistry registry) {
        PluginConfig config = base();
        return () -> transforms.stream().map(name -> registry.transform(name, config)).toList();
    }

    /** One line for tables: "ball-goal k=1 first-valid". */
    public String describe() {
        StringBuilder text = new StringBuilder(metric);
        metricOptions.forEach((key, value) -> text.append(' ').append(key).append('=').append(value));
        text.append(" w=").append(objectWeights.format());
        if (!transforms.isEmpty()) {
            text.append(" +").append(String.join("+", transforms));
        }
        text.append(" k=").append(k).append(' ').append(selector);
        selectorOptions.forEach((key, value) -> text.append(' ').append(key).append('=').append(value));
        if (replay != Replay.RAW) {
            text.append(" replay=").append(replay.key());
        }
        return text.toString();
    }
}
