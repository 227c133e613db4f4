package org.scenes.internal.convert;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.scenes.api.Observer;
import org.scenes.api.Side;
import org.scenes.internal.convert.RebuildStep.Sent;
import org.scenes.internal.gamelog.CommandLogReader;
import org.scenes.internal.gamelog.CommandSource;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogException;
import org.scenes.internal.gamelog.PlayerState;

/**
 * One game's conversion on the reading thread: show by show, places the show in the steps of the
 * game, pairs it with the commands sent before and in its step, makes the players on first sight,
 * and hands the step to the workers; at the end, checks the command log against the game log.
 */
final class GameRun {
    /** Share of player steps whose executed commands may disagree with the command log before it is refused. */
    private static final double DISAGREEMENT_REFUSED = 0.2;
    /** Player steps compared before judging. */
    private static final int AGREEMENT_SAMPLE = 200;

    private final RebuildSettings settings;
    private final Path gameLog;
    private final GameLogConverter.Output output;
    private final List<String> warnings = new ArrayList<>();
    private final GameParameters parameters = new GameParameters();
    private final CommandsAhead commands;
    private final StepClock clock;
    private final PlayerSlots slots = new PlayerSlots();
    private final RebuildWorkers workers;
    private final SynchSees synchSees;
    private final SeePhases phases;
    /** Every player of the game by TEAM_UNUM; null for those not selected. */
    private final Map<String, RebuiltPlayer> players = new LinkedHashMap<>();
    /** Versions from the players' init commands (the command log holds them before the game). */
    private final Map<String, Integer> versions = new HashMap<>();
    /** Players who asked for synchronous sees before their first show, by TEAM_UNUM. */
    private final Map<String, Boolean> synchSee = new HashMap<>();
    /** The latest show, null before the first: its teams check the senders, its score ends the manifest. */
    private GameFrame lastFrame;

    GameRun(RebuildSettings settings, Path gameLog, CommandSource source, GameLogConverter.Output output) {
        this.settings = settings;
        this.gameLog = gameLog;
        this.output = output;
        this.commands = new CommandsAhead(source);
        this.clock = new StepClock(commands);
        this.workers = new RebuildWorkers(settings, gameLog, parameters, slots);
        this.synchSees = new SynchSees(clock, parameters, slots);
        this.phases = new SeePhases(settings.seePhase(), commands, clock, parameters, slots);
    }

    /** A parameter line of the game log. */
    void parameters(String line) {
        parameters.read(line);
    }

    /**
     * Whether the game log is cut at the failure (its last line, after at least one show): then
     * a warning, and the scenes up to there are kept.
     */
    boolean cutOff(GameLogException e) {
        if (clock.frames() == 0 || !e.cutOff()) {
            return false;
        }
        warnings.add(e.getMessage() + "; the game log is cut there: scenes up to cycle " + clock.lastTime()
                + " kept");
        return true;
    }

