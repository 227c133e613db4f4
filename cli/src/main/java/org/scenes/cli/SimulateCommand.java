package org.scenes.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.scenes.app.Teams;
import org.scenes.simulator.GameResult;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;
import org.scenes.simulator.teacher.Teachers;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParentCommand;
import picocli.CommandLine.Spec;

/** {@code scenes simulate}: a game between teacher agents in the embedded simulator, written as player logs. */
@Command(name = "simulate", mixinStandardHelpOptions = true,
        description = {"Play a game between teacher agents in the embedded soccer simulator and write each"
                + " player's log (TEAM_UNUM.lsf.gz, classic .lsf layout) for 'scenes convert'."
                + " Same options and seed, same logs. Model and simplifications: docs/simulator.md."})
final class SimulateCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @ParentCommand
    ScenesCommand top;

    @Option(names = "--teams", paramLabel = "TEACHER:N,TEACHER:N", defaultValue = "krislet:5,krislet:5",
            description = "The left and right team: teacher and number of players (1 to 11)."
                    + " Teachers: ${COMPLETION-CANDIDATES}. Default: ${DEFAULT-VALUE}.",
            completionCandidates = TeacherNames.class)
    String teams;

    @Option(names = "--names", paramLabel = "LEFT,RIGHT", defaultValue = "Teal,Amber",
            description = "Team names (letters, digits, '-', '_'). Default: ${DEFAULT-VALUE}.")
    String names;

    @Option(names = "--cycles", paramLabel = "N", defaultValue = "6000",
            description = "Game length in cycles of 100 ms; half time at half. Default: ${DEFAULT-VALUE}.")
    int cycles;

    @Option(names = {"--game-seed", "--seed"}, paramLabel = "N", defaultValue = "1",
            description = "The game's seed: all its randomness (noise, teachers' choices); --seed is the older spelling."
                    + " Default: ${DEFAULT-VALUE}.")
    long seed;

    @Option(names = "--out-dir", paramLabel = "DIR", required = true,
            description = "Where the player logs go (created if missing; existing logs of the same names are replaced).")
    Path outDir;

    @Option(names = "--record", paramLabel = "DIR",
            description = "Also write the server's logs of the game there: the game log (.rcg, rcssserver 19's"
                    + " text format, for rcssmonitor and other log tools) and the command log (.rcl).")
    Path recordDir;

    /** The teacher names for the help text. */
    static final class TeacherNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return Teachers.names().iterator();
        }
    }

    @Override
    public Integer call() throws IOException {
        String[] teamSpecs = teams.split(",", -1);
        if (teamSpecs.length != 2) {
            throw new UsageException("--teams: give two teams, e.g. krislet:5,krislet:5, not '" + teams + "'");
        }
        String[] teamNames = names.split(",", -1);
        if (teamNames.length != 2) {
            throw new UsageException("--names: give two team names, e.g. Teal,Amber, not '" + names + "'");
        }
        if (cycles < 1) {
            throw new UsageException("--cycles: must be at least 1, not " + cycles);
        }
        GameSetup setup;
        try {
            setup = new GameSetup(Teams.builtIn(teamSpecs[0], teamNames[0].trim()), Teams.builtIn(teamSpecs[1],
                    teamNames[1].trim()), cycles, seed, outDir);
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        long started = System.nanoTime();
        Simulator simulator = new Simulator(setup);
        if (recordDir != null) {
            simulator.recordTo(recordDir);
        }
        GameResult result = play(simulator, setup.cycles());
        printSummary(spec.commandLine().getOut(), setup, result, (System.nanoTime() - started) / 1e9);
        for (Path log : simulator.recorded()) {
            spec.commandLine().getOut().printf(Locale.ROOT, "%-14s %s%n", "Server log", log.toAbsolutePath());
        }
        spec.commandLine().getOut().flush();
        return ExitCodes.OK;
    }

    /** Runs the game with a progress bar in game cycles on a terminal, silent when piped. */
    static GameResult play(GameSetup setup) throws IOException {
        return play(new Simulator(setup), setup.cycles());
    }

    /** Runs the simulator's game with a progress bar in game cycles on a terminal, silent when piped. */
    static GameResult play(Simulator simulator, int cycles) throws IOException {
        try (TerminalProgress bar = TerminalProgress.start("Simulating", cycles, " cycles", 1)) {
            return simulator.run(bar::stepTo);
        }
    }

    static void printSummary(PrintWriter out, GameSetup setup, GameResult result, double seconds) {
        String left = setup.left().name();
        String right = setup.right().name();
        out.printf(Locale.ROOT, "%-14s %s %d : %d %s%n", "Score", left, result.scoreLeft(), result.scoreRight(), right);
        out.printf(Locale.ROOT, "%-14s %s %d, %s %d%n", "Kicks", left, result.kicksLeft(), right, result.kicksRight());
        out.printf(Locale.ROOT, "%-14s %d (%d simulator steps with pauses) in %.2f s%n", "Cycles", result.cycles(),
                result.steps(), seconds);
        out.printf(Locale.ROOT, "%-14s %d player logs in %s%n", "Written", result.logs().size(),
                setup.logDirectory().toAbsolutePath());
        for (Path log : result.logs()) {
            out.printf(Locale.ROOT, "  %s%n", log.getFileName());
        }
        out.flush();
    }
}
