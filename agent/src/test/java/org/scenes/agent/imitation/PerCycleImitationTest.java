package org.scenes.agent.imitation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.Grid;
import org.scenes.api.ObjectKind;
import org.scenes.api.Observer;
import org.scenes.api.Relation;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;
import org.scenes.api.Side;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;

/**
 * A knowledge base of a player that acts every cycle on a see every other cycle (two see ages):
 * in synchronous mode the imitator acts at every (think), on the latest view and its age, with
 * body and neck, as the recorded player did.
 */
class PerCycleImitationTest {
    private static final Observer ME = new Observer("Teal", Side.LEFT, 1);

    private static Scene stored(int age, Action... actions) {
        SeenObject ball = SeenObject.simple(ObjectKind.BALL, "b", Relation.NONE, 20, 0, Grid.DEFAULT);
        return new Scene(10 + age, ME, List.of(ball), List.of(actions), null, age);
    }

    private static ImitationBrain brain(String serverParam) {
        // The same view: dash (and look left) when fresh, turn (and look right) a cycle later.
        KnowledgeBase knowledge = KnowledgeBase.of(Grid.DEFAULT, List.of(
                stored(0, Action.dash(80), Action.turnNeck(-30)),
                stored(1, Action.turn(20), Action.turnNeck(30))));
        Recognizer recognizer = new Recognizer(knowledge, () -> ImitationBrainTest.BALL, 1);
        ImitationBrain brain = new ImitationBrain("Teal", recognizer, ImitationBrainTest.FIRST, List::of, new Random(1));
        brain.receive("(init l 1 before_kick_off)", command -> { });
        brain.receive(serverParam, command -> { });
        return brain;
    }

    @Test
    void synchronousModeActsEveryCycleWithBodyAndNeckByTheAgeOfTheView() {
        ImitationBrain brain = brain("(server_param (player_size 0.3)(synch_mode 1))");
        List<String> sent = new ArrayList<>();
        brain.receive("(sense_body 10 (view_mode high normal))", sent::add);
        brain.receive("(see 10 ((b) 20 0))", sent::add);
        assertEquals(List.of(), sent, "no decision before the cycle's (think)");
        brain.receive("(think)", sent::add);
        assertEquals(List.of("(dash 80)", "(turn_neck -30)"), sent);
        sent.clear();
        brain.receive("(sense_body 11 (view_mode high normal))", sent::add);
        brain.receive("(think)", sent::add);
        assertEquals(List.of("(turn 20)", "(turn_neck 30)"), sent, "no see this cycle: the view is a cycle old");
        assertEquals(2, brain.decisions());
    }

    @Test
    void inRealTimeItAnswersEachSeeAsAFreshView() {
        ImitationBrain brain = brain("(server_param (player_size 0.3)(synch_mode 0))");
        List<String> sent = new ArrayList<>();
        brain.receive("(sense_body 10 (view_mode high normal))", sent::add);
        brain.receive("(see 10 ((b) 20 0))", sent::add);
        assertEquals(List.of("(dash 80)", "(turn_neck -30)"), sent);
    }
}
