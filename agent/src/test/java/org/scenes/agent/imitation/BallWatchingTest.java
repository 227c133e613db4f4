package org.scenes.agent.imitation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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

/** Under target replay a player keeps its ball as fresh as its teacher did, widening its view for a ball behind. */
class BallWatchingTest {
    /** Standing at (-12, 0), facing x+: the centre spot 12 m ahead, two flags and the goal beyond. */
    private static final String FLAGS = "((f c) 12 0) ((f p r t) 52.1 -23) ((f p r b) 52.1 23) ((g r) 64.5 0)";

    /** A recorded player that saw its ball every cycle of play, 30 m to its left, and dashed towards the goal. */
    private static ImitationBrain brain(Replay replay) {
        Observer nine = new Observer("Teal", Side.LEFT, 9);
        List<Scene> scenes = new ArrayList<>();
        for (int t = 0; t < 30; t++) {
            World world = new World(-12, 0, 0, 0, 0, 0, 8000, 1, 0, -12, 30, 0, 0, 0, List.of(), "play_on", 0, 0);
            scenes.add(new Scene(t, nine, List.of(), List.of(Action.dash(60)), null, 0, world));
        }
        Recognizer recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, scenes), () -> (query, stored) -> 0, 1);
        return new ImitationBrain("Teal", recognizer, ImitationBrainTest.FIRST, List::of, new Random(1),
                ImitationBrain.Guards.OFF, replay);
    }

    /**
     * What the player sends in each of the cycles 1 to 4, on synchronous vision or in real time:
     * the ball 10 m behind it seen at 1 and 4 only.
     */
    private static List<List<String>> play(ImitationBrain brain, boolean synchronous) {
        brain.receive("(init l 9 before_kick_off)", command -> { });
        brain.receive("(server_param (synch_mode " + (synchronous ? 1 : 0) + "))", command -> { });
        brain.receive("(hear 0 referee play_on)", command -> { });
        List<List<String>> cycles = new ArrayList<>();
        for (int t = 1; t <= 4; t++) {
            List<String> sent = new ArrayList<>();
            brain.receive("(sense_body " + t + " (view_mode high narrow))", sent::add);
            brain.receive("(see " + t + " " + FLAGS + (t == 1 || t == 4 ? " ((b) 10 180))" : ")"), sent::add);
            cycles.add(sent);
        }
        return cycles;
    }

    @Test
    void aBallBehindUnseenForLongerThanTheTeacherLetItWidensTheViewUntilItIsSeen() {
        List<List<String>> sent = play(brain(Replay.TARGET), true);
        assertFalse(sent.get(0).stream().anyMatch(command -> command.startsWith("(change_view")), sent.toString());
        assertTrue(sent.get(1).contains("(change_view wide)"), "the ball a cycle old: " + sent);
        assertTrue(sent.get(1).contains("(turn_neck 90)") || sent.get(1).contains("(turn_neck -90)"),
                "the head as far round as it goes: " + sent);
        assertFalse(sent.get(2).stream().anyMatch(command -> command.startsWith("(change_view")), "asked once: " + sent);
        assertEquals("(change_view narrow)", sent.get(3).get(sent.get(3).size() - 1), "seen again: " + sent);
    }

    @Test
    void inRealTimeTheHeadTurnsButTheViewStays() {
        List<List<String>> sent = play(brain(Replay.TARGET), false);
        assertTrue(sent.get(1).contains("(turn_neck 90)") || sent.get(1).contains("(turn_neck -90)"), sent.toString());
        assertFalse(sent.stream().flatMap(List::stream).anyMatch(command -> command.startsWith("(change_view")),
                sent.toString());
    }

    @Test
    void rawReplayLeavesViewAndHeadAlone() {
        for (List<String> cycle : play(brain(Replay.RAW), true)) {
            assertEquals(List.of("(dash 60)"), cycle);
        }
    }
}
