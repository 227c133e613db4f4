package org.scenes.evaluate;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ActionType;
import org.scenes.api.Observer;
import org.scenes.api.Scene;
import org.scenes.simulator.Brain;

class ShadowLabelsTest {
    private static final List<String> MESSAGES = List.of("(init l 1 before_kick_off)", "(player_type (id 0))",
            "(see 1 ((b) 10 0))", "(sense_body 1)", "(see 2 ((b) 9 0))", "(sense_body 2)", "(sense_body 3)",
            "(see 3 ((b) 8 0))", "(sense_body 4)", "(see 4 ((b) 7 0))");

    /** Builds a scene (cycle = see time, its own dash) on each see, and sends that dash. */
    private static Brain imitator(ShadowLabels labels) {
        return (message, send) -> {
            if (message.startsWith("(see ")) {
                int time = Integer.parseInt(message.split(" ")[1]);
                labels.built(new Scene(time, Observer.UNKNOWN, List.of(), List.of(Action.dash(50)), null, 0, null));
                send.accept("(dash 50)");
            }
        };
    }

    /**
     * A teacher that moves before any see, answers see 1 on the next sense_body with a turn, a
     * turn_neck and an extra dash, leaves see 2 unanswered, answers see 3 with only a turn_neck and
     * see 4 at once with a kick.
     */
    private static Brain shadow() {
        int[] sees = {0};
        return (message, send) -> {
            if (message.startsWith("(player_type")) {
                send.accept("(move -10 0)");
            } else if (message.startsWith("(see ")) {
                sees[0]++;
                if (sees[0] == 4) {
                    send.accept("(kick 100 0)");
                }
            } else if (message.startsWith("(sense_body 1)")) {
                send.accept("(turn 30)");
                send.accept("(turn_neck 10)");
                send.accept("(dash 20)");
            } else if (message.startsWith("(sense_body 4)")) {
                send.accept("(turn_neck -20)");
            }
        };
    }

    private static List<Scene> play(boolean shadowFirst) {
        ShadowLabels labels = new ShadowLabels();
        Brain imitator = labels.imitator(imitator(labels));
        Brain shadow = labels.shadow(shadow());
        List<String> sent = new ArrayList<>();
        Consumer<String> nowhere = command -> { };
        for (String message : MESSAGES) {
            if (shadowFirst) {
                shadow.receive(message, nowhere);
                imitator.receive(message, sent::add);
            } else {
                imitator.receive(message, sent::add);
                shadow.receive(message, nowhere);
            }
        }
        assertEquals(4, sent.size(), "the imitator's own commands go out untouched");
        return labels.labelled();
    }

    @Test
    void eachSceneGetsTheShadowsReplyToItsSeeAndUnansweredSeesAreLeftOut() {
        for (boolean shadowFirst : new boolean[] {false, true}) {
            List<Scene> labelled = play(shadowFirst);
            assertEquals(List.of(1, 4), labelled.stream().map(Scene::cycle).toList(), "shadow first: " + shadowFirst);
            assertEquals(List.of(new Action(ActionType.TURN, 30, Double.NaN), new Action(ActionType.TURN_NECK, 10,
                    Double.NaN)), labelled.get(0).actions());
            assertEquals(List.of(new Action(ActionType.KICK, 100, 0)), labelled.get(1).actions());
        }
    }

    @Test
    void theLabelsBelongToTheUniformNumberTheServerGaveTheImitator() {
        ShadowLabels labels = new ShadowLabels();
        Brain imitator = labels.imitator(imitator(labels));
        assertEquals(0, labels.unum(), "unknown before the init is answered");
        imitator.receive("(init r 7 before_kick_off)", command -> { });
        assertEquals(7, labels.unum());
    }

    @Test
    void aSceneBuiltAgainOnTheSameSeeIsLabelledOnce() {
        ShadowLabels labels = new ShadowLabels();
        Brain imitator = labels.imitator((message, send) -> {
            if (message.startsWith("(sense_body")) {
                // a paced imitator deciding again on its latest see
                labels.built(new Scene(7, Observer.UNKNOWN, List.of(), List.of(), null, 0, null));
            }
        });
        Brain shadow = labels.shadow((message, send) -> {
            if (message.startsWith("(see ")) {
                send.accept("(dash 80)");
            }
        });
        for (String message : List.of("(sense_body 6)", "(see 7 ((b) 3 0))", "(sense_body 7)", "(sense_body 8)")) {
            imitator.receive(message, command -> { });
            shadow.receive(message, command -> { });
        }
        List<Scene> labelled = labels.labelled();
        assertEquals(1, labelled.size(), "the scene before any see is dropped, the repeat on see 7 too");
        assertEquals(List.of(new Action(ActionType.DASH, 80, Double.NaN)), labelled.get(0).actions());
    }

    /** A shadow whose replies come later, as a program's on a real-time server: each see's at the next collect. */
    private static final class LateTeacher implements Brain, LateShadow {
        private final List<String> pending = new ArrayList<>();

        @Override
        public void receive(String message, Consumer<String> send) {
            if (message.startsWith("(see 1 ")) {
                pending.add("(turn 30)");
            } else if (message.startsWith("(see 2 ")) {
                pending.add("(kick 100 0)");
            }
        }

        @Override
        public void collect(Consumer<String> send) {
            pending.forEach(send);
            pending.clear();
        }
    }

    @Test
    void aLateShadowsRepliesAnswerTheSeeBeforeTheMessageTheyCameBefore() {
        ShadowLabels labels = new ShadowLabels();
        PlayerTrace trace = new PlayerTrace(1);
        // as Dagger and Evaluation wrap them: the labels' views inside the trace
        Brain player = new TracedBrain(labels.imitator(imitator(labels)), labels.shadow(new LateTeacher()), trace);
        for (String message : List.of("(init l 1 before_kick_off)", "(see 1 ((b) 10 0))", "(see 2 ((b) 9 0))",
                "(sense_body 2)")) {
            player.receive(message, command -> { });
        }
        List<Scene> labelled = labels.labelled();
        assertEquals(List.of(1, 2), labelled.stream().map(Scene::cycle).toList());
        assertEquals(new Action(ActionType.TURN, 30, Double.NaN), labelled.get(0).primaryAction());
        assertEquals(new Action(ActionType.KICK, 100, 0), labelled.get(1).primaryAction());
        assertEquals(List.of("turn", "kick"), trace.decisions().stream().map(d -> d.shadow().head()).toList());
    }
}
