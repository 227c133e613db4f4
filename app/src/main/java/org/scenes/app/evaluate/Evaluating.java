package org.scenes.app.evaluate;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongConsumer;
import java.util.function.Supplier;
import org.scenes.agent.imitation.ImitationTeam;
import org.scenes.agent.net.ClientOptions;
import org.scenes.agent.net.ServerAddress;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.Side;
import org.scenes.app.Progress;
import org.scenes.app.RequestException;
import org.scenes.app.Teams;
import org.scenes.evaluate.Arena;
import org.scenes.evaluate.Comparison;
import org.scenes.evaluate.Dagger;
import org.scenes.evaluate.Disagreements;
import org.scenes.evaluate.Evaluation;
import org.scenes.evaluate.ExternalShadow;
import org.scenes.evaluate.ExternalTeam;
import org.scenes.evaluate.HtmlReport;
import org.scenes.evaluate.Learner;
import org.scenes.evaluate.LiveArena;
import org.scenes.evaluate.PacedBrain;
import org.scenes.evaluate.ServerLogGames;
import org.scenes.evaluate.Tables;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.scene.LazySceneFileWriter;
import org.scenes.internal.scene.SceneCompression;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.simulator.GameSetup;

/**
 * {@code scenes evaluate}: the teacher team and an imitator learnt from it play the same games
 * (same seeds, start positions, opponent), in process or on a soccer server, and their behaviour is
 * compared; optionally DAgger rounds that correct the imitator with a shadow teacher's labels. Or,
 * with {@link GameLogs}, the same figures of existing server logs, no game played.
 */
public final class Evaluating {
    private Evaluating() {
    }

    /**
     * The teams of the games: built-in teachers, or programs (external teams).
     *
     * @param teacher the built-in teacher's name ({@code krislet}), unless {@code teacherCommand} is given
     * @param players players per side of teacher and imitator
     * @param opponent the built-in opponent, {@code TEACHER:N}, unless {@code opponentCommand} is given
     * @param teacherCommand an external teacher team's command, or null
     * @param opponentCommand an external opponent's command, or null
     */
    public record Lineup(String teacher, int players, String opponent, String teacherCommand, String opponentCommand) {
    }

    /**
     * Where the games are played.
     *
     * @param address a soccer server's {@code HOST:PORT}, or null for the embedded simulator
     * @param logs the directory the server writes its game logs to, or null
     * @param waitSeconds how long a game waits for the server, an external team's players and a shadow's init
     * @param version the protocol version our players send in their inits on a server
     */
    public record Server(String address, Path logs, double waitSeconds, int version) {
    }

    /**
     * Existing game logs to evaluate instead of playing.
     *
     * @param teacher the teacher's games' directory, or null
     * @param imitator the imitator's games' directory, or null
     * @param team the team measured in every game, or null for the one team all the games have
     */
    public record GameLogs(Path teacher, Path imitator, String team) {
        /** None: the games are played. */
        public static final GameLogs NONE = new GameLogs(null, null, null);

        /** Whether any is given: then no game is played and no configuration is needed. */
        public boolean given() {
            return teacher != null || imitator != null || team != null;
        }
    }

    /**
     * What to evaluate. It is checked by {@link #run}, in the order the command line always checked
     * its options, each refusal a {@link RequestException} naming the option.
     *
     * @param sceneFiles the scene files the imitator is learnt from; empty: the teacher's own games
     * @param configs the matching configurations; exactly one to play, none needed for {@link GameLogs}
     * @param teams the teams
     * @param cycles cycles per game
     * @param seeds games per side, seeds {@code firstSeed}, {@code firstSeed + 1}, ...
     * @param firstSeed the first game seed
     * @param trainGames teacher games learnt from without scene files (seeds 1001, 1002, ...)
     * @param thinkSteps the imitator decides on the latest see every so many steps; 0: on every see
     * @param knowledge with scene files: an imitation team with roles, or null for every player on all the scenes
     * @param server where the games are played
     * @param shadowCommand a shadow teacher that is a program, or null (the teacher in process, if built in)
     * @param dagger DAgger rounds after the evaluation
     * @param disagreements the CSV file of the sees where imitator and shadow part, or null
     * @param gameLogs existing game logs instead of games, or {@link GameLogs#NONE}
     * @param report the directory of the HTML report, or null
     */
    public record Request(List<Path> sceneFiles, List<MatchConfig> configs, Lineup teams, int cycles, int seeds,
                          long firstSeed, int trainGames, double thinkSteps, ImitationTeam.Knowledge knowledge,
                          Server server, String shadowCommand, int dagger, Path daggerOut, Path disagreements,
                          GameLogs gameLogs, Path report) {
        public Request {
            sceneFiles = List.copyOf(sceneFiles);
            configs = List.copyOf(configs);
            Objects.requireNonNull(teams, "teams");
            Objects.requireNonNull(server, "server");
            Objects.requireNonNull(gameLogs, "gameLogs");
        }
    }

