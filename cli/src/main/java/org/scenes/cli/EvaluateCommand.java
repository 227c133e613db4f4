package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.scenes.agent.imitation.ImitationTeam;
import org.scenes.app.evaluate.Evaluating;
import org.scenes.evaluate.Dagger;
import org.scenes.evaluate.Tables;
import org.scenes.internal.validate.MatchConfig;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes evaluate}: teacher and imitator play the same games; do they play alike? */
@Command(name = "evaluate",
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

    // --version is the protocol version here, so the standard help mixin (-h, -V) cannot be used
    @Option(names = {"-h", "--help"}, usageHelp = true, description = "Show this help message and exit.")
    boolean help;

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
    double thinkSteps;

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

    @Option(names = "--dagger-out", paramLabel = "DIR",
            description = "With --dagger: write each round's labelled scenes, DIR/round-R/TEAM_UNUM-gN.json.gz (the"
                    + " player's N-th game), so 'scenes play', 'validate' and 'evaluate' can learn from them as from"
                    + " any recorded player's scenes (round R's labels are what round R + 1 adds).")
    Path daggerOut;

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
        Evaluating.GameLogs gameLogs = new Evaluating.GameLogs(teacherGames, imitatorGames, team);
        // configurations are read (their files, their checks) only when games are played
        List<MatchConfig> configs = gameLogs.given() ? List.of() : match.configs();
        Evaluating.Request request = new Evaluating.Request(sceneFiles, configs,
                new Evaluating.Lineup(teacher, players, opponent, teacherCommand, opponentCommand), cycles, seeds,
                firstSeed, trainGames, thinkSteps, knowledge, new Evaluating.Server(server, serverLogs, serverWait, version),
                shadowCommand, dagger, daggerOut, disagreements, gameLogs, report);
        PrintWriter out = spec.commandLine().getOut();
        Evaluating.Outcome outcome = Evaluating.run(request, top.global::registry,
                TerminalProgress.reporter(gameLogs.given() ? " games" : " cycles", 1), new Printed(out, spec.commandLine().getErr()));
        if (outcome.report() != null && !json) {
            out.println();
            out.println("Report written to " + outcome.report().toAbsolutePath());
        }
        out.flush();
        return ExitCodes.OK;
    }

    /** What the evaluation tells as it goes, printed: with --json only the JSON object reaches standard output. */
    private final class Printed implements Evaluating.Events {
        private final PrintWriter out;
        private final PrintWriter err;

        Printed(PrintWriter out, PrintWriter err) {
            this.out = out;
            this.err = err;
        }

        @Override
        public void learnt(int scenes, MatchConfig config) {
            if (!json) {
                out.printf(Locale.ROOT, "%-14s %d scenes; %s%n", "Learnt", scenes, config.describe());
                out.flush();
            }
        }

        @Override
        public void daggerBegins() {
            if (!json) {
                out.println(Dagger.Round.header());
                out.flush();
            }
        }

        @Override
        public void round(Dagger.Round round) {
            if (!json) {
                if (round.number() == 0) {
                    out.println(round.teacherRow());
                }
                out.println(round.row());
                out.flush();
            }
        }

        @Override
        public void notice(String line) {
            // from the games' threads
            synchronized (err) {
                err.println(line);
                err.flush();
            }
        }

        @Override
        public void figures(Evaluating.Outcome outcome) throws IOException {
            if (json) {
                out.println(ConfigFiles.JSON.writeValueAsString(outcome.json()));
            } else {
                if (!outcome.rounds().isEmpty()) {
                    out.printf("%nRound %d%n", outcome.rounds().size() - 1);
                }
                out.print(Tables.text(outcome.comparison()));
            }
        }
    }
}
