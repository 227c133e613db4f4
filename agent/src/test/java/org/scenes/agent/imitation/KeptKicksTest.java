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

/** Under target replay a kick that would hand the ball to an opponent gives way to a neighbour's kick that keeps it. */
class KeptKicksTest {
    /** Standing at (-12, 0), facing x+: the centre spot 12 m ahead, two flags and the goal beyond; the ball at the feet. */
    private static final String VIEW = "((f c) 12 0) ((f p r t) 52.1 -23) ((f p r b) 52.1 23) ((g r) 64.5 0) ((b) 0.5 0)";
    /** An opponent 6 m straight ahead. */
    private static final String OPPONENT_AHEAD = " ((p \"Red\" 5) 6 0)";
    /** A teammate 8 m away, 60 degrees to the left. */
    private static final String TEAMMATE_LEFT = " ((p \"Teal\" 7) 8 -60)";

    /** A recorded player at the same spot whose nearest scene kicked straight ahead, the next one 60 degrees left. */
    private static ImitationBrain brain() {
        return brain(-12, Action.kick(60, 0), Action.kick(60, -60));
    }

    /** A recorded player at ({@code x}, 0), facing x+ with the ball 0.5 m ahead, whose scenes in order kicked so. */
    private static ImitationBrain brain(double x, Action... kicks) {
        Observer nine = new Observer("Teal", Side.LEFT, 9);
        World world = new World(x, 0, 0, 0, 0, 0, 8000, 1, 0, x + 0.5, 0, 0, 0, 0, List.of(), "play_on", 0, 0);
        List<Scene> scenes = new ArrayList<>();
        for (int i = 0; i < kicks.length; i++) {
            scenes.add(new Scene(i + 1, nine, List.of(), List.of(kicks[i]), null, 0, world));
        }
        Recognizer recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, scenes), () -> (query, stored) -> 0, 1);
        return new ImitationBrain("Teal", recognizer, ImitationBrainTest.FIRST, List::of, new Random(1),
                ImitationBrain.Guards.OFF, Replay.TARGET);
    }

    private static List<String> firstAnswer(ImitationBrain brain, String seen) {
        return firstAnswer(brain, VIEW, seen);
    }

    private static List<String> firstAnswer(ImitationBrain brain, String view, String seen) {
        brain.receive("(init l 9 play_on)", command -> { });
        brain.receive("(server_param (synch_mode 1))", command -> { });
        List<String> sent = new ArrayList<>();
        brain.receive("(sense_body 1 (view_mode high normal))", sent::add);
        brain.receive("(see 1 " + view + seen + ")", sent::add);
        return sent;
    }

    /** The power and direction of the kick among {@code sent}. */
    private static double[] kick(List<String> sent) {
        String kick = sent.stream().filter(command -> command.startsWith("(kick ")).findFirst()
                .orElseThrow(() -> new AssertionError("no kick in " + sent));
        String[] words = kick.substring(1, kick.length() - 1).split(" ");
        return new double[] {Double.parseDouble(words[1]), Double.parseDouble(words[2])};
    }

    @Test
    void theNearestKickIsSentWhenItKeepsTheBall() {
        ImitationBrain brain = brain();
        double[] kick = kick(firstAnswer(brain, TEAMMATE_LEFT));
        assertEquals(60, kick[0], 1e-6);
        assertEquals(0, kick[1], 1e-6);
        assertEquals(0L, brain.counters().get("kicks_kept_instead"));
    }

    @Test
    void aKickIntoAnOpponentGivesWayToTheNextNeighboursKickToTheOpenTeammate() {
        ImitationBrain brain = brain();
        double[] kick = kick(firstAnswer(brain, OPPONENT_AHEAD + TEAMMATE_LEFT));
        assertEquals(60, kick[0], 1e-6);
        assertEquals(-60, kick[1], 1e-6);
        assertEquals(1L, brain.counters().get("kicks_kept_instead"));
        assertEquals(0L, brain.counters().get("kicks_handed_over"));
    }

    @Test
    void nearTheGoalAKickThatKeepsTheBallGivesWayToANeighboursKickThatScores() {
        // at (30, 0) facing the goal 22.5 m ahead, an opponent 10 m away to the right of the course
        String view = "((f p r c) 6 0) ((f g r t) 23.6 -17.3) ((f g r b) 23.6 17.3) ((g r) 22.5 0) ((b) 0.5 0)";
        ImitationBrain brain = brain(30, Action.kick(30, 90), Action.kick(100, 0));
        double[] kick = kick(firstAnswer(brain, view, " ((p \"Red\" 4) 10 36.9)"));
        assertEquals(100, kick[0], 1e-6);
        assertEquals(0, kick[1], 1.0);
        assertEquals(1L, brain.counters().get("kicks_shot_instead"));
        assertEquals(0L, brain.counters().get("kicks_kept_instead"));
    }
}