    /** What a front end may show while the work goes on, besides the progress of each stage. */
    public interface Events {
        /** The imitator's knowledge base is built: {@code scenes} scenes, matched with {@code config}. */
        default void learnt(int scenes, MatchConfig config) {
        }

        /** DAgger's rounds begin: {@link Dagger.Round#header()} heads their rows. */
        default void daggerBegins() {
        }

        /** A DAgger round is done; round 0 also has the teacher's row. */
        default void round(Dagger.Round round) {
        }

        /** A one-line message from the games on a server (a game that waits, a log still missing). */
        default void notice(String line) {
        }

        /** The figures, before the report is written: shown then, they stay shown when the report fails. */
        default void figures(Outcome outcome) throws IOException {
        }
    }

    /**
     * The evaluation's result.
     *
     * @param about what was compared, as label and text, in order
     * @param comparison the figures (of DAgger's last round)
     * @param results the games (of DAgger's last round)
     * @param rounds DAgger's rounds 0 to N, or none
     * @param report the HTML report's page, or null
     */
    public record Outcome(Map<String, String> about, Comparison comparison, Evaluation.Results results,
                         List<Dagger.Round> rounds, Path report) {
        /** Everything as nested maps and lists for a JSON writer: about, the figures, the rounds if any. */
        public Map<String, Object> json() {
            Map<String, Object> root = new LinkedHashMap<>();
            root.put("about", about);
            root.putAll(Tables.json(comparison));
            if (!rounds.isEmpty()) {
                root.put("rounds", rounds.stream().map(Dagger.Round::json).toList());
            }
            return root;
        }
    }

    /** The request checked, the teams built. */
    private record Setup(String teacherName, GameSetup.Team teacher, GameSetup.Team opponent, Side side,
                         MatchConfig config, PluginRegistry registry, List<Long> seeds, ExternalShadow shadow) {
    }

    /**
     * Evaluates: learns the imitator, plays the games (and DAgger's rounds), writes the disagreements
     * and the report; or reads the request's game logs.
     *
     * @param registry the plugins, asked for only when games are played
     * @param progress told of each stage: Reading games (games), Learning, Evaluating, Round N (cycles)
     * @throws RequestException for a request that cannot be evaluated, before any game
     * @throws IOException when files, games or the server fail
     */
    public static Outcome run(Request request, Supplier<PluginRegistry> registry, Progress progress, Events events)
            throws IOException {
        if (request.gameLogs().given()) {
            return fromGameLogs(request, progress, events);
        }
        Setup setup = setup(request, registry);
        Outcome outcome = play(request, setup, arena(request.server(), events), progress, events);
        Map<String, String> about = outcome.about();
        if (request.disagreements() != null) {
            List<Evaluation.Results> games = outcome.rounds().isEmpty() ? List.of(outcome.results())
                    : outcome.rounds().stream().map(Dagger.Round::results).toList();
            long rows = Disagreements.write(request.disagreements(), games);
            about.put("disagreements", rows + " sees on which imitator and shadow parted, in "
                    + request.disagreements());
        }
        Server server = request.server();
        about.put("played on", server.address() == null ? "the embedded simulator, in process, synchronous"
                : "the soccer server at " + server.address() + (server.logs() == null ? ", without its game logs"
                        : ", positions from its game logs in " + server.logs())
                        + "; the seeds seed the players, the server's noise is its own (scenes server --seed)");
        return report(request, outcome, "scenes evaluate: " + setup.teacherName() + " and its imitator", events);
    }

    /** Tells the figures, then writes the report if one is asked for. */
    private static Outcome report(Request request, Outcome outcome, String title, Events events) throws IOException {
        events.figures(outcome);
        if (request.report() == null) {
            return outcome;
        }
        Path page = HtmlReport.write(request.report(), title, outcome.about(), outcome.comparison(), outcome.results());
        return new Outcome(outcome.about(), outcome.comparison(), outcome.results(), outcome.rounds(), page);
    }

