package org.scenes.evaluate;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.function.Consumer;
import java.util.function.LongConsumer;
import java.util.function.Supplier;
import java.util.stream.Stream;
import org.scenes.agent.imitation.ImitationBrain;
import org.scenes.agent.imitation.ImitationTeam;
import org.scenes.agent.imitation.Viewing;
import org.scenes.api.ActionSelector;
import org.scenes.api.ActionType;
import org.scenes.api.Grid;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.SceneTransform;
import org.scenes.internal.convert.SceneConverter;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.protocol.ViewWidth;
import org.scenes.internal.target.Replay;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.simulator.Brain;
import org.scenes.simulator.BrainFactory;
import org.scenes.simulator.GameResult;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.Simulator;

/**
 * Learns an imitator from its teacher's own games, in process, through the same steps a user
 * types: simulate (player logs), convert (scenes), knowledge base. The logs go to a temporary
 * directory that is deleted afterwards.
 */
public final class Learner {
    /**
     * The learnt imitator: its brains, the knowledge base they match in (the team's, with roles),
     * its roles or null, and its matching.
     */
    public record Imitator(BrainFactory brains, KnowledgeBase knowledge, ImitationTeam roles, Matching matching) {
        /** How many scenes it learnt from. */
        public int scenes() {
            return knowledge.size();
        }

        /**
         * The imitator with more scenes, by the uniform number of the player that built them
         * (DAgger's labelled sequences): with roles, each player's join its counterpart's too.
         */
        public Imitator plus(Map<Integer, List<List<Scene>>> sequences) {
            if (roles == null) {
                return of(knowledge.plus(sequences.values().stream().flatMap(List::stream).toList(),
                        matching.transforms()), matching);
            }
            return of(roles.plus(sequences, matching.transforms(), matching::recognizer), matching);
        }
    }

    /**
     * How to match: the metric, k, selector and transforms, as made from a configuration, how the
     * chosen action is carried out and the view the players ask for (null: the server's).
     */
    public record Matching(Supplier<SceneMetric> metric, int k,
                           Supplier<ActionSelector> selector,
                           Supplier<List<SceneTransform>> transforms, Replay replay,
                           ViewWidth view) {
        /** Matching on the server's view. */
        public Matching(Supplier<SceneMetric> metric, int k,
                        Supplier<ActionSelector> selector,
                        Supplier<List<SceneTransform>> transforms, Replay replay) {
            this(metric, k, selector, transforms, replay, null);
        }

        /** Matching that sends the recorded commands as they are. */
        public Matching(Supplier<SceneMetric> metric, int k,
                        Supplier<ActionSelector> selector,
                        Supplier<List<SceneTransform>> transforms) {
            this(metric, k, selector, transforms, Replay.RAW);
        }

        /** Nearest scenes in {@code knowledge} as this matching finds them. */
        Recognizer recognizer(KnowledgeBase knowledge) {
            return new Recognizer(knowledge, metric, k, SceneTransform.queryImage(transforms.get()));
        }

        /** The matching a configuration (of {@code validate}, {@code tune}) describes. */
        public static Matching of(MatchConfig config, PluginRegistry registry) {
            config.check(registry);
            return new Matching(config.metricFactory(registry), config.k(), config.selectorFactory(registry),
                    config.transformFactory(registry), config.replay(), config.view());
        }
    }

    private Learner() {
    }

