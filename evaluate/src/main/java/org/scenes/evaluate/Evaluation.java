package org.scenes.evaluate;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Objects;
import java.util.Random;
import java.util.function.LongConsumer;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.GameLogs;
import org.scenes.simulator.BrainFactory;
import org.scenes.simulator.GameResult;
import org.scenes.simulator.GameSetup;

/**
 * Teacher and imitator in the same situations: for every seed, one game with the teacher team on
 * the left and one with the imitating team in its place (same team name, seats, seed and
 * opponent, so the same start positions and the same noise until their play differs). While
 * the imitator plays, a shadow teacher is fed each imitating player's messages and what it
 * would have sent is traced beside what the imitator sent.
 */
public final class Evaluation {
    /**
     * What to play.
     *
     * @param teacher the teacher team (its name is the imitating team's name too)
     * @param imitator the imitating players' brains
     * @param opponent the right team in every game
     * @param cycles each game's length
     * @param seeds one pair of games per seed
     * @param side the side teacher and imitator play: {@link #sideOf}
     * @param shadow the shadow teacher beside each imitating player: the teacher's own brains, an
     *               {@link ExternalShadow}, or null for none
     */
    public record Plan(GameSetup.Team teacher, BrainFactory imitator, GameSetup.Team opponent, int cycles,
                       List<Long> seeds, Side side, BrainFactory shadow) {
        /** A plan with teacher and imitator on their {@link #sideOf side}. */
        public Plan(GameSetup.Team teacher, BrainFactory imitator, GameSetup.Team opponent, int cycles,
                    List<Long> seeds) {
            this(teacher, imitator, opponent, cycles, seeds, sideOf(teacher.brains(), opponent.brains()));
        }

        /** A plan whose shadow is the teacher in process, none for an {@link ExternalTeam}. */
        public Plan(GameSetup.Team teacher, BrainFactory imitator, GameSetup.Team opponent, int cycles,
                    List<Long> seeds, Side side) {
            this(teacher, imitator, opponent, cycles, seeds, side,
                    teacher.brains() instanceof ExternalTeam ? null : teacher.brains());
        }

        /** This plan with another shadow teacher (null for none). */
        public Plan withShadow(BrainFactory newShadow) {
            return new Plan(teacher, imitator, opponent, cycles, seeds, side, newShadow);
        }

        /** Whether a team of the plan is an {@link ExternalTeam}: its games are measured from the server's logs. */
        public boolean external() {
            return teacher.brains() instanceof ExternalTeam || opponent.brains() instanceof ExternalTeam;
        }

        public Plan {
            Objects.requireNonNull(teacher, "teacher");
            Objects.requireNonNull(imitator, "imitator");
            Objects.requireNonNull(opponent, "opponent");
            seeds = List.copyOf(seeds);
            if (seeds.isEmpty()) {
                throw new IllegalArgumentException("an evaluation needs at least one seed");
            }
            if (cycles < 1) {
                throw new IllegalArgumentException("cycles must be at least 1, not " + cycles);
            }
            Objects.requireNonNull(side, "side");
            Side expected = sideOf(teacher.brains(), opponent.brains());
            if (side != expected) {
                throw new IllegalArgumentException("teacher and imitator play on the "
                        + (expected == Side.LEFT ? "left" : "right") + " side with these teams: the first team to join"
                        + " a server plays on the left, and ours joins before an external one");
            }
        }

        /**
         * The side teacher and imitator play, the same in the teacher's games and in the imitator's
         * so that their figures compare. The first team to join a server plays on the left, and
         * ours joins before an external team (its command is started once ours is on the server):
         * an external teacher against our opponent plays on the right, and so does its imitator.
         * Against an external opponent they play on the left: the imitator joins first, and an
         * external teacher's command is started first, the opponent's once all its players joined.
         * Without external teams: the left.
         */
        public static Side sideOf(BrainFactory teacher, BrainFactory opponent) {
            return teacher instanceof ExternalTeam && !(opponent instanceof ExternalTeam) ? Side.RIGHT : Side.LEFT;
        }

        /** Game cycles all the games of the plan run, for progress. */
        public long totalCycles() {
            return 2L * seeds.size() * cycles;
        }
    }

    private Evaluation() {
    }

