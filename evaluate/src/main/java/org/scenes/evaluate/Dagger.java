package org.scenes.evaluate;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import java.util.function.LongConsumer;
import org.scenes.agent.imitation.ImitationBrain;
import org.scenes.agent.imitation.Viewing;
import org.scenes.api.Grid;
import org.scenes.api.Scene;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;
import org.scenes.simulator.GameSetup;

/**
 * Learning from the corrections (DAgger, dataset aggregation: Ross, Gordon and Bagnell 2011),
 * round by round. Each round the imitator of the current knowledge base plays the plan's seeds
 * beside its shadow teacher; those games are evaluated against the teacher's (played once, in
 * the first round: the same seeds give the same games), and the scenes each imitating player
 * built, labelled with its shadow's replies to the same sees ({@link ShadowLabels}), join the
 * knowledge base, one sequence per player and game in cycle order, for the next round.
 * It needs the plan's shadow teacher: the teacher's own brain in process, or a program beside each
 * imitating player ({@link ExternalShadow}).
 */
public final class Dagger {
    /**
     * One round's imitator and figures.
     *
     * @param number 0 for the imitator as first learnt
     * @param scenes the scenes of its knowledge base
     * @param added of those, the scenes the previous round labelled
     * @param labelled the scenes this round's games labelled, for the next
     */
    public record Round(int number, int scenes, int added, int labelled, Comparison comparison,
                        Evaluation.Results results) {
        /** The column heads of {@link #row}. */
        public static String header() {
            return String.format(Locale.ROOT, "%-8s %8s %7s %8s %8s %7s %8s %9s %7s", "round", "scenes", "added",
                    "goals", "mix JSD", "stuck", "to ball", "agreement", "Turing");
        }

        /** The teacher's figures in the columns of {@link #row} that it has ("-": not measured). */
        public String teacherRow() {
            return String.format(Locale.ROOT, "%-8s %8s %7s %8s %8s %7s %8s %9s %7s", "teacher", "", "",
                    cell(figure("goalsPer1000", true), 1, "%.2f"), "", cell(figure("stuckShare", true), 100, "%.1f%%"),
                    cell(figure("ballDistance", true), 1, "%.1f"), "", "");
        }

        /**
         * Goals per 1000 cycles, action-mix JSD, stuck share, distance to the ball, agreement, Turing
         * accuracy ("-": not measured, such as the stuck share of an external teacher without traces).
         */
        public String row() {
            return String.format(Locale.ROOT, "%-8d %8d %7d %8s %8.4f %7s %8s %9s %6.1f%%", number, scenes,
                    added, cell(figure("goalsPer1000", false), 1, "%.2f"), divergence(),
                    cell(figure("stuckShare", false), 100, "%.1f%%"), cell(figure("ballDistance", false), 1, "%.1f"),
                    cell(figure("agreement", false), 100, "%.1f%%"), 100 * comparison.turing().accuracy());
        }

        /**
         * The action mix's divergence from the teacher's: of the commands sent on sees when both were
         * traced, else of the commands the server's logs show executed (an external teacher).
         */
        private double divergence() {
            double sent = comparison.divergence().mean();
            return Double.isNaN(sent) ? comparison.executedDivergence().mean() : sent;
        }

        /** A figure for JSON: null when it was not measured. */
        private static Double measured(double value) {
            return Double.isNaN(value) ? null : value;
        }

        private static String cell(double value, double scale, String format) {
            return Double.isNaN(value) ? "-" : String.format(Locale.ROOT, format, scale * value);
        }

        /** The row's figures by name, for JSON. */
        public Map<String, Object> json() {
            Map<String, Object> json = new LinkedHashMap<>();
            json.put("round", number);
            json.put("scenes", scenes);
            json.put("added", added);
            json.put("labelled", labelled);
            json.put("goalsPer1000", measured(figure("goalsPer1000", false)));
            json.put("divergence", divergence());
            json.put("stuckShare", measured(figure("stuckShare", false)));
            json.put("ballDistance", measured(figure("ballDistance", false)));
            json.put("agreement", measured(figure("agreement", false)));
            json.put("turing", comparison.turing().accuracy());
            return json;
        }

        /** The figure's mean, NaN when it was not measured. */
        private double figure(String key, boolean teacher) {
            if (!comparison.has(key)) {
                return Double.NaN;
            }
            Comparison.Figure figure = comparison.figure(key);
            return (teacher ? figure.teacher() : figure.imitator()).mean();
        }
    }

    private final Evaluation.Plan plan;
    private final double thinkSteps;
    private Learner.Imitator imitator;
    private int added;
    /** The last round's labelled scenes, one sequence per imitating player and game. */
    private List<ShadowLabels> corrections = List.of();
    private List<PlayedGame> teacherGames;
    private int rounds;