    /** The figures of existing game logs. */
    private static Outcome fromGameLogs(Request request, Progress progress, Events events) throws IOException {
        GameLogs logs = request.gameLogs();
        require(request.dagger() == 0, "--dagger: plays and corrects the imitator; not with --teacher-games (the"
                + " figures of existing game logs)");
        require(request.shadowCommand() == null && request.disagreements() == null, (request.shadowCommand() != null
                ? "--shadow-command" : "--disagreements") + ": a shadow plays beside the imitator's games; not with"
                + " --teacher-games (the figures of existing game logs)");
        require(logs.teacher() != null && logs.imitator() != null, logs.teacher() == null && logs.imitator() == null
                ? "--team: goes with --teacher-games DIR --imitator-games DIR"
                : "--teacher-games and --imitator-games: give both (the teacher's and the imitator's game logs)");
        require(request.sceneFiles().isEmpty() && request.server().address() == null,
                "--teacher-games: evaluates existing game logs; it takes no SCENES and no --server");
        long started = System.nanoTime();
        List<Path> teacherLogs = gameLogs("--teacher-games", logs.teacher());
        List<Path> imitatorLogs = gameLogs("--imitator-games", logs.imitator());
        // the divergences and the Turing folds pair game i of one side with game i of the other
        require(teacherLogs.size() == imitatorLogs.size(), "--teacher-games " + logs.teacher() + " holds "
                + teacherLogs.size() + " game logs and --imitator-games " + logs.imitator() + " "
                + imitatorLogs.size() + ": give as many of each (game i of one side is compared with game i of the"
                + " other)");
        ServerLogGames.Read read;
        progress.begin("Reading games", teacherLogs.size() + imitatorLogs.size());
        try {
            LongConsumer counter = counter(progress);
            read = ServerLogGames.read(teacherLogs, imitatorLogs, logs.team(), counter::accept);
        } catch (IllegalArgumentException e) {
            throw new RequestException("--team: " + e.getMessage());
        } finally {
            progress.end();
        }
        Map<String, String> about = new LinkedHashMap<>();
        about.put("team", read.team());
        about.put("teacher games", describe(logs.teacher(), read.teacherGames()));
        about.put("imitator games", describe(logs.imitator(), read.imitatorGames()));
        about.put("games", "read from the server's logs; each side's games numbered 1, 2, ... in name order (the"
                + " Turing figure's folds pair them)");
        about.put("not measured", "what only the players' own traffic tells: sees answered, the mix of commands"
                + " sent on sees and its stuck share, agreement with a shadow teacher");
        about.put("time", String.format(Locale.ROOT, "%.1f s", (System.nanoTime() - started) / 1e9));
        Outcome outcome = new Outcome(about, Comparison.of(read.results()), read.results(), List.of(), null);
        return report(request, outcome, "scenes evaluate: " + read.team() + ", teacher's and imitator's games", events);
    }

    private static List<Path> gameLogs(String option, Path directory) throws IOException {
        try {
            return ServerLogGames.gameLogs(directory);
        } catch (IllegalArgumentException e) {
            throw new RequestException(option + ": " + e.getMessage());
        }
    }

    private static String describe(Path directory, List<ServerLogGames.Game> games) {
        long withCommands = games.stream().filter(g -> g.commandLog() != null).count();
        return games.size() + " in " + directory + " (" + String.join(", ", games.stream()
                .map(g -> g.gameLog().getFileName().toString()).toList()) + "); executed commands from "
                + (withCommands == games.size() ? "their .rcl" : withCommands == 0 ? "the .rcg's counters (no .rcl)"
                        : withCommands + " .rcl, the others' .rcg counters");
    }

