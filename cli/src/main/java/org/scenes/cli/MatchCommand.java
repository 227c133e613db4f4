package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.scenes.agent.imitation.ImitationBrain;
import org.scenes.agent.imitation.ImitationTeam;
import org.scenes.app.Teams;
import org.scenes.evaluate.Arena;
import org.scenes.evaluate.GameFigures;
import org.scenes.evaluate.Match;
import org.scenes.evaluate.Tables;
import org.scenes.internal.scene.SceneCompression;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.simulator.BrainFactory;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.teacher.Teachers;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes match}: two teams, teachers or imitators, play one game; the score and both sides' figures. */
@Command(name = "match", mixinStandardHelpOptions = true,
        description = {"Play one game in the embedded simulator between two teams and report the score and, for"
                + " both, the behaviour figures of 'scenes evaluate'.",
                "A team SPEC is TEACHER:N (krislet, statebased) or imitator:N:SCENES[:CONFIG.json], SCENES a"
                + " scene file, a directory of them, or several joined by '+'; CONFIG a file of 'scenes tune'"
                + " (else the matching options given). Imitators get a shadow teacher (--shadow) for the agreement."})
final class MatchCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @ParentCommand
    ScenesCommand top;

    @Mixin
    MatchOptions match;

    @Option(names = "--left", paramLabel = "SPEC", required = true, description = "The left team.")
    String left;

    @Option(names = "--right", paramLabel = "SPEC", required = true, description = "The right team.")
    String right;

    @Option(names = "--names", paramLabel = "LEFT,RIGHT", defaultValue = "Teal,Amber",
            description = "Team names. Default: ${DEFAULT-VALUE}.")
    String names;

    @Option(names = "--cycles", paramLabel = "N", defaultValue = "6000", description = "Game length. Default: ${DEFAULT-VALUE}.")
    int cycles;

    @Option(names = "--game-seed", paramLabel = "S", defaultValue = "1", description = "The game's seed. Default: ${DEFAULT-VALUE}.")
    long gameSeed;

    @Option(names = "--shadow", paramLabel = "TEACHER", defaultValue = "krislet",
            description = "The teacher an imitator's agreement is measured against. Default: ${DEFAULT-VALUE}.")
    String shadow;

    @Mixin
    ImitationTeamOptions roles;

    @Option(names = "--json", description = "Print one JSON object instead of the table.")
    boolean json;

    /** A parsed team spec: its brains and, for an imitator, the shadow beside each player. */
    private record Side(GameSetup.Team team, BrainFactory shadow, String description) {
    }

    @Override
    public Integer call() throws IOException {
        String[] teamNames = names.split(",", -1);
        if (teamNames.length != 2) {
            throw new UsageException("--names: give two team names, e.g. Teal,Amber, not '" + names + "'");
        }
        if (cycles < 1) {
            throw new UsageException("--cycles: must be at least 1, not " + cycles);
        }
        roles.checkThinkSteps();
        BrainFactory shadowTeacher;
        try {
            shadowTeacher = Teachers.byName(shadow);
        } catch (IllegalArgumentException e) {
            throw new UsageException("--shadow: " + e.getMessage());
        }
        Side l = side("--left", left, teamNames[0].trim(), shadowTeacher);
        Side r = side("--right", right, teamNames[1].trim(), shadowTeacher);
        if (l.team().name().equals(r.team().name())) {
            throw new UsageException("--names: the two teams need different names");
        }
        Match.Outcome outcome;
        try (TerminalProgress bar = TerminalProgress.start("Playing", cycles, " cycles", 1)) {
            outcome = Match.play(l.team(), l.shadow(), r.team(), r.shadow(), cycles, gameSeed, Arena.embedded(),
                    bar::stepTo);
        }
        GameFigures leftFigures = GameFigures.of(outcome.left());
        GameFigures rightFigures = GameFigures.of(outcome.right());
        PrintWriter out = spec.commandLine().getOut();
        if (json) {
            Map<String, Object> root = new LinkedHashMap<>();
            root.put("left", Map.of("spec", l.description(), "name", l.team().name(), "goals", outcome.left().goalsFor(),
                    "figures", Tables.json(leftFigures)));
            root.put("right", Map.of("spec", r.description(), "name", r.team().name(), "goals", outcome.right().goalsFor(),
                    "figures", Tables.json(rightFigures)));
            root.put("cycles", outcome.left().result().cycles());
            root.put("seed", gameSeed);
            out.println(ConfigFiles.JSON.writeValueAsString(root));
        } else {
            out.printf(Locale.ROOT, "%-14s %s (%s) %d : %d %s (%s)%n", "Score", l.team().name(), l.description(),
                    outcome.left().goalsFor(), outcome.right().goalsFor(), r.team().name(), r.description());
            out.printf(Locale.ROOT, "%-14s %d, seed %d%n%n", "Cycles", outcome.left().result().cycles(), gameSeed);
            out.print(Tables.match(l.team().name(), leftFigures, r.team().name(), rightFigures));
        }
        out.flush();
        return ExitCodes.OK;
    }

    private Side side(String option, String text, String name, BrainFactory shadowTeacher) throws IOException {
        String[] parts = text.trim().split(":", 4);
        if (!parts[0].equals("imitator")) {
            if (parts.length != 2) {
                throw new UsageException(option + ": '" + text + "' is neither TEACHER:N nor imitator:N:SCENES[:CONFIG]");
            }
            return new Side(Teams.builtIn(text, name), null, text.trim());
        }
        if (parts.length < 3 || parts[2].isEmpty()) {
            throw new UsageException(option + ": an imitator needs its scenes: imitator:N:SCENES[:CONFIG.json]");
        }
        int players;
        try {
            players = Integer.parseInt(parts[1]);
        } catch (NumberFormatException e) {
            throw new UsageException(option + ": '" + parts[1] + "' in '" + text + "' is not a number of players");
        }
        List<Path> files = new ArrayList<>();
        for (String part : parts[2].split("\\+")) {
            Path path = Path.of(part);
            if (Files.isDirectory(path)) {
                files.addAll(SceneCompression.sceneFilesIn(path));
            } else if (Files.isRegularFile(path)) {
                files.add(path);
            } else {
                throw new UsageException(option + ": no scene file or directory " + path);
            }
        }
        if (files.isEmpty()) {
            throw new UsageException(option + ": no scene files in " + parts[2]);
        }
        MatchConfig config;
        if (parts.length == 4) {
            config = ConfigFiles.read(Path.of(parts[3]));
        } else {
            List<MatchConfig> configs = match.configs();
            if (configs.size() != 1) {
                throw new UsageException("match uses one configuration: give one --metric and one --k");
            }
            config = configs.get(0);
        }
        try {
            config.check(top.global.registry());
        } catch (IllegalArgumentException e) {
            throw new UsageException(option + ": " + e.getMessage());
        }
        // a file the knowledge base cannot hold is failed work (exit 1), its message names the file
        ImitationTeam team = roles.load(files, config, top.global.registry());
        try {
            return new Side(new GameSetup.Team(name, players, roles.brains(team, config, top.global.registry(),
                    ImitationBrain.Guards.OFF)), shadowTeacher, "imitator of " + team.scenes() + " scenes, "
                    + team.describe() + ", " + config.describe());
        } catch (IllegalArgumentException e) {
            throw new UsageException(option + ": " + e.getMessage());
        }
    }
}