    void frame(GameFrame frame) {
        try {
            step(frame);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private void step(GameFrame frame) throws IOException {
        clock.show(frame);
        lastFrame = frame;
        int time = frame.time();
        int stoppage = clock.showStoppage();
        String mode = frame.playMode();
        // what was sent before this show: the players' inits (versions) come before their first show
        List<Sent> before = new ArrayList<>();
        collect(before, time, stoppage, true);
        List<RebuiltPlayer> starting = new ArrayList<>(0);
        for (PlayerState state : frame.players()) {
            if (state.state() != 0) {
                RebuiltPlayer player = player(frame, state);
                if (player != null && !player.started) {
                    player.started = true;
                    starting.add(player);
                }
            }
        }
        Set<RebuiltPlayer> synchDue = synchSees.due(frame);
        List<Sent> at = new ArrayList<>();
        collect(at, time, stoppage, false);
        // past the end of a cut command log nothing was sent as far as it tells: not evidence of another game
        boolean covered = !commands.ended() || time <= commands.lastTime();
        phases.hand(new RebuildStep(frame, clock.step(), before, at, !mode.equals("time_over"), starting, synchDue,
                covered), workers);
        clock.shown(mode);
    }

    /**
     * What players sent in steps before ({@code time}, {@code stoppage}) (or, when not
     * {@code before}, in that step, after its see), for the players' workers.
     */
    private void collect(List<Sent> into, int time, int stoppage, boolean before) throws IOException {
        while (true) {
            CommandLogReader.Entry entry = commands.peek();
            if (entry == null) {
                return;
            }
            boolean wanted = before ? entry.before(time, stoppage)
                    : entry.time() == time && entry.stoppage() == stoppage;
            if (!wanted) {
                return;
            }
            route(commands.take(), into);
        }
    }

    /** An entry taken for its step: the referee's goal, a player's init, or a message for its worker. */
    private void route(CommandLogReader.Entry entry, List<Sent> into) throws IOException {
        if (entry.referee()) {
            if (entry.text().startsWith("goal_")) {
                commands.goalAt(entry.time());
            }
            return;
        }
        String team = entry.team();
        if (lastFrame != null && !team.equals(lastFrame.leftTeam()) && !team.equals(lastFrame.rightTeam())) {
            throw new LogException(commands.file(), entry.line(), team + "_" + entry.unum()
                    + " plays in neither team of " + gameLog.getFileName() + " (" + lastFrame.leftTeam() + ", "
                    + lastFrame.rightTeam() + "): the command log of another game?", null);
        }
        String key = team + "_" + entry.unum();
        String message = entry.text();
        if (message.startsWith("(init ")) {
            int version = CommandsAhead.version(message);
            versions.put(key, version);
            long at = clock.serverStep(entry);
            phases.init(key, at);
            // clients of version 18 and later see synchronously from their init on
            synchSees.init(key, at, version >= 18);
            return;
        }
        synchSees.sent(key, message, entry);
        RebuiltPlayer player = players.get(key);
        if (player == null) {
            if (message.startsWith("(synch_see)")) {
                synchSee.put(key, true);
            }
            return; // before the player's first show, or a player not converted
        }
        into.add(new Sent(player, message));
    }

    /** The player of a show's slot, made on first sight; null when not selected. */
    private RebuiltPlayer player(GameFrame frame, PlayerState state) throws IOException {
        String team = state.side() == Side.LEFT ? frame.leftTeam() : frame.rightTeam();
        String key = team + "_" + state.unum();
        if (players.containsKey(key)) {
            return players.get(key);
        }
        Observer observer = new Observer(team, state.side(), state.unum());
        RebuiltPlayer player = null;
        if (settings.selected().test(observer)) {
            int version = versions.getOrDefault(key, commands.initAhead(key, frame.time()));
            // clients of version 18 and later see synchronously from their init on
            double factor = state.viewWidth() / parameters.visibleAngle;
            boolean synch = version >= 18 || synchSee.getOrDefault(key, false)
                    // cones only synchronous vision has (60 and 120 degrees): a log without the init
                    || Math.abs(factor - 2.0 / 3) < 1e-6 || Math.abs(factor - 4.0 / 3) < 1e-6;
            SeePhases.Phase phase = synch ? SeePhases.Phase.FIRST_STEP : phases.phase(key, frame.time(), state);
            boolean goalie = (state.state() & PlayerState.GOALIE) != 0;
            player = new RebuiltPlayer(observer, key, output.open(observer, goalie), workers.next(), version, synch,
                    phase.offset(), settings.fading().forObserver(key));
            player.goalie = goalie;
            if (!phase.told()) {
                phases.undecided(player, frame.time(), phase);
            }
            if (synch) {
                synchSees.synchFromStart(key);
            }
            slots.put(state, player);
        }
        players.put(key, player);
        return player;
    }

    /** Hands out what is left, waits for the workers and gathers the players' reports. */
    GameLogConverter.Result finish() throws IOException {
        // what was sent after the last show; entries more than a step past it belong to no show
        int beyond = 0;
        CommandLogReader.Entry firstBeyond = null;
        List<Sent> after = new ArrayList<>();
        int lastTime = clock.lastTime();
        for (CommandLogReader.Entry entry = commands.take(); entry != null; entry = commands.take()) {
            if (clock.frames() > 0 && entry.time() > lastTime + 1) {
                beyond++;
                firstBeyond = firstBeyond == null ? entry : firstBeyond;
            } else {
                route(entry, after);
            }
        }
        if (clock.frames() == 0) {
            throw new LogException(gameLog, 0, "no show in the game log: nothing to rebuild", null);
        }
        phases.decide(Integer.MAX_VALUE, workers);
        workers.submit(RebuildStep.after(after));
        workers.stop();
        int lastCommandTime = commands.lastTime();
        if (firstBeyond != null) {
            warnings.add(commands.file() + ":" + firstBeyond.line() + ": the command log goes on to cycle "
                    + lastCommandTime + " (" + beyond + " lines) after the game log's last show at cycle "
                    + lastTime + ": a cut game log, or the command log of another game; those lines were left out");
        } else if (lastCommandTime + 1 < lastTime) {
            warnings.add(commands.file() + ": the command log ends at cycle " + lastCommandTime
                    + ", the game log goes on to cycle " + lastTime + ": later scenes have no actions and are dropped");
        }
        long agreed = 0;
        long disagreed = 0;
        List<GameLogConverter.PlayerResult> results = new ArrayList<>();
        for (RebuiltPlayer player : players.values()) {
            if (player != null && player.feed != null) {
                agreed += player.agreed;
                disagreed += player.disagreed;
                results.add(new GameLogConverter.PlayerResult(player.observer, player.feed.finish(0)));
            }
        }
        long compared = agreed + disagreed;
        if (compared >= AGREEMENT_SAMPLE && disagreed > DISAGREEMENT_REFUSED * compared) {
            throw new LogException(commands.file(), 0, String.format(Locale.ROOT,
                    "the commands of %.0f %% of %d player steps disagree with what %s says was executed:"
                            + " the command log of another game?", 100.0 * disagreed / compared, compared,
                    gameLog.getFileName()), null);
        }
        return new GameLogConverter.Result(clock.frames(), results, warnings, lastFrame);
    }

    /** Ends the workers' threads (once), rethrowing the first failure. */
    void stopWorkers() throws IOException {
        workers.stop();
    }
}
