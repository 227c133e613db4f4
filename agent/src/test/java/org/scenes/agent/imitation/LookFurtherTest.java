package org.scenes.agent.imitation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.Observer;
import org.scenes.api.Scene;
import org.scenes.api.Side;
import org.scenes.api.World;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.target.Replay;

/** At k 1, a player under target replay whose one neighbour sends no body command takes a farther neighbour's. */
class LookFurtherTest {
    /** Standing at (-12, 0), facing x+: the centre spot and the ball 12 m ahead, two flags and the goal beyond. */
    private static final String AHEAD = "((f c) 12 0) ((f p r t) 52.1 -23) ((f p r b) 52.1 23) ((g r) 64.5 0) ((b) 12 0)";

    /**
     * Scenes nearest in stored order: a recorded player that only turned its neck, one placed for a
     * kick-off, then one that turned its body.
     */
    private static List<String> answer(Replay replay) {
        Observer nine = new Observer("Teal", Side.LEFT, 9);
        World world = new World(-12, 0, 0, 0, 0, 0, 8000, 1, 0, 0, 0, 0, 0, 0, List.of(), "play_on", 0, 0);
        List<Scene> scenes = new ArrayList<>();
        scenes.add(new Scene(0, nine, List.of(), List.of(Action.turnNeck(30)), null, 0, world));
        scenes.add(new Scene(1, nine, List.of(), List.of(Action.move(-10, 5)), null, 0, world));
        scenes.add(new Scene(2, nine, List.of(), List.of(Action.turn(90)), null, 0, world));
        Recognizer recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, scenes),
                () -> (query, stored) -> stored.cycle(), 1);
        ImitationBrain brain = new ImitationBrain("Teal", recognizer, ImitationBrainTest.FIRST, List::of,
                new Random(1), ImitationBrain.Guards.OFF, replay);
        List<String> sent = new ArrayList<>();
        brain.receive("(init l 9 play_on)", s -> { });
        brain.receive("(see 1 " + AHEAD + ")", sent::add);
        assertEquals(replay == Replay.TARGET ? 1 : 0, brain.counters().get("looked_further"));
        return sent;
    }

    @Test
    void underTargetReplayTheNearestBodyCommandOtherThanAMoveIsTaken() {
        List<String> sent = answer(Replay.TARGET);
        assertTrue(sent.stream().anyMatch(command -> command.startsWith("(turn ")), "a body turn: " + sent);
    }

    @Test
    void rawReplayKeepsTheRecordedNeckTurn() {
        assertEquals(List.of("(turn_neck 30)"), answer(Replay.RAW));
    }
}
