package org.scenes.agent.imitation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ActionSelector;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;

/** The loop guards overrule the selector only where they must, and count each time. */
class GuardsTest {
    private static final ActionSelector FIRST = (nearest, random) -> nearest.get(0).scene().primaryAction();

    /** Three stored scenes by ball distance: 5 m kick, 6 m dash, 7 m turn. */
    private static Recognizer recognizer() {
        List<Scene> scenes = new ArrayList<>();
        scenes.add(scene(5, Action.kick(100, 0)));
        scenes.add(scene(6, Action.dash(40)));
        scenes.add(scene(7, Action.turn(30)));
        return new Recognizer(KnowledgeBase.of(Grid.DEFAULT, scenes), () -> ImitationBrainTest.BALL, 3);
    }

    private static Scene scene(double ball, Action action) {
        return new Scene(1, Observer.UNKNOWN, List.of(SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, ball, 0,
                Grid.DEFAULT)), List.of(action));
    }

    private static List<String> play(ImitationBrain brain, String... messages) {
        List<String> sent = new ArrayList<>();
        brain.receive("(init l 2 before_kick_off)", sent::add);
        for (String message : messages) {
            brain.receive(message, sent::add);
        }
        return sent;
    }

    @Test
    void withoutGuardsTheSelectorsChoiceStands() {
        ImitationBrain brain = new ImitationBrain("T", recognizer(), FIRST, List::of, new Random(1));
        List<String> sent = play(brain, "(see 1 ((b) 5 0))", "(see 2 ((b) 5 0))", "(see 3 ((b) 5 0))");
        assertEquals(List.of("(kick 100 0)", "(kick 100 0)", "(kick 100 0)"), sent);
        assertEquals(null, brain.counters().get("guard.kick_out_of_reach"));
    }

    @Test
    void noKickWithTheBallOutOfReachAndAnotherActionWhenStuck() {
        ImitationBrain brain = new ImitationBrain("T", recognizer(), FIRST, List::of, new Random(1),
                new ImitationBrain.Guards(true, 3));
        // the ball 5 m away is out of reach: the nearest neighbour that is no kick dashes
        List<String> sent = play(brain, "(see 1 ((b) 5 0))", "(see 2 ((b) 5 0))", "(see 3 ((b) 5 0))",
                "(see 4 ((b) 5 0))", "(see 5 ((b) 5.5 0))");
        // three dashes left the view unchanged: the third see takes the next other action, the turn
        assertEquals(List.of("(dash 40)", "(dash 40)", "(turn 30)", "(dash 40)", "(dash 40)"), sent);
        assertEquals(5L, brain.counters().get("guard.kick_out_of_reach"));
        assertEquals(1L, brain.counters().get("guard.stuck"));
    }

    @Test
    void aKickWithinReachIsKept() {
        ImitationBrain brain = new ImitationBrain("T", recognizer(), FIRST, List::of, new Random(1), ImitationBrain.Guards.ON);
        // the server's own reach: 0.3 + 0.085 + 4.7 = 5.085 m, so the ball at 5 m is kickable
        List<String> sent = play(brain, "(server_param (player_size 0.3)(ball_size 0.085)(kickable_margin 4.7))",
                "(see 1 ((b) 5 0))");
        assertEquals(List.of("(kick 100 0)"), sent);
        assertEquals(0L, brain.counters().get("guard.kick_out_of_reach"));
    }
}
