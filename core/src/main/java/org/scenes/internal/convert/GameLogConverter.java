package org.scenes.internal.convert;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;
import java.util.function.Predicate;
import org.scenes.api.Grid;
import org.scenes.api.Observer;
import org.scenes.internal.gamelog.CommandLogReader;
import org.scenes.internal.gamelog.CommandSource;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogException;
import org.scenes.internal.gamelog.GameLogReader;
import org.scenes.internal.vision.Fading;
import org.scenes.internal.vision.SeeWriter;

/**
 * Scenes for every player of a game from the server's own logs: the game log ({@code .rcg},
 * where everything was each step) and the command log ({@code .rcl}, what each player sent).
 * Each player's messages are rebuilt step by step, in the order the player got and sent them
 * ({@code sense_body}, the {@code see} the server would have sent, by {@link SeeWriter}, then the
 * commands of that step), and converted by {@link SceneConverter} under the rules of player logs
 * (docs/conversion.md, "Scenes from game logs"). Streams both logs: memory grows with the
 * number of players, not with the game's length.
 *
 * <p>The parts, each in its own file: {@link GameRun} reads the game show by show on the caller's
 * thread, placing each show in the game's steps ({@link StepClock}) and pairing it with the commands
 * sent before and in its step, read ahead from the command source ({@link CommandsAhead});
 * {@link SynchSees} and {@link SeePhases} decide when each player's sees fall; the
 * {@link RebuildWorkers} rebuild each player's messages ({@link PerceptWriter}) and convert them.
 */
public final class GameLogConverter {
    /** Where an asynchronous player's see clock starts. */
    public enum SeePhase {
        /** Multiples of the see period from the first step, as the project's simulator keeps it. */
        FIRST_STEP,
        /**
         * rcssserver's: the player's own see counter, started at the first tick after its connection;
         * the command log gives the connection's step, not the tick: of the candidates the one that
         * explains clearly most of the player's commands (a see-driven player answers in the cycle
         * of a see), else the first; when the commands' timing tells the candidates not apart, the
         * one whose sees best explain what the player did ({@link PhaseEvidence}). Without the
         * step, the same among offsets from the first step's.
         */
        INFER
    }

    /** Where one player's scenes go. */
    @FunctionalInterface
    public interface Output {
        SceneConverter.SceneSink open(Observer observer) throws IOException;

        /** The same for a player the game log marks as its team's goalie or not. */
        default SceneConverter.SceneSink open(Observer observer, boolean goalie) throws IOException {
            return open(observer);
        }
    }

    /** One player's conversion. */
    public record PlayerResult(Observer observer, ConversionReport report) {
        /** {@code TEAM_UNUM}, the player's name in the command log. */
        public String key() {
            return observer.team() + "_" + observer.uniformNumber();
        }
    }

    /**
     * @param frames shows read from the game log
     * @param warnings what was wrong but left the scenes sound, each naming the file and line
     * @param last the last show read (teams and final score), null when none was
     */
    public record Result(long frames, List<PlayerResult> players, List<String> warnings, GameFrame last) {
    }

    private final Grid grid;
    private final Pairing pairing;
    private final Fading fading;
    private final Predicate<Observer> selected;
    private final int threads;
    private boolean commandsBeforeSee;
    private SeePhase seePhase = SeePhase.INFER;
    private boolean keepUnanswered;
    private boolean world;

    /**
     * @param grid and {@code pairing} make the scenes, as for player logs
     * @param fading how a seen player's team and number fade with distance
     * @param selected which players get scenes (all are seen by the others)
     * @param threads threads rebuilding and converting the players (each player on one)
     */
    public GameLogConverter(Grid grid, Pairing pairing, Fading fading, Predicate<Observer> selected, int threads) {
        this.grid = Objects.requireNonNull(grid, "grid");
        this.pairing = Objects.requireNonNull(pairing, "pairing");
        this.fading = Objects.requireNonNull(fading, "fading");
        this.selected = Objects.requireNonNull(selected, "selected");
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be 1 or more, not " + threads);
        }
        this.threads = threads;
    }

    /**
     * Within a step, the player's commands come before its see, right after {@code sense_body}
     * ({@code true}), or (the default) before it only when the player already holds a see taken
     * after its last command took effect, otherwise after it (players answer what they see; see
     * {@code Worker.commandsFirst}). The command log does not say.
     */
    public GameLogConverter commandsBeforeSee(boolean before) {
        this.commandsBeforeSee = before;
        return this;
    }

    /** Unanswered sees become scenes without action, as {@link SceneConverter.Builder#keepUnanswered}. */
    public GameLogConverter keepUnanswered(boolean keep) {
        this.keepUnanswered = keep;
        return this;
    }

    /**
     * Whether each scene carries the player's world model, built from the rebuilt percepts (then
     * each {@code sense_body} carries the player's state and the referee's calls are heard); default false.
     */
    public GameLogConverter world(boolean world) {
        this.world = world;
        return this;
    }

    /** Where asynchronous players' see clocks start (default {@link SeePhase#INFER}). */
    public GameLogConverter seePhase(SeePhase phase) {
        this.seePhase = Objects.requireNonNull(phase, "phase");
        return this;
    }

    /**
     * Converts one game. A truncated game log (its last line cut) gives a warning and the scenes
     * up to there; a game log out of order, or a command log of another game (team names or
     * executed commands disagree), is a {@link GameLogException} or {@link LogException} naming
     * the file and line.
     */
    public Result convert(Path gameLog, Path commandLog, Output output) throws IOException {
        try (CommandLogReader commands = CommandLogReader.open(commandLog)) {
            return convert(gameLog, commands, output);
        }
    }

    /**
     * Converts one game whose commands come from {@code commands} (a command log, or those inferred
     * from the game log); as {@link #convert(Path, Path, Output)}. The caller closes the source.
     */
    public Result convert(Path gameLog, CommandSource commands, Output output) throws IOException {
        GameRun run = new GameRun(new RebuildSettings(grid, pairing, fading, selected, threads, commandsBeforeSee,
                seePhase, keepUnanswered, world), gameLog, commands, output);
        try {
            try {
                GameLogReader.forEach(gameLog, run::frame, run::parameters);
            } catch (UncheckedIOException e) {
                throw e.getCause();
            } catch (GameLogException e) {
                if (!run.cutOff(e)) {
                    throw e;
                }
            }
            return run.finish();
        } finally {
            run.stopWorkers();
        }
    }

    /** Every player of the game: the default selection. */
    public static Predicate<Observer> everyone() {
        return observer -> true;
    }

    /** The players of {@code team} (any when null) with number {@code unum} (any when 0). */
    public static Predicate<Observer> only(String team, int unum) {
        return observer -> (team == null || team.equals(observer.team()))
                && (unum == 0 || unum == observer.uniformNumber());
    }

}