    /** Plays every game of the plan; {@code progress} gets the cycles played so far over all games. */
    public static Results run(Plan plan, Arena arena, LongConsumer progress) throws IOException {
        List<PlayedGame> teacherGames = new ArrayList<>();
        List<PlayedGame> imitatorGames = new ArrayList<>();
        long[] done = {0};
        for (long seed : plan.seeds()) {
            teacherGames.add(play(PlayedGame.Role.TEACHER, plan.teacher(), null, plan, seed, arena, done, progress));
            GameSetup.Team imitating = new GameSetup.Team(plan.teacher().name(), plan.teacher().players(), plan.imitator());
            imitatorGames.add(play(PlayedGame.Role.IMITATOR, imitating, plan.shadow(), plan, seed, arena, done,
                    progress));
        }
        return new Results(teacherGames, imitatorGames);
    }

    /**
     * One game with {@code team} driving on the plan's side and {@code shadow} (or none) beside each
     * of its players; an external team is not traced. The plan's {@link ExternalShadow}'s programs
     * are ended after the game.
     */
    static PlayedGame play(PlayedGame.Role role, GameSetup.Team team, BrainFactory shadow, Plan plan, long seed,
                                  Arena arena, long[] done, LongConsumer progress) throws IOException {
        List<PlayerTrace> traces = new ArrayList<>();
        BrainFactory brains = team.brains() instanceof ExternalTeam ? team.brains()
                : traced(team.brains(), shadow, seed, traces);
        GameSetup.Team seated = new GameSetup.Team(team.name(), team.players(), brains);
        GameSetup setup = plan.side() == Side.LEFT
                ? new GameSetup(seated, plan.opponent(), plan.cycles(), seed, null)
                : new GameSetup(plan.opponent(), seated, plan.cycles(), seed, null);
        List<GameFrame> frames = new ArrayList<>();
        long before = done[0];
        GameResult result;
        try {
            if (shadow != null && plan.shadow() instanceof ExternalShadow external) {
                external.startGame(team.name(), team.players());
            }
            result = arena.play(setup, time -> progress.accept(before + time), frames::add);
        } finally {
            if (plan.shadow() instanceof ExternalShadow external) {
                external.endGame();
            }
        }
        done[0] = before + plan.cycles();
        progress.accept(done[0]);
        traces.forEach(PlayerTrace::close);
        if (plan.external()) {
            // our players hear only their own kick counters: every game's kicks from the game log, alike
            result = new GameResult(result.scoreLeft(), result.scoreRight(), ServerLogGames.kicks(frames, Side.LEFT),
                    ServerLogGames.kicks(frames, Side.RIGHT), result.cycles(), result.steps(), result.logs());
        }
        return new PlayedGame(role, plan.side(), seed, result, frames, traces,
                executed(result, frames, plan.side(), team.name()));
    }

    /**
     * The executed commands from the server's command log beside the game log the arena read (a
     * live server's), else from the frames' counters.
     */
    static ExecutedCommands executed(GameResult result, List<GameFrame> frames, Side side, String team)
            throws IOException {
        for (Path log : result.logs()) {
            String name = log.getFileName().toString();
            if (name.endsWith(".rcg") || name.endsWith(".rcg.gz")) {
                try {
                    return ExecutedCommands.fromCommandLog(frames, side, team, GameLogs.commandLogBeside(log));
                } catch (IllegalArgumentException none) {
                    break; // rcssserver writes its .rcl only with text_logging
                }
            }
        }
        return ExecutedCommands.fromCounters(frames, side);
    }

    /**
     * Brains of {@code driver}, each traced into a new entry of {@code traces} (in the order the
     * simulator seats them: uniform numbers 1, 2, ...), with a {@code shadow} brain (or none) beside.
     */
    static BrainFactory traced(BrainFactory driver, BrainFactory shadow, long seed, List<PlayerTrace> traces) {
        return (team, random) -> new TracedBrain(driver.create(team, random), unum -> {
            // on a live server each player's number comes on its own thread: traces are kept in number order
            PlayerTrace trace = new PlayerTrace(unum);
            synchronized (traces) {
                traces.add(trace);
                traces.sort(Comparator.comparingInt(PlayerTrace::unum));
            }
            // the shadow's own random source: it must not draw from the driver's
            return new TracedBrain.Seat(trace, shadow == null ? null : shadow.create(team, new Random(seed * 31 + unum)));
        });
    }

    /** The games played, teacher's and imitator's, in seed order. */
    public record Results(List<PlayedGame> teacher, List<PlayedGame> imitator) {
        public Results {
            teacher = List.copyOf(teacher);
            imitator = List.copyOf(imitator);
        }
    }
}
