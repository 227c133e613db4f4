package org.scenes.agent.imitation;

import static org.junit.jupiter.api.Assertions.assertEquals;

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

/** Under target replay the team's nearest player runs to the ball of its own team's set play. */
class SetPlayTakerTest {
    /** Standing at (-12, 0), facing x+: the centre spot and the ball 12 m ahead, two flags and the goal beyond. */
    private static final String AHEAD = "((f c) 12 0) ((f p r t) 52.1 -23) ((f p r b) 52.1 23) ((g r) 64.5 0) ((b) 12 0)";

    /** A recorded player that, 12 m from the ball at a kick-off of its own, turned away from it. */
    private static ImitationBrain brain() {
        Observer nine = new Observer("Teal", Side.LEFT, 9);
        List<Scene> scenes = new ArrayList<>();
        for (int t = 0; t < 30; t++) {
            World world = new World(-12, 0, 0, 0, 0, 0, 8000, 1, 0, 0, 0, 0, 0, 0, List.of(), "kick_off_l", 0, 0);
            scenes.add(new Scene(t, nine, List.of(), List.of(Action.turn(90)), null, 0, world));
        }
        Recognizer recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, scenes), () -> (query, stored) -> 0, 1);
        return new ImitationBrain("Teal", recognizer, ImitationBrainTest.FIRST, List::of, new Random(1),
                ImitationBrain.Guards.OFF, Replay.TARGET);
    }

    /** What the player sends at its first see after the referee called {@code mode}. */
    private static List<String> answer(String mode, String seen) {
        return ImitationBrainTest.firstAnswerAfter(brain(), 9, mode, seen);
    }

    @Test
    void theNearestRunsToTheBallOfItsTeamsSetPlay() {
        assertEquals(List.of("(dash 100)"), answer("kick_off_l", AHEAD));
        assertEquals(List.of("(dash 100)"), answer("free_kick_l", AHEAD));
    }

    @Test
    void notAtTheOtherTeamsSetPlayNorWithATeammateNearerTheBall() {
        assertEquals(List.of("(turn 90)"), answer("kick_off_r", AHEAD), "the other team's kick-off: the recorded turn");
        assertEquals(List.of("(turn 90)"), answer("kick_off_l", AHEAD.replace("((b) 12 0)",
                "((b) 12 0) ((p \"Teal\" 10) 2 0)")), "a teammate 10 m nearer the ball takes it");
    }
}
