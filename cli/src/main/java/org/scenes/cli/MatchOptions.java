package org.scenes.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.scenes.api.ActionWeights;
import org.scenes.api.ObjectWeights;
import org.scenes.internal.target.Replay;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.options.KeyConverters;
import picocli.CommandLine.Option;

/** How scenes are matched and an action chosen: the options validate, tune and play share. */
final class MatchOptions {
    @Option(names = "--config", paramLabel = "CONFIG.json",
            description = "Matching configuration written by 'scenes tune' (repeatable: one run each); other matching options given override it.")
    List<Path> configFiles = new ArrayList<>();

    @Option(names = "--metric", paramLabel = "NAME", split = ",",
            description = "Metric(s) (see 'scenes plugins'); several give one run each. Default: ball-goal.")
    List<String> metrics;

    @Option(names = "--k", paramLabel = "N", split = ",",
            description = "Neighbours to consider; several give one run each. Default: 1.")
    List<Integer> ks;

    @Option(names = "--selector", paramLabel = "NAME",
            description = "Action selector: first-valid, random, vote, vote-random. Default: first-valid.")
    String selector;

    @Option(names = "--object-weights", paramLabel = "W",
            description = "Weights of ball/goal/flag/line/players/teammates/opponents/unknown, e.g. 1/1/0/0/0/0/0/0 or ball=1,goal=1.")
    String objectWeights;

    @Option(names = "--action-weights", paramLabel = "W",
            description = "Weights of none/dash/kick/turn_neck/turn/catch/move for selectors, e.g. 1/1/3/0/1/1/1 or kick=3.")
    String actionWeights;

    @Option(names = "--option", paramLabel = "KEY=VALUE",
            description = "A metric option (repeatable), e.g. --option space=polar; 'scenes plugins' lists them.")
    Map<String, String> options = new LinkedHashMap<>();

    @Option(names = "--matching", paramLabel = "greedy|optimal",
            description = "Object pairing of the object metrics (same as --option matching=...).")
    String matching;

    @Option(names = "--params", paramLabel = "copy|average",
            description = "Action parameters copied from the chosen neighbour or averaged over those that agree.")
    String params;

    @Option(names = "--selector-option", paramLabel = "KEY=VALUE",
            description = "A selector option (repeatable), e.g. percent=20 for vote-random.")
    Map<String, String> selectorOptions = new LinkedHashMap<>();

    @Option(names = "--transform", paramLabel = "NAME",
            description = "Scene transform applied to train and test scenes (repeatable), e.g. memory.")
    List<String> transforms;

    @Option(names = "--replay", paramLabel = "raw|target", converter = KeyConverters.Replay.class,
            description = "How the chosen scene's actions are carried out: raw sends the recorded commands; target"
                    + " reaches what they achieved in the field (body direction, running direction, ball velocity,"
                    + " gaze) from the player's own world model (scenes converted with --world). Default: raw, or the"
                    + " config's.")
    Replay replay;

    @Option(names = "--seed", paramLabel = "S", description = "Seed of every random choice. Default: 1, or the config's.")
    Long seed;

    /** The configurations to run: the config file (or defaults) with the given options, one per metric and k. */
    List<MatchConfig> configs() {
        List<MatchConfig> configs = new ArrayList<>();
        if (configFiles.isEmpty()) {
            configs.addAll(configs(MatchConfig.DEFAULT));
        }
        for (Path file : configFiles) {
            configs.addAll(configs(ConfigFiles.read(file)));
        }
        return configs;
    }

    private List<MatchConfig> configs(MatchConfig base) {
        try {
            if (objectWeights != null) {
                base = base.withObjectWeights(ObjectWeights.parse(objectWeights));
            }
            if (actionWeights != null) {
                base = base.withActionWeights(ActionWeights.parse(actionWeights));
            }
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        if (selector != null || params != null || !selectorOptions.isEmpty()) {
            Map<String, String> chosen = new LinkedHashMap<>(selector == null ? base.selectorOptions() : Map.of());
            chosen.putAll(selectorOptions);
            if (params != null) {
                chosen.put("params", params);
            }
            base = base.withSelector(selector == null ? base.selector() : selector, chosen);
        }
        if (transforms != null) {
            base = base.withTransforms(transforms);
        }
        if (seed != null) {
            base = base.withSeed(seed);
        }
        if (replay != null) {
            base = base.withReplay(replay);
        }
        List<MatchConfig> configs = new ArrayList<>();
        List<String> metricNames = metrics == null ? List.of(base.metric()) : metrics;
        List<Integer> kValues = ks == null ? List.of(base.k()) : ks;
        for (String metric : metricNames) {
            Map<String, String> metricOptions = new LinkedHashMap<>(metric.equals(base.metric()) ? base.metricOptions() : Map.of());
            metricOptions.putAll(options);
            if (matching != null) {
                metricOptions.put("matching", matching);
            }
            for (int k : kValues) {
                if (k < 1) {
                    throw new UsageException("--k must be at least 1, not " + k);
                }
                configs.add(base.withMetric(metric, metricOptions).withK(k));
            }
        }
        return configs;
    }
}