    /** Checks the request for games and builds the teams. */
    private static Setup setup(Request request, Supplier<PluginRegistry> registry) {
        List<Path> sceneFiles = request.sceneFiles();
        Lineup teams = request.teams();
        Server server = request.server();
        Path disagreements = request.disagreements();
        String shadowCommand = request.shadowCommand();
        require(request.configs().size() == 1, "evaluate uses one configuration: give one --metric and one --k");
        require(request.cycles() >= 1, "--cycles: must be at least 1, not " + request.cycles());
        require(request.seeds() >= 1, "--seeds: must be at least 1, not " + request.seeds());
        require(!sceneFiles.isEmpty() || request.trainGames() >= 1,
                "--train-games: must be at least 1 when no scene files are given, not " + request.trainGames());
        List<Long> seeds = new ArrayList<>();
        for (int i = 0; i < request.seeds(); i++) {
            seeds.add(request.firstSeed() + i);
        }
        require(PacedBrain.valid(request.thinkSteps()), "--think-steps: must be 0, or 1 or more, not "
                + PacedBrain.text(request.thinkSteps()));
        require(request.dagger() >= 0, "--dagger: must be 0 or more rounds, not " + request.dagger());
        require(request.daggerOut() == null || request.dagger() > 0, "--dagger-out: writes DAgger's labelled scenes;"
                + " give --dagger N too");
        require(request.daggerOut() == null || !Files.isRegularFile(request.daggerOut()), "--dagger-out: "
                + request.daggerOut() + " is a file, not a directory");
        if (request.daggerOut() != null) {
            // its round directories are written over: a scene file learnt from must not lie there
            Path out = request.daggerOut().toAbsolutePath().normalize();
            for (Path file : request.sceneFiles()) {
                require(!file.toAbsolutePath().normalize().startsWith(out), "--dagger-out: " + request.daggerOut()
                        + " holds " + file + ", which the imitator learns from; write the labels elsewhere");
            }
        }
        require(request.knowledge() == null || !sceneFiles.isEmpty(),
                "--knowledge: roles come from the uniform numbers of scene files; give SCENES");
        String teacherCommand = teams.teacherCommand();
        String opponentCommand = teams.opponentCommand();
        boolean externalTeacherAlone = teacherCommand != null && shadowCommand == null;
        require(request.dagger() == 0 || !externalTeacherAlone, "--dagger: labels with a shadow teacher; with"
                + " --teacher-command give the teacher program as --shadow-command too (or a built-in --teacher)");
        require(disagreements == null || !externalTeacherAlone, "--disagreements: an external teacher has no shadow in"
                + " process; give the teacher program as --shadow-command too");
        require(shadowCommand == null || !shadowCommand.isBlank(), "--shadow-command: an empty command");
        require(server.waitSeconds() > 0 && server.waitSeconds() <= 86_400,
                "--server-wait: give seconds between 0 and 86400, not " + server.waitSeconds());
        require(disagreements == null || sceneFiles.stream().noneMatch(f -> f.toAbsolutePath().normalize()
                .equals(disagreements.toAbsolutePath().normalize())), "--disagreements: " + disagreements
                + " is an input (SCENES); an output never overwrites an input");
        if (teacherCommand != null || opponentCommand != null) {
            String option = teacherCommand != null ? "--teacher-command" : "--opponent-command";
            require(server.address() != null && server.logs() != null, option + ": an external team plays on a server"
                    + " and is measured from its logs: give --server HOST:PORT and --server-logs DIR");
            require(!sceneFiles.isEmpty(), option + ": give the SCENES to learn the imitator from (the teacher's games"
                    + " are not played in process with an external team)");
            require(teacherCommand == null || !teacherCommand.isBlank(), "--teacher-command: an empty command");
            require(opponentCommand == null || !opponentCommand.isBlank(), "--opponent-command: an empty command");
        }
        GameSetup.Team teacher = teacherCommand != null
                ? new GameSetup.Team("Teal", teams.players(), new ExternalTeam(teacherCommand))
                : Teams.builtIn(teams.teacher() + ":" + teams.players(), "Teal");
        GameSetup.Team opponent = opponentCommand != null
                ? new GameSetup.Team("Amber", teams.players(), new ExternalTeam(opponentCommand))
                : Teams.builtIn(teams.opponent(), "Amber");
        ExternalShadow shadow = shadowCommand == null ? null : new ExternalShadow(shadowCommand,
                server.address() == null ? ExternalShadow.Pacing.EACH_MESSAGE : ExternalShadow.Pacing.AS_THE_SERVER,
                wait(server));
        return new Setup(teacherCommand != null ? "the command '" + teacherCommand + "'" : teams.teacher(), teacher,
                opponent, Evaluation.Plan.sideOf(teacher.brains(), opponent.brains()), request.configs().get(0),
                registry.get(),
                seeds, shadow);
    }

    private static Duration wait(Server server) {
        return Duration.ofMillis(Math.round(server.waitSeconds() * 1000));
    }

    /** The checks' one shape: a {@link RequestException} saying {@code message} unless {@code holds}. */
    private static void require(boolean holds, String message) {
        if (!holds) {
            throw new RequestException(message);
        }
    }

