package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;
import org.scenes.simulator.Brain;
import org.scenes.simulator.GameSetup;
import org.scenes.simulator.teacher.Teachers;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Grid;
import org.scenes.api.Observer;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.Side;
import org.scenes.internal.gamelog.GameFrame;
import org.scenes.internal.gamelog.PlayerState;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.validate.MatchConfig;

/**
 * An imitator does not send kick-off moves its teacher never sent (issue 29.5): the real Krislet
 * client moves once, before its first see, so its scenes hold no move, and its imitator must not
 * be placed again by the runtime after half time and goals; the executed move share would part
 * from the teacher's for nothing the teacher did.
 */
class KickOffMovesTest {
    private static final Learner.Matching MATCHING = Learner.Matching.of(
            MatchConfig.DEFAULT.withMetric("ball-goal", Map.of()), PluginRegistry.load());

    /** The moves each left player executed in the game, by uniform number. */
    private static List<Integer> moves(PlayedGame game) {
        GameFrame last = game.frames().get(game.frames().size() - 1);
        return last.players().stream().filter(p -> p.side() == Side.LEFT)
                .sorted(java.util.Comparator.comparingInt(PlayerState::unum)).map(p -> p.counts().move()).toList();
    }

    private static Scene scene(int cycle, Action action) {
        return new Scene(cycle, Observer.UNKNOWN, List.of(), List.of(action), null, 0, null);
    }

    private static KnowledgeBase knowledge(Action... actions) {
        List<Scene> scenes = new java.util.ArrayList<>();
        for (int i = 0; i < actions.length; i++) {
            scenes.add(scene(i + 1, actions[i]));
        }
        return KnowledgeBase.of(Grid.DEFAULT, scenes);
    }

    @Test
    void anImitatorRepeatsItsKickOffMoveOnlyWhenItsTeacherMoved() {
        Brain still = Learner.of(knowledge(Action.dash(60), Action.turn(30)), MATCHING).brains()
                .create("Teal", new Random(1));
        // the real Krislet client's one placement may come after its first see: a scene at time 0
        Brain placedOnce = Learner.of(KnowledgeBase.of(Grid.DEFAULT, List.of(scene(0, Action.move(-10, 5)),
                scene(1, Action.dash(60)))), MATCHING).brains().create("Teal", new Random(1));
        assertFalse(placedOnce.repeatsKickOffMove());
        Brain moving = Learner.of(knowledge(Action.dash(60), Action.move(-10, 0)), MATCHING).brains()
                .create("Teal", new Random(1));
        assertFalse(still.repeatsKickOffMove());
        assertTrue(moving.repeatsKickOffMove());
    }

    @Test
    void aPlacementBeforeTheKickOffIsNotMatchedInPlayUnlessTheTeacherPlacedItselfAgain() {
        // matched in play, the real Krislet's placement (a scene at time 0) made an imitator send moves the
        // server ignores, every decision, for hundreds of cycles
        KnowledgeBase placedOnce = KnowledgeBase.of(Grid.DEFAULT, List.of(scene(0, Action.move(-10, 5)),
                scene(1, Action.dash(60)), scene(2, Action.turn(30))));
        Learner.Imitator imitator = Learner.of(placedOnce, MATCHING);
        assertEquals(2, imitator.scenes());
        assertTrue(imitator.knowledge().scenes().stream().noneMatch(s -> s.actionType() == ActionType.MOVE));
        KnowledgeBase placedAgain = KnowledgeBase.of(Grid.DEFAULT, List.of(scene(0, Action.move(-10, 5)),
                scene(1, Action.dash(60)), scene(300, Action.move(-10, 5))));
        assertEquals(3, Learner.of(placedAgain, MATCHING).scenes(), "a teacher placed again keeps its moves");
    }

    @Test
    void theTracedAndTheLiveWrappersKeepTheDriversAnswer() {
        Brain declines = new Brain() {
            @Override
            public void receive(String message, Consumer<String> send) {
            }

            @Override
            public boolean repeatsKickOffMove() {
                return false;
            }
        };
        assertFalse(new TracedBrain(declines, null, new PlayerTrace(1)).repeatsKickOffMove());
        assertTrue(new TracedBrain((m, s) -> { }, null, new PlayerTrace(1)).repeatsKickOffMove());
        Brain live = LiveArena.seeded((team, random) -> declines, 1, Side.LEFT,
                new LiveArena.Scoreboard(), new java.util.concurrent.atomic.AtomicInteger(),
                new java.util.concurrent.atomic.AtomicReference<>(), line -> { }).create("Teal", new Random(1));
        live.receive("(init l 1 before_kick_off)", command -> { });
        assertFalse(live.repeatsKickOffMove(), "the live runtime's wrapper, once its brain is made");
    }

    @Test
    void inTheSimulatorTheImitatorOfATeacherThatNeverMovedIsNotPlacedAgainAtHalfTime() throws IOException {
        GameSetup.Team teacher = new GameSetup.Team("Teal", 2, Teachers.byName("krislet"));
        GameSetup.Team opponent = new GameSetup.Team("Amber", 2, Teachers.byName("krislet"));
        Learner.Imitator imitator = Learner.of(knowledge(Action.dash(60), Action.turn(30)), MATCHING);
        // 400 cycles: half time at 200, after which the runtime places each player again (the teacher's default)
        Evaluation.Plan plan = new Evaluation.Plan(teacher, imitator.brains(), opponent, 400, List.of(1L));
        Evaluation.Results results = Evaluation.run(plan, Arena.embedded(), done -> { });
        // each player's executed moves in the last frame: its first placement, then the two cycles after half time if placed again
        assertEquals(List.of(3, 3), moves(results.teacher().get(0)), "the built-in teacher is placed again");
        assertEquals(List.of(1, 1), moves(results.imitator().get(0)));
    }
}