    /**
     * Plays one game per training seed with the teacher on the left against {@code opponent} and
     * learns from the teacher's players' scenes; {@code progress} gets the cycles played so far.
     */
    public static Imitator fromTeacherGames(GameSetup.Team teacher, GameSetup.Team opponent, int cycles,
                                            List<Long> trainingSeeds, Matching matching, LongConsumer progress)
            throws IOException {
        Path directory = Files.createTempDirectory("scenes-evaluate-");
        try {
            KnowledgeBase.Builder builder = KnowledgeBase.builder(Grid.DEFAULT);
            // with world models, so world-model metrics and target replay work on the teacher's games
            SceneConverter converter = SceneConverter.with(Grid.DEFAULT).world(true).build();
            long done = 0;
            for (long seed : trainingSeeds) {
                Path logs = directory.resolve("seed-" + seed);
                long before = done;
                GameResult result = new Simulator(new GameSetup(teacher, opponent, cycles, seed, logs))
                        .run(time -> progress.accept(before + time));
                done += cycles;
                progress.accept(done);
                for (Path log : result.logs()) {
                    if (!log.getFileName().toString().startsWith(teacher.name() + "_")) {
                        continue;
                    }
                    List<Scene> scenes = new ArrayList<>();
                    converter.convert(log, scenes::add);
                    builder.addSequence(scenes, matching.transforms().get());
                }
            }
            return of(builder.build(), matching);
        } finally {
            deleteTree(directory);
        }
    }

    /**
     * An imitator on a knowledge base already built (from scene files, say), every player on all
     * of it; without the teacher's placements and kick-off repeats when it never placed itself again.
     */
    public static Imitator of(KnowledgeBase all, Matching matching) {
        // one pass over the scenes: a knowledge base decodes each on every read
        boolean moved = teacherMoved(all);
        KnowledgeBase knowledge = moved ? all : withoutPlacements(all);
        BrainFactory brains = Viewing.with(ImitationBrain.factory(matching.recognizer(knowledge), matching.selector(),
                matching.transforms(), ImitationBrain.Guards.OFF, matching.replay()), matching.view());
        return new Imitator(moved ? brains : withoutKickOffRepeats(brains), knowledge, null, matching);
    }

    /**
     * An imitation team with roles from scene files (as {@code scenes play} assembles one): each
     * player on its counterpart's or the team's knowledge, with its counterpart's kick-off moves,
     * set-play kicks and goalie flag.
     */
    public static Imitator roles(List<Path> files, Matching matching, ImitationTeam.Knowledge knowledge) {
        return of(ImitationTeam.load(files, matching.transforms(), matching::recognizer, knowledge), matching);
    }

    private static Imitator of(ImitationTeam team, Matching matching) {
        return new Imitator(Viewing.with(team.brains(matching.selector(), matching.transforms(),
                ImitationBrain.Guards.OFF, matching.replay()), matching.view()), team.knowledge(), team, matching);
    }

    /**
     * The knowledge to match in when the teacher never placed itself again: without its placement
     * before the kick-off. The brain places itself when its {@code player_type}s arrive; matched
     * in play, such a scene makes a player send {@code move}s that the server ignores, over and over
     * (the view does not change), where its teacher never sent one.
     */
    private static KnowledgeBase withoutPlacements(KnowledgeBase knowledge) {
        return knowledge.without(scene -> scene.actionType() == ActionType.MOVE);
    }

    /**
     * Whether the teacher placed itself again during its games: a scene after the game's first cycle
     * whose action is a {@code move} (the placement before the kick-off, at time 0, every teacher makes).
     */
    static boolean teacherMoved(KnowledgeBase knowledge) {
        return knowledge.scenes().stream().anyMatch(scene -> scene.cycle() > 0 && scene.actionType() == ActionType.MOVE);
    }

    /**
     * The brains with the runtime's repeats of their kick-off move after goals and half time turned
     * off: an imitator does not send moves its teacher never sent (the real Krislet client moves
     * once, before its first see, so its scenes hold no move).
     */
    static BrainFactory withoutKickOffRepeats(BrainFactory brains) {
        return new BrainFactory() {
            @Override
            public Brain create(String team, Random random) {
                Brain brain = brains.create(team, random);
                return new Brain() {
                    @Override
                    public void receive(String message, Consumer<String> send) {
                        brain.receive(message, send);
                    }

                    @Override
                    public boolean repeatsKickOffMove() {
                        return false;
                    }
                };
            }

            @Override
            public boolean goalie(int unum) {
                return brains.goalie(unum);
            }
        };
    }

    private static void deleteTree(Path directory) throws IOException {
        try (Stream<Path> paths = Files.walk(directory)) {
            for (Path path : paths.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(path);
            }
        }
    }
}