    /** The embedded simulator, or the live server. */
    private static Arena arena(Server server, Events events) {
        if (server.address() == null) {
            require(server.logs() == null, "--server-logs: needs --server (the embedded simulator's games have"
                    + " positions)");
            return Arena.embedded();
        }
        ServerAddress address;
        try {
            address = ServerAddress.parse(server.address());
        } catch (IllegalArgumentException e) {
            throw new RequestException("--server: " + e.getMessage());
        }
        require(server.logs() == null || Files.isDirectory(server.logs()), "--server-logs: " + server.logs()
                + " is not a directory");
        ClientOptions client;
        try {
            client = ClientOptions.of(address, "Teal").withVersion(server.version());
        } catch (IllegalArgumentException e) {
            throw new RequestException("--version: " + e.getMessage());
        }
        // an init is given 5 s: one answered after its player gave up leaves a player on the server
        return new LiveArena(client.withTimeouts(Duration.ofSeconds(5), Duration.ofSeconds(10)), server.logs(),
                wait(server), events::notice);
    }

    /** Learns the imitator and plays the games, or DAgger's rounds. */
    private static Outcome play(Request request, Setup setup, Arena arena, Progress progress, Events events)
            throws IOException {
        Learner.Matching matching;
        try {
            matching = Learner.Matching.of(setup.config(), setup.registry());
        } catch (IllegalArgumentException e) {
            throw new RequestException(e.getMessage());
        }
        Map<String, String> about = new LinkedHashMap<>();
        about.put("teacher", setup.teacherName() + ", " + setup.teacher().players() + " players");
        about.put("opponent", describe(setup.opponent()));
        Learner.Imitator imitator;
        long started = System.nanoTime();
        int cycles = request.cycles();
        List<Path> sceneFiles = request.sceneFiles();
        if (sceneFiles.isEmpty()) {
            List<Long> trainingSeeds = new ArrayList<>();
            for (int i = 0; i < request.trainGames(); i++) {
                trainingSeeds.add(1001L + i);
            }
            progress.begin("Learning", (long) request.trainGames() * cycles);
            try {
                imitator = Learner.fromTeacherGames(setup.teacher(), setup.opponent(), cycles, trainingSeeds,
                        matching, counter(progress));
            } finally {
                progress.end();
            }
            about.put("imitator learnt from", request.trainGames() + " teacher games of " + cycles
                    + " cycles against the same opponent, seeds " + trainingSeeds + " (" + imitator.scenes() + " scenes)");
        } else {
            // a file the knowledge base cannot hold is failed work (exit 1), its message names the file
            imitator = request.knowledge() == null
                    ? Learner.of(KnowledgeBase.load(sceneFiles, matching.transforms()), matching)
                    : Learner.roles(sceneFiles, matching, request.knowledge());
            about.put("imitator learnt from", sceneFiles.size() + " scene files (" + imitator.scenes()
                    + " scenes): " + String.join(" ", sceneFiles.stream().map(Path::toString).toList()));
            about.put("roles", imitator.roles() == null ? "none: every player on all the scenes"
                    : imitator.roles().describe());
        }
        about.put("matching", setup.config().describe());
        about.put("imitator tempo", request.thinkSteps() == 0 ? "answers every see"
                : "decides on the latest see every " + PacedBrain.text(request.thinkSteps()) + " steps (the Krislet client's think loop)");
        about.put("games", setup.seeds().size() + " per side of " + cycles + " cycles, seeds " + setup.seeds());
        events.learnt(imitator.scenes(), setup.config());
        Evaluation.Plan plan = new Evaluation.Plan(setup.teacher(),
                PacedBrain.pace(imitator.brains(), request.thinkSteps()), setup.opponent(), cycles, setup.seeds(),
                setup.side());
        if (setup.shadow() != null) {
            plan = plan.withShadow(setup.shadow());
        }
        about.put("shadow teacher", plan.shadow() == null ? "none"
                : setup.shadow() != null ? "the command '" + setup.shadow().command() + "', a process per imitating"
                        + " player fed its messages" + (setup.shadow().pacing() == ExternalShadow.Pacing.EACH_MESSAGE
                                ? " (a (think) after each, its commands up to (done) answer it)"
                                : " as the server sends them")
                : setup.teacherName() + " in process");
        Evaluation.Results results;
        Comparison comparison;
        List<Dagger.Round> rounds = request.dagger() == 0 ? List.of()
                : dagger(request, plan, imitator, arena, progress, events);
        if (rounds.isEmpty()) {
            progress.begin("Evaluating", plan.totalCycles());
            try {
                results = Evaluation.run(plan, arena, counter(progress));
            } finally {
                progress.end();
            }
            comparison = Comparison.of(results);
        } else {
            Dagger.Round last = rounds.get(rounds.size() - 1);
            results = last.results();
            comparison = last.comparison();
            about.put("DAgger", request.dagger() + " rounds after the first evaluation (round 0): in each round's games"
                    + " (the same seeds) the scenes each imitating player built, labelled with its shadow teacher's"
                    + " reply to the same see, join the knowledge base of the next round; the teacher's games are"
                    + " played once. Figures below: round " + last.number());
            about.put("DAgger: columns", Dagger.Round.header().trim());
            about.put("DAgger: teacher", rounds.get(0).teacherRow().trim());
            for (Dagger.Round round : rounds) {
                about.put("DAgger: round " + round.number(), round.row().trim());
            }
        }
        if (results.teacher().stream().anyMatch(g -> g.frames().isEmpty())) {
            about.put("not measured", HtmlReport.NO_POSITIONS);
        }
        about.put("time", String.format(Locale.ROOT, "%.1f s", (System.nanoTime() - started) / 1e9));
        return new Outcome(about, comparison, results, rounds, null);
    }

