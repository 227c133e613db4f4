package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.scenes.agent.imitation.ImitationBrain;
import org.scenes.agent.sim.GameResult;
import org.scenes.agent.sim.GameSetup;
import org.scenes.match.KnowledgeBase;
import org.scenes.match.Recognizer;
import org.scenes.plugin.PluginRegistry;
import org.scenes.validate.MatchConfig;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes play}: imitating players, learnt from scene files, play a game in the embedded simulator. */
@Command(name = "play", mixinStandardHelpOptions = true,
        description = {"Play a game in the embedded simulator with imitating players on the left: each see becomes"
                + " a scene, the nearest stored scenes (--metric, --k) and the selector choose the command."
                + " The right team is a teacher. Each player's log is written like 'scenes simulate' does."})
final class PlayCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @ParentCommand
    ScenesCommand top;

    @Parameters(paramLabel = "SCENES", arity = "1..*", description = "Scene files to learn from (the knowledge base).")
    List<Path> sceneFiles;

    @Mixin
    MatchOptions match;

    @Option(names = "--players", paramLabel = "N", defaultValue = "5",
            description = "Imitating players (1 to 11). Default: ${DEFAULT-VALUE}.")
    int players;

    @Option(names = "--opponent", paramLabel = "TEACHER:N", defaultValue = "krislet:5",
            description = "The right team: teacher and number of players. Default: ${DEFAULT-VALUE}.")
    String opponent;

    @Option(names = "--names", paramLabel = "LEFT,RIGHT", defaultValue = "Imitator,Amber",
            description = "Team names. Default: ${DEFAULT-VALUE}.")
    String names;

    @Option(names = "--cycles", paramLabel = "N", defaultValue = "6000",
            description = "Game length in cycles. Default: ${DEFAULT-VALUE}.")
    int cycles;

    @Option(names = "--out-dir", paramLabel = "DIR", required = true, description = "Where the player logs go.")
    Path outDir;

    @Override
    public Integer call() throws IOException {
        List<MatchConfig> configs = match.configs();
        if (configs.size() != 1) {
            throw new UsageException("play uses one configuration: give one --metric and one --k");
        }
        MatchConfig config = configs.get(0);
        PluginRegistry registry = top.global.registry();
        config.check(registry);
        String[] teamNames = names.split(",", -1);
        if (teamNames.length != 2) {
            throw new UsageException("--names: give two team names, e.g. Imitator,Amber, not '" + names + "'");
        }
        if (cycles < 1) {
            throw new UsageException("--cycles: must be at least 1, not " + cycles);
        }
        GameSetup.Team right = SimulateCommand.team(opponent, teamNames[1].trim());
        long started = System.nanoTime();
        KnowledgeBase knowledge = KnowledgeBase.load(sceneFiles, config.transformFactory(registry));
        Recognizer recognizer = new Recognizer(knowledge, config.metricFactory(registry), config.k());
        GameSetup setup;
        try {
            GameSetup.Team left = new GameSetup.Team(teamNames[0].trim(), players, ImitationBrain.factory(recognizer,
                    config.selectorFactory(registry), config.transformFactory(registry)));
            setup = new GameSetup(left, right, cycles, config.seed(), outDir);
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        PrintWriter out = spec.commandLine().getOut();
        out.printf(Locale.ROOT, "%-14s %d scenes from %d files; %s%n", "Learnt", knowledge.size(), sceneFiles.size(),
                config.describe());
        GameResult result = SimulateCommand.play(setup);
        SimulateCommand.printSummary(out, setup, result, (System.nanoTime() - started) / 1e9);
        return ExitCodes.OK;
    }
}