    /**
     * Rounds on {@code plan}'s teacher, opponent, cycles and seeds (its imitator is not used),
     * starting from {@code imitator} (with its roles, when it has them: each player's labels join
     * its counterpart's knowledge too); the imitator decides every {@code thinkSteps} steps
     * ({@link PacedBrain}).
     */
    public Dagger(Evaluation.Plan plan, Learner.Imitator imitator, double thinkSteps) {
        if (plan.shadow() == null) {
            throw new IllegalArgumentException("DAgger labels with a shadow teacher: the teacher in process, or an"
                    + " external one beside each imitating player");
        }
        if (!PacedBrain.valid(thinkSteps)) {
            throw new IllegalArgumentException("think steps must be 0, or 1 or more, not " + PacedBrain.text(thinkSteps));
        }
        this.plan = plan;
        this.imitator = imitator;
        this.thinkSteps = thinkSteps;
    }

    /** Game cycles the next round plays, for progress: the first round plays the teacher's games too. */
    public long nextRoundCycles() {
        return (teacherGames == null ? 2L : 1L) * plan.seeds().size() * plan.cycles();
    }

    /**
     * Adds the previous round's labelled scenes (none before the first round) to the knowledge
     * base, plays the round's games and labels the imitator's scenes; {@code progress} gets the
     * cycles played so far in the round.
     */
    public Round next(Arena arena, LongConsumer progress) throws IOException {
        if (!corrections.isEmpty()) {
            Map<Integer, List<List<Scene>>> byPlayer = new TreeMap<>();
            for (ShadowLabels player : corrections) {
                byPlayer.computeIfAbsent(player.unum(), unum -> new ArrayList<>()).add(player.labelled());
            }
            imitator = imitator.plus(byPlayer);
        }
        boolean first = teacherGames == null;
        List<PlayedGame> teacher = first ? new ArrayList<>() : teacherGames;
        List<PlayedGame> imitating = new ArrayList<>();
        List<ShadowLabels> labelled = new ArrayList<>();
        long[] done = {0};
        for (long seed : plan.seeds()) {
            if (first) {
                teacher.add(Evaluation.play(PlayedGame.Role.TEACHER, plan.teacher(), null, plan, seed, arena, done,
                        progress));
            }
            Labelling labelling = new Labelling(imitator.brains(), plan.shadow(), thinkSteps);
            GameSetup.Team team = new GameSetup.Team(plan.teacher().name(), plan.teacher().players(),
                    labelling.imitator());
            imitating.add(Evaluation.play(PlayedGame.Role.IMITATOR, team, labelling.shadow(), plan, seed, arena, done,
                    progress));
            labelled.addAll(labelling.players);
        }
        teacherGames = teacher;
        Evaluation.Results results = new Evaluation.Results(teacher, imitating);
        Round round = new Round(rounds++, imitator.scenes(), added,
                labelled.stream().mapToInt(player -> player.labelled().size()).sum(),
                Comparison.of(results), results);
        corrections = labelled;
        added = round.labelled();
        return round;
    }

    /** The scenes the last round labelled, one sequence per imitating player and game, in seed and uniform number order. */
    List<List<Scene>> corrections() {
        return corrections.stream().map(ShadowLabels::labelled).toList();
    }

    /**
     * One imitating player's scenes of one game of the last round, labelled with its shadow's replies.
     *
     * @param unum the player's uniform number
     * @param goalie whether it kept goal
     * @param scenes the labelled scenes, in cycle order
     */
    public record Correction(int unum, boolean goalie, List<Scene> scenes) {
    }

    /** The last round's labelled scenes, player by player and game by game, as they join the next round's knowledge. */
    public List<Correction> labelled() {
        return corrections.stream().map(player -> new Correction(player.unum(), imitator.brains().goalie(player.unum()),
                player.labelled())).toList();
    }

    /** The grid of the imitator's scenes, labelled ones included. */
    public Grid grid() {
        return imitator.knowledge().grid();
    }

    /**
     * One game's imitating players and their shadows, each pair sharing one {@link ShadowLabels}.
     * {@link Evaluation#traced} makes each player's shadow right after its driver.
     */
    private static final class Labelling {
        final List<ShadowLabels> players = new ArrayList<>();
        private final BrainFactory imitation;
        private final BrainFactory teacher;
        private final double thinkSteps;

        Labelling(BrainFactory imitation, BrainFactory teacher, double thinkSteps) {
            this.imitation = imitation;
            this.teacher = teacher;
            this.thinkSteps = thinkSteps;
        }

        BrainFactory imitator() {
            return new BrainFactory() {
                @Override
                public Brain create(String team, Random random) {
                    ShadowLabels labels = new ShadowLabels();
                    players.add(labels);
                    Brain brain = imitation.create(team, random);
                    ImitationBrain imitating = Viewing.imitation(brain);
                    if (imitating != null) {
                        imitating.onScene(labels::built);
                    }
                    return labels.imitator(PacedBrain.pace(brain, thinkSteps));
                }

                @Override
                public boolean goalie(int unum) {
                    return imitation.goalie(unum);
                }
            };
        }

        BrainFactory shadow() {
            return (team, random) -> {
                if (players.isEmpty()) {
                    throw new IllegalStateException("a shadow is made after its imitating player");
                }
                return players.get(players.size() - 1).shadow(teacher.create(team, random));
            };
        }
    }
}