    /** DAgger's rounds 0 to {@code dagger}, each told and with its progress. */
    private static List<Dagger.Round> dagger(Request request, Evaluation.Plan plan, Learner.Imitator imitator,
                                             Arena arena, Progress progress, Events events) throws IOException {
        Dagger dagger = new Dagger(plan, imitator, request.thinkSteps());
        events.daggerBegins();
        List<Dagger.Round> rounds = new ArrayList<>();
        for (int r = 0; r <= request.dagger(); r++) {
            progress.begin("Round " + r, dagger.nextRoundCycles());
            try {
                rounds.add(dagger.next(arena, counter(progress)));
            } finally {
                progress.end();
            }
            events.round(rounds.get(r));
            if (request.daggerOut() != null && r < request.dagger()) {
                events.notice(writeLabels(dagger, request.daggerOut().resolve("round-" + r)));
            }
        }
        return rounds;
    }

    /**
     * A round's labelled scenes as scene files, {@code TEAM_UNUM-gN.json.gz} for the player's N-th game,
     * which {@code scenes play}, {@code validate} and {@code evaluate} take as they take any recorded
     * player's (the goalie marked); what was written, in a line.
     */
    private static String writeLabels(Dagger dagger, Path directory) throws IOException {
        Files.createDirectories(directory);
        Map<String, Integer> games = new HashMap<>();
        int files = 0;
        long scenes = 0;
        for (Dagger.Correction player : dagger.labelled()) {
            if (player.scenes().isEmpty()) {
                continue;
            }
            String name = player.scenes().get(0).observer().team() + "_" + player.unum();
            int game = games.merge(name, 1, Integer::sum);
            Path target = directory.resolve(SceneCompression.GZIP.fileName(name + "-g" + game));
            try (LazySceneFileWriter writer = new LazySceneFileWriter(target, dagger.grid(), "DAgger labels")) {
                if (player.goalie()) {
                    writer.goalie();
                }
                for (Scene scene : player.scenes()) {
                    writer.write(scene);
                }
                writer.commit();
            }
            files++;
            scenes += player.scenes().size();
        }
        return String.format(Locale.ROOT, "%-22s %d scene files, %d scenes, in %s", "DAgger labels", files, scenes,
                directory);
    }

    /** A team as the report's about table names it: with its command when it is external. */
    private static String describe(GameSetup.Team team) {
        if (team.brains() instanceof ExternalTeam external) {
            return team.name() + ", " + team.players() + " players, the command '" + external.command() + "'";
        }
        return team.name() + ", " + team.players() + " players";
    }

    /**
     * The steps done so far, as work in the evaluate module reports them (from any thread), turned into
     * the progress's steps; a count lower than one already told adds nothing.
     */
    private static LongConsumer counter(Progress progress) {
        AtomicLong told = new AtomicLong();
        return done -> {
            long before = told.getAndAccumulate(done, Math::max);
            if (done > before) {
                progress.stepBy(done - before);
            }
        };
    }
}
