package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.scenes.agent.imitation.ImitationTeam;
import org.scenes.agent.net.ClientOptions;
import org.scenes.agent.net.ServerAddress;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Side;
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
import org.scenes.internal.validate.MatchConfig;
import org.scenes.simulator.GameSetup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes evaluate}: teacher and imitator play the same games; do they play alike? */
@Command(name = "evaluate", mixinStandardHelpOptions = true,
        description = {"Closed-loop evaluation: the teacher team and an imitating team play the same games (same"
                + " seeds, start positions, opponent) in the embedded simulator (or on a soccer server with"
                + " --server), and their behaviour is compared:"
                + " action mix and its divergence, kicks and goals per 1000 cycles, distance to the ball, kick-off"
                + " to first touch, stuck share, agreement with a shadow teacher, and a Turing figure.",
                "The imitator is learnt from the teacher's own games (simulate, convert, knowledge base, in"
                + " process), or from the SCENES files given.",
                "With --teacher-games DIR --imitator-games DIR no game is played: the same figures come from"
                + " existing server logs (.rcg or .rcg.gz, the .rcl beside when there is one) of any team."})
final class EvaluateCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @ParentCommand
    ScenesCommand top;

    @Parameters(paramLabel = "SCENES", arity = "0..*",
            description = "Scene files to learn the imitator from; default: the teacher's own games (--train-games).")
    List<Path> sceneFiles = new ArrayList<>();

    @Mixin
    MatchOptions match;

    @Option(names = "--teacher", paramLabel = "NAME", defaultValue = "krislet",
            description = "The teacher the imitator is compared with: ${COMPLETION-CANDIDATES}. Default: ${DEFAULT-VALUE}.",
            completionCandidates = SimulateCommand.TeacherNames.class)
    String teacher;

    @Option(names = "--players", paramLabel = "N", defaultValue = "5", description = "Players per side. Default: ${DEFAULT-VALUE}.")
    int players;

    @Option(names = "--opponent", paramLabel = "TEACHER:N", defaultValue = "krislet:5",
            description = "The right team in every game. Default: ${DEFAULT-VALUE}.")
    String opponent;

    @Option(names = "--cycles", paramLabel = "N", defaultValue = "6000", description = "Cycles per game. Default: ${DEFAULT-VALUE}.")
    int cycles;

    @Option(names = "--seeds", paramLabel = "N", defaultValue = "5",
            description = "Games per side, seeds --first-seed, --first-seed + 1, ... Default: ${DEFAULT-VALUE}.")
    int seeds;

    @Option(names = "--first-seed", paramLabel = "S", defaultValue = "1", description = "The first game seed. Default: ${DEFAULT-VALUE}.")
    long firstSeed;

    @Option(names = "--train-games", paramLabel = "N", defaultValue = "2",
            description = "Teacher games learnt from when no SCENES are given (seeds 1001, 1002, ...: never an"
                    + " evaluation seed). Default: ${DEFAULT-VALUE}.")
    int trainGames;

    @Option(names = "--think-steps", paramLabel = "N", defaultValue = "0",
            description = "Pace the imitator like the Krislet client's think loop: decide on the latest see every N"
                    + " steps (Krislet: 2); 0 answers every see, as 'scenes play' does. Default: ${DEFAULT-VALUE}.")
    int thinkSteps;

    @Option(names = "--knowledge", paramLabel = "counterpart|team", converter = ImitationTeamOptions.KnowledgeConverter.class,
            description = "With SCENES: an imitation team with roles, as 'scenes play' assembles it: each player on its"
                    + " counterpart's scenes (the recorded player with its uniform number; counterpart) or everyone's"
                    + " (team), with its counterpart's kick-off moves, set-play kicks and goalie flag; --dagger's labels"
                    + " join the labelling player's counterpart's scenes too. Default: no roles, every player on all"
                    + " the scenes.")
    ImitationTeam.Knowledge knowledge;

    @Option(names = "--version", paramLabel = "V", defaultValue = "9",
            description = "With --server: the protocol version our players (the imitator, and teams played in process)"
                    + " send in their inits, 7 to 19; a --shadow-command gets its player's messages. Default:"
                    + " ${DEFAULT-VALUE}.")
    int version;

    @Option(names = "--dagger", paramLabel = "N", defaultValue = "0",
            description = "After the evaluation, N rounds of DAgger: the scenes the imitator built in its games (the"
                    + " same seeds each round), labelled with what its shadow teacher sent on the same sees, join"
                    + " its knowledge base, and it is evaluated again; one row of figures per round. Needs a shadow:"
                    + " the teacher in process, or --shadow-command. Default: ${DEFAULT-VALUE}.")
    int dagger;

    @Option(names = "--shadow-command", paramLabel = "CMD",
            description = "A shadow teacher that is a program (HELIOS base's player, the classic Krislet): a process"
                    + " per imitating player, started (bash -c, in its own session) before each imitator game and"
                    + " ended after it; {host} and {port} are replaced by a loopback endpoint of its own that answers"
                    + " its init as the server answered its player's, {team} by the team's name, {players} by 1,"
                    + " {unum} by the player's number. It is sent every message the imitator receives; its commands"
                    + " are recorded (agreement, --disagreements, --dagger's labels), never executed. In the embedded"
                    + " simulator each message is followed by (think) and the program must answer (done); on --server"
                    + " the server's own (think), if any, is forwarded.")
    String shadowCommand;

    @Option(names = "--disagreements", paramLabel = "FILE",
            description = "Write where the imitator and its shadow part, one CSV row per see (round, seed, unum,"
                    + " cycle, imitator's command, shadow's command): the sees of the running clock on which they"
                    + " sent different body commands (a turn the other way round counts) or only one of them sent one.")
    Path disagreements;

    @Option(names = "--json", description = "Print one JSON object instead of the table.")
    boolean json;

    @Option(names = "--report", paramLabel = "DIR", description = "Write the HTML report DIR/index.html (self-contained).")
    Path report;

    @Option(names = "--server", paramLabel = "HOST:PORT",
            description = "Play the games on a live soccer server through the UDP runtime instead of in process:"
                    + " each game waits until the server takes a new game (scenes server --games N"
                    + " --games-per-seed 2, or rcssserver restarted in a loop; docs/evaluation.md).")
    String server;

    @Option(names = "--server-logs", paramLabel = "DIR",
            description = "With --server: the directory the server writes its game logs (.rcg) to; positions, paths,"
                    + " heat maps and replays come from them. Without it those figures are not measured.")
    Path serverLogs;

    @Option(names = "--server-wait", paramLabel = "SECONDS", defaultValue = "60",
            description = "With --server: how long each game waits for the server to accept its first player,"
                    + " and for an external team's players to join; also how long a --shadow-command may take to send"
                    + " its init. Default: ${DEFAULT-VALUE}.")
    double serverWait;

    @Option(names = "--teacher-command", paramLabel = "CMD",
            description = "An external teacher team: a command started (bash -c, in its own session) for each game on"
                    + " --server, after our opponent joined, so it plays the right side (and the imitator too); with"
                    + " --opponent-command it is started first, through a relay on loopback ({host}, {port}), and"
                    + " plays the left side as the imitator does; {host}, {port}, {team}, {players} are replaced; its"
                    + " whole process group is ended after each game. Needs --server-logs (the figures come from the"
                    + " server's logs) and SCENES.")
    String teacherCommand;

    @Option(names = "--opponent-command", paramLabel = "CMD",
            description = "An external opponent, started like --teacher-command for each game (--players players,"
                    + " the right side), with --teacher-command too (once all the teacher's players joined). Needs"
                    + " --server, --server-logs and SCENES.")
    String opponentCommand;

    @Option(names = "--teacher-games", paramLabel = "DIR",
            description = "Evaluate from existing game logs instead of playing: the teacher's games, every .rcg or"
                    + " .rcg.gz in DIR (with the .rcl beside when there is one). Needs --imitator-games.")
    Path teacherGames;

    @Option(names = "--imitator-games", paramLabel = "DIR",
            description = "With --teacher-games: the imitator's game logs. Games of each side pair in name order.")
    Path imitatorGames;

    @Option(names = "--team", paramLabel = "NAME",
            description = "With --teacher-games: the team measured in every game. Default: the one team name all"
                    + " the games have.")
    String team;

    @Override
    public Integer call() throws IOException {
        if (teacherGames != null || imitatorGames != null || team != null) {
            require(dagger == 0, "--dagger: plays and corrects the imitator; not with --teacher-games (the figures of"
                    + " existing game logs)");
            require(shadowCommand == null && disagreements == null, (shadowCommand != null ? "--shadow-command"
                    : "--disagreements") + ": a shadow plays beside the imitator's games; not with --teacher-games (the"
                    + " figures of existing game logs)");
            return fromGameLogs();
        }
        Setup setup = setup();
        PrintWriter out = spec.commandLine().getOut();
        Outcome outcome = evaluate(setup, arena(), json ? null : out);
        if (disagreements != null) {
            List<Evaluation.Results> games = outcome.rounds().isEmpty() ? List.of(outcome.results())
                    : outcome.rounds().stream().map(Dagger.Round::results).toList();
            long rows = Disagreements.write(disagreements, games);
            outcome.about().put("disagreements", rows + " sees on which imitator and shadow parted, in "
                    + disagreements);
        }
        outcome.about().put("played on", server == null ? "the embedded simulator, in process, synchronous"
                : "the soccer server at " + server + (serverLogs == null ? ", without its game logs"
                        : ", positions from its game logs in " + serverLogs)
                        + "; the seeds seed the players, the server's noise is its own (scenes server --seed)");
        if (json) {
            Map<String, Object> root = new LinkedHashMap<>();
            root.put("about", outcome.about());
            root.putAll(Tables.json(outcome.comparison()));
            if (!outcome.rounds().isEmpty()) {
                root.put("rounds", outcome.rounds().stream().map(Dagger.Round::json).toList());
            }
            out.println(ConfigFiles.JSON.writeValueAsString(root));
        } else {
            if (!outcome.rounds().isEmpty()) {
                out.printf("%nRound %d%n", outcome.rounds().size() - 1);
            }
            out.print(Tables.text(outcome.comparison()));
        }
        if (report != null) {
            Path page = HtmlReport.write(report, "scenes evaluate: " + setup.teacherName() + " and its imitator",
                    outcome.about(), outcome.comparison(), outcome.results());
            if (!json) {
                out.println();
                out.println("Report written to " + page.toAbsolutePath());
            }
        }
        out.flush();
        return ExitCodes.OK;
    }

    /** {@code --teacher-games DIR --imitator-games DIR}: the figures of existing game logs. */
    private int fromGameLogs() throws IOException {
        require(teacherGames != null && imitatorGames != null, teacherGames == null && imitatorGames == null
                ? "--team: goes with --teacher-games DIR --imitator-games DIR"
                : "--teacher-games and --imitator-games: give both (the teacher's and the imitator's game logs)");
        require(sceneFiles.isEmpty() && server == null,
                "--teacher-games: evaluates existing game logs; it takes no SCENES and no --server");
        long started = System.nanoTime();
        List<Path> teacherLogs = gameLogs("--teacher-games", teacherGames);
        List<Path> imitatorLogs = gameLogs("--imitator-games", imitatorGames);
        // the divergences and the Turing folds pair game i of one side with game i of the other
        require(teacherLogs.size() == imitatorLogs.size(), "--teacher-games " + teacherGames + " holds "
                + teacherLogs.size() + " game logs and --imitator-games " + imitatorGames + " " + imitatorLogs.size()
                + ": give as many of each (game i of one side is compared with game i of the other)");
        ServerLogGames.Read read;
        try (TerminalProgress bar = TerminalProgress.start("Reading games", teacherLogs.size() + imitatorLogs.size(),
                " games", 1)) {
            read = ServerLogGames.read(teacherLogs, imitatorLogs, team, bar::stepTo);
        } catch (IllegalArgumentException e) {
            throw new UsageException("--team: " + e.getMessage());
        }
        Comparison comparison = Comparison.of(read.results());
        Map<String, String> about = new LinkedHashMap<>();
        about.put("team", read.team());
        about.put("teacher games", describe(teacherGames, read.teacherGames()));
        about.put("imitator games", describe(imitatorGames, read.imitatorGames()));
        about.put("games", "read from the server's logs; each side's games numbered 1, 2, ... in name order (the"
                + " Turing figure's folds pair them)");
        about.put("not measured", "what only the players' own traffic tells: sees answered, the mix of commands"
                + " sent on sees and its stuck share, agreement with a shadow teacher");
        about.put("time", String.format(Locale.ROOT, "%.1f s", (System.nanoTime() - started) / 1e9));
        PrintWriter out = spec.commandLine().getOut();
        if (json) {
            Map<String, Object> root = new LinkedHashMap<>();
            root.put("about", about);
            root.putAll(Tables.json(comparison));
            out.println(ConfigFiles.JSON.writeValueAsString(root));
        } else {
            out.print(Tables.text(comparison));
        }
        if (report != null) {
            Path page = HtmlReport.write(report, "scenes evaluate: " + read.team() + ", teacher's and imitator's games",
                    about, comparison, read.results());
            if (!json) {
                out.println();
                out.println("Report written to " + page.toAbsolutePath());
            }
        }
        out.flush();
        return ExitCodes.OK;
    }

    private static List<Path> gameLogs(String option, Path directory) throws IOException {
        try {
            return ServerLogGames.gameLogs(directory);
        } catch (IllegalArgumentException e) {
            throw new UsageException(option + ": " + e.getMessage());
        }
    }

    private static String describe(Path directory, List<ServerLogGames.Game> games) {
        long withCommands = games.stream().filter(g -> g.commandLog() != null).count();
        return games.size() + " in " + directory + " (" + String.join(", ", games.stream()
                .map(g -> g.gameLog().getFileName().toString()).toList()) + "); executed commands from "
                + (withCommands == games.size() ? "their .rcl" : withCommands == 0 ? "the .rcg's counters (no .rcl)"
                        : withCommands + " .rcl, the others' .rcg counters");
    }

    /** Everything the evaluation needs, checked. */
    record Setup(String teacherName, GameSetup.Team teacher, GameSetup.Team opponent, Side side, MatchConfig config,
                 PluginRegistry registry, List<Path> sceneFiles, int trainGames, int cycles, List<Long> seeds,
                 ImitationTeam.Knowledge knowledge, int thinkSteps, int dagger, ExternalShadow shadow) {
    }

    /** The evaluation's games (of the last DAgger round), figures, DAgger rounds (or none) and what was compared. */
    record Outcome(Map<String, String> about, Comparison comparison, Evaluation.Results results,
                   List<Dagger.Round> rounds) {
    }

    private Setup setup() {
        List<MatchConfig> configs = match.configs();
        require(configs.size() == 1, "evaluate uses one configuration: give one --metric and one --k");
        require(cycles >= 1, "--cycles: must be at least 1, not " + cycles);
        require(seeds >= 1, "--seeds: must be at least 1, not " + seeds);
        require(!sceneFiles.isEmpty() || trainGames >= 1,
                "--train-games: must be at least 1 when no scene files are given, not " + trainGames);
        List<Long> seedList = new ArrayList<>();
        for (int i = 0; i < seeds; i++) {
            seedList.add(firstSeed + i);
        }
        require(thinkSteps >= 0, "--think-steps: must be 0 or more, not " + thinkSteps);
        require(dagger >= 0, "--dagger: must be 0 or more rounds, not " + dagger);
        require(knowledge == null || !sceneFiles.isEmpty(),
                "--knowledge: roles come from the uniform numbers of scene files; give SCENES");
        boolean externalTeacherAlone = teacherCommand != null && shadowCommand == null;
        require(dagger == 0 || !externalTeacherAlone, "--dagger: labels with a shadow teacher; with --teacher-command"
                + " give the teacher program as --shadow-command too (or a built-in --teacher)");
        require(disagreements == null || !externalTeacherAlone, "--disagreements: an external teacher has no shadow in"
                + " process; give the teacher program as --shadow-command too");
        require(shadowCommand == null || !shadowCommand.isBlank(), "--shadow-command: an empty command");
        require(serverWait > 0 && serverWait <= 86_400,
                "--server-wait: give seconds between 0 and 86400, not " + serverWait);
        require(disagreements == null || sceneFiles.stream().noneMatch(f -> f.toAbsolutePath().normalize()
                .equals(disagreements.toAbsolutePath().normalize())), "--disagreements: " + disagreements
                + " is an input (SCENES); an output never overwrites an input");
        if (teacherCommand != null || opponentCommand != null) {
            String option = teacherCommand != null ? "--teacher-command" : "--opponent-command";
            require(server != null && serverLogs != null, option + ": an external team plays on a server and is"
                    + " measured from its logs: give --server HOST:PORT and --server-logs DIR");
            require(!sceneFiles.isEmpty(), option + ": give the SCENES to learn the imitator from (the teacher's games"
                    + " are not played in process with an external team)");
            require(teacherCommand == null || !teacherCommand.isBlank(), "--teacher-command: an empty command");
            require(opponentCommand == null || !opponentCommand.isBlank(), "--opponent-command: an empty command");
        }
        GameSetup.Team teacherTeam = teacherCommand != null
                ? new GameSetup.Team("Teal", players, new ExternalTeam(teacherCommand))
                : SimulateCommand.team(teacher + ":" + players, "Teal");
        GameSetup.Team opponentTeam = opponentCommand != null
                ? new GameSetup.Team("Amber", players, new ExternalTeam(opponentCommand))
                : SimulateCommand.team(opponent, "Amber");
        ExternalShadow shadow = shadowCommand == null ? null : new ExternalShadow(shadowCommand,
                server == null ? ExternalShadow.Pacing.EACH_MESSAGE : ExternalShadow.Pacing.AS_THE_SERVER,
                Duration.ofMillis(Math.round(serverWait * 1000)));
        return new Setup(teacherCommand != null ? "the command '" + teacherCommand + "'" : teacher, teacherTeam,
                opponentTeam, Evaluation.Plan.sideOf(teacherTeam.brains(), opponentTeam.brains()), configs.get(0),
                top.global.registry(), sceneFiles, trainGames, cycles, seedList, knowledge, thinkSteps, dagger, shadow);
    }

    /** The option checks' one shape: a usage error (exit code 2) saying {@code message} unless {@code holds}. */
    private static void require(boolean holds, String message) {
        if (!holds) {
            throw new UsageException(message);
        }
    }

    /** The embedded simulator, or with --server the live server. */
    private Arena arena() {
        if (server == null) {
            require(serverLogs == null, "--server-logs: needs --server (the embedded simulator's games have positions)");
            return Arena.embedded();
        }
        ServerAddress address;
        try {
            address = ServerAddress.parse(server);
        } catch (IllegalArgumentException e) {
            throw new UsageException("--server: " + e.getMessage());
        }
        require(serverLogs == null || Files.isDirectory(serverLogs), "--server-logs: " + serverLogs + " is not a directory");
        PrintWriter err = spec.commandLine().getErr();
        // an init is given 5 s: one answered after its player gave up leaves a player on the server
        ClientOptions client;
        try {
            client = ClientOptions.of(address, "Teal").withVersion(version);
        } catch (IllegalArgumentException e) {
            throw new UsageException("--version: " + e.getMessage());
        }
        return new LiveArena(client.withTimeouts(Duration.ofSeconds(5), Duration.ofSeconds(10)), serverLogs,
                Duration.ofMillis(Math.round(serverWait * 1000)), line -> {
                    synchronized (err) {
                        err.println(line);
                        err.flush();
                    }
                });
    }

    /** Learns the imitator and plays the games, with a progress bar per stage on a terminal. */
    static Outcome evaluate(Setup setup, Arena arena, PrintWriter out) throws IOException {
        Learner.Matching matching;
        try {
            matching = Learner.Matching.of(setup.config(), setup.registry());
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        Map<String, String> about = new LinkedHashMap<>();
        about.put("teacher", setup.teacherName() + ", " + setup.teacher().players() + " players");
        about.put("opponent", describe(setup.opponent()));
        Learner.Imitator imitator;
        long started = System.nanoTime();
        if (setup.sceneFiles().isEmpty()) {
            List<Long> trainingSeeds = new ArrayList<>();
            for (int i = 0; i < setup.trainGames(); i++) {
                trainingSeeds.add(1001L + i);
            }
            try (TerminalProgress bar = TerminalProgress.start("Learning", (long) setup.trainGames() * setup.cycles(),
                    " cycles", 1)) {
                imitator = Learner.fromTeacherGames(setup.teacher(), setup.opponent(), setup.cycles(), trainingSeeds,
                        matching, bar.stepper());
            }
            about.put("imitator learnt from", setup.trainGames() + " teacher games of " + setup.cycles()
                    + " cycles against the same opponent, seeds " + trainingSeeds + " (" + imitator.scenes() + " scenes)");
        } else {
            // a file the knowledge base cannot hold is failed work (exit 1), its message names the file
            imitator = setup.knowledge() == null
                    ? Learner.of(KnowledgeBase.load(setup.sceneFiles(), matching.transforms()), matching)
                    : Learner.roles(setup.sceneFiles(), matching, setup.knowledge());
            about.put("imitator learnt from", setup.sceneFiles().size() + " scene files (" + imitator.scenes()
                    + " scenes): " + String.join(" ", setup.sceneFiles().stream().map(Path::toString).toList()));
            about.put("roles", imitator.roles() == null ? "none: every player on all the scenes"
                    : imitator.roles().describe());
        }
        about.put("matching", setup.config().describe());
        about.put("imitator tempo", setup.thinkSteps() == 0 ? "answers every see"
                : "decides on the latest see every " + setup.thinkSteps() + " steps (the Krislet client's think loop)");
        about.put("games", setup.seeds().size() + " per side of " + setup.cycles() + " cycles, seeds " + setup.seeds());
        if (out != null) {
            out.printf(Locale.ROOT, "%-14s %d scenes; %s%n", "Learnt", imitator.scenes(), setup.config().describe());
            out.flush();
        }
        Evaluation.Plan plan = new Evaluation.Plan(setup.teacher(),
                PacedBrain.pace(imitator.brains(), setup.thinkSteps()), setup.opponent(), setup.cycles(),
                setup.seeds(), setup.side());
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
        List<Dagger.Round> rounds = setup.dagger() == 0 ? List.of() : dagger(setup, plan, imitator, arena, out);
        if (rounds.isEmpty()) {
            try (TerminalProgress bar = TerminalProgress.start("Evaluating", plan.totalCycles(), " cycles", 1)) {
                results = Evaluation.run(plan, arena, bar.stepper());
            }
            comparison = Comparison.of(results);
        } else {
            Dagger.Round last = rounds.get(rounds.size() - 1);
            results = last.results();
            comparison = last.comparison();
            about.put("DAgger", setup.dagger() + " rounds after the first evaluation (round 0): in each round's games"
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
        return new Outcome(about, comparison, results, rounds);
    }

    /** DAgger's rounds 0 to {@code --dagger}, a row printed and a progress bar per round. */
    private static List<Dagger.Round> dagger(Setup setup, Evaluation.Plan plan, Learner.Imitator imitator, Arena arena,
                                             PrintWriter out)
            throws IOException {
        Dagger dagger = new Dagger(plan, imitator, setup.thinkSteps());
        if (out != null) {
            out.println(Dagger.Round.header());
            out.flush();
        }
        List<Dagger.Round> rounds = new ArrayList<>();
        for (int r = 0; r <= setup.dagger(); r++) {
            try (TerminalProgress bar = TerminalProgress.start("Round " + r, dagger.nextRoundCycles(), " cycles", 1)) {
                rounds.add(dagger.next(arena, bar.stepper()));
            }
            if (out != null) {
                if (r == 0) {
                    out.println(rounds.get(0).teacherRow());
                }
                out.println(rounds.get(r).row());
                out.flush();
            }
        }
        return rounds;
    }

    static String describe(GameSetup.Team team) {
        if (team.brains() instanceof ExternalTeam external) {
            return team.name() + ", " + team.players() + " players, the command '" + external.command() + "'";
        }
        return team.name() + ", " + team.players() + " players";
    }
}
