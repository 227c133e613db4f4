package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.scenes.agent.imitation.ImitationBrain;
import org.scenes.agent.imitation.ImitationTeam;
import org.scenes.api.PluginRegistry;
import org.scenes.app.Teams;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.simulator.GameResult;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/**
 * {@code scenes play}: imitating players, learnt from scene files, play a game in the embedded
 * simulator, or on a soccer server over UDP with {@code --server}.
 */
@Command(name = "play",
        description = {"Play with imitating players: each see becomes a scene, the nearest stored scenes (--metric,"
                + " --k) and the selector choose the command.",
                "Without --server: a game in the embedded simulator, imitators on the left, a teacher on the right;"
                + " each player's log is written like 'scenes simulate' does.",
                "With --server HOST:PORT: the imitation team plays on that soccer server (rcssserver or any other) over"
                + " UDP, a thread per player, until the referee says time_over or Ctrl-C; 'scenes team --teacher'"
                + " starts a teacher team the same way. Exit 1 when a player found no server, lost it or failed."})
final class PlayCommand implements Callable<Integer> {
    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help message and exit.")
    boolean help;

    @Spec
    CommandSpec spec;

    @ParentCommand
    ScenesCommand top;

    @Parameters(paramLabel = "SCENES", arity = "1..*", description = "Scene files to learn from (the knowledge base).")
    List<Path> sceneFiles;

    @Mixin
    MatchOptions match;

    @Option(names = "--players", paramLabel = "N",
            description = "Imitating players (1 to 11). Default: 5 in the simulator, 11 on a server.")
    Integer players;

    @Option(names = "--guard", description = "Loop guards: no kick with the ball out of reach, another neighbour's"
            + " action when the same one leaves the view unchanged for 5 sees. Off: pure imitation.")
    boolean guard;

    @Mixin
    LiveOptions live;

    @Mixin
    ImitationTeamOptions roles;

    @Option(names = "--opponent", paramLabel = "TEACHER:N", defaultValue = "krislet:5",
            description = "The right team: teacher and number of players. Default: ${DEFAULT-VALUE}.")
    String opponent;

    @Option(names = "--names", paramLabel = "LEFT,RIGHT", defaultValue = "Imitator,Amber",
            description = "Team names. Default: ${DEFAULT-VALUE}.")
    String names;

    @Option(names = "--cycles", paramLabel = "N", defaultValue = "6000",
            description = "Game length in cycles. Default: ${DEFAULT-VALUE}.")
    int cycles;

    @Option(names = "--out-dir", paramLabel = "DIR",
            description = "Where the player logs go (the simulator; required there). On a server: --log-dir.")
    Path outDir;

    @Option(names = "--record", paramLabel = "DIR",
            description = "The simulator: also write the server's game log (.rcg) and command log (.rcl) there.")
    Path recordDir;

    @Override
    public Integer call() throws IOException, InterruptedException {
        List<MatchConfig> configs = match.configs();
        if (configs.size() != 1) {
            throw new UsageException("play uses one configuration: give one --metric and one --k");
        }
        MatchConfig config = configs.get(0);
        PluginRegistry registry = top.global.registry();
        config.check(registry);
        ImitationBrain.Guards guards = guard ? ImitationBrain.Guards.ON : ImitationBrain.Guards.OFF;
        if (live.server != null) {
            return onServer(config, registry, guards);
        }
        if (outDir == null) {
            throw new UsageException("--out-dir: say where the player logs go (or play on a server with --server)");
        }
        int players = this.players == null ? 5 : this.players;
        String[] teamNames = names.split(",", -1);
        if (teamNames.length != 2) {
            throw new UsageException("--names: give two team names, e.g. Imitator,Amber, not '" + names + "'");
        }
        if (cycles < 1) {
            throw new UsageException("--cycles: must be at least 1, not " + cycles);
        }
        GameSetup.Team right = Teams.builtIn(opponent, teamNames[1].trim());
        long started = System.nanoTime();
        ImitationTeam team = roles.load(sceneFiles, config, registry);
        GameSetup setup;
        try {
            GameSetup.Team left = new GameSetup.Team(teamNames[0].trim(), players,
                    roles.brains(team, config, registry, guards));
            setup = new GameSetup(left, right, cycles, config.seed(), outDir);
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        PrintWriter out = spec.commandLine().getOut();
        out.printf(Locale.ROOT, "%-14s %d scenes from %d files, %s; %s%n", "Learnt", team.scenes(), sceneFiles.size(),
                team.describe(), config.describe());
        Simulator simulator = new Simulator(setup);
        if (recordDir != null) {
            simulator.recordTo(recordDir);
        }
        GameResult result = SimulateCommand.play(simulator, setup.cycles());
        SimulateCommand.printSummary(out, setup, result, (System.nanoTime() - started) / 1e9);
        for (Path log : simulator.recorded()) {
            out.printf(Locale.ROOT, "%-14s %s%n", "Server log", log.toAbsolutePath());
        }
        out.flush();
        return ExitCodes.OK;
    }

    private Integer onServer(MatchConfig config, PluginRegistry registry, ImitationBrain.Guards guards)
            throws IOException, InterruptedException {
        CommandLine.ParseResult parsed = spec.commandLine().getParseResult();
        for (String simulatorOnly : List.of("--opponent", "--names", "--cycles", "--out-dir", "--record")) {
            if (parsed.hasMatchedOption(simulatorOnly)) {
                throw new UsageException(simulatorOnly + ": only for the embedded simulator; on a server the server"
                        + " decides the opponent and the game length (--team names this team, --log-dir keeps the logs)");
            }
        }
        var options = live.clientOptions("Imitator");
        ImitationTeam team = roles.load(sceneFiles, config, registry);
        PrintWriter err = spec.commandLine().getErr();
        err.printf(Locale.ROOT, "%-14s %d scenes from %d files, %s; %s%n", "Learnt", team.scenes(), sceneFiles.size(),
                team.describe(), config.describe());
        err.flush();
        return LiveTeam.play(options, players == null ? 11 : players, roles.brains(team, config, registry, guards),
                config.seed(), live.json, spec.commandLine().getOut(), err);
    }
}
