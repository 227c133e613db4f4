package org.scenes.internal.validate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ActionLabel;
import org.scenes.api.Neighbour;
import org.scenes.api.Observer;
import org.scenes.api.Scene;
import org.scenes.api.Side;

/** Body, neck and joint labels, no-op commands, and the two baselines beside every accuracy. */
class BaselinesTest {
    private static final Observer PLAYER = new Observer("HELIOS_base", Side.LEFT, 7);

    private static Scene scene(int cycle, Action... actions) {
        return new Scene(cycle, PLAYER, List.of(), List.of(actions));
    }

    @Test
    void labelsSeparateBodyAndNeckAndCommandsThatChangeNothing() {
        List<Action> nothing = List.of(Action.turn(0), Action.turnNeck(0));
        assertEquals("turn", ActionLabel.PRIMARY.of(nothing), "the classic figure is unchanged");
        assertEquals("noop", ActionLabel.BODY.of(nothing));
        assertEquals("noop", ActionLabel.NECK.of(nothing));
        assertEquals("noop+noop", ActionLabel.BOTH.of(nothing));
        List<Action> dash = List.of(Action.dash(76.3, 60), Action.turnNeck(-12));
        assertEquals("dash+turn_neck", ActionLabel.BOTH.of(dash));
        assertEquals("none", ActionLabel.BODY.of(List.of(Action.turnNeck(30))));
        assertEquals("turn_neck", ActionLabel.PRIMARY.of(List.of(Action.turnNeck(30))));
        assertEquals("none+none", ActionLabel.BOTH.of(List.of()));
        assertEquals("dash", ActionLabel.BODY.of(List.of(Action.dash(-0.5))));
        assertEquals("noop", ActionLabel.BODY.of(List.of(Action.kick(0, 45))));
        assertEquals("tackle", ActionLabel.BODY.of(List.of(Action.tackle(0, true))), "a tackle's first is its direction");
    }

    @Test
    void baselinesAreTheTrainingMajorityAndTheRecordedActionBefore() {
        // training: 3 no-op turns, 2 dashes; test: dash dash turn(0) turn(0) dash
        List<Scene> train = List.of(scene(1, Action.turn(0)), scene(2, Action.turn(0)), scene(3, Action.turn(0)),
                scene(4, Action.dash(50)), scene(5, Action.dash(50)));
        List<Scene> test = List.of(scene(10, Action.dash(80, 0), Action.turnNeck(10)),
                scene(11, Action.dash(80, 30), Action.turnNeck(10)),
                scene(12, Action.turn(0), Action.turnNeck(0)), scene(13, Action.turn(0), Action.turnNeck(0)),
                scene(14, Action.dash(20), Action.turnNeck(10)));
        List<List<Action>> predicted = List.of(List.of(Action.dash(80, 10), Action.turnNeck(10)),
                List.of(Action.turn(10)), List.of(Action.turn(0), Action.turnNeck(5)), List.of(),
                List.of(Action.dash(20, -170), Action.turnNeck(10)));
        ValidationReport report = ValidationReport.of(train, test, predicted, new long[5]);

        assertEquals(3 / 5.0, report.accuracy(ActionLabel.PRIMARY), 1e-12);
        assertEquals(3 / 5.0, report.accuracy(), 1e-12, "accuracy() is the primary label");
        assertEquals(3 / 5.0, report.accuracy(ActionLabel.BODY), 1e-12);
        assertEquals("noop", report.majorityClass(ActionLabel.BODY));
        assertEquals(2 / 5.0, report.majorityBaseline(ActionLabel.BODY), 1e-12);
        assertEquals("turn", report.majorityClass(ActionLabel.PRIMARY));
        // previous: none, dash(=), noop(!=dash), noop(=), noop(!=dash)
        assertEquals(2 / 5.0, report.repeatPreviousBaseline(ActionLabel.BODY), 1e-12);
        // neck truth: turn_neck turn_neck noop noop turn_neck; predicted: turn_neck none turn_neck none turn_neck
        assertEquals(2 / 5.0, report.accuracy(ActionLabel.NECK), 1e-12);
        assertEquals("none", report.majorityClass(ActionLabel.NECK));
        assertEquals(0, report.majorityBaseline(ActionLabel.NECK));
        assertEquals(2 / 5.0, report.repeatPreviousBaseline(ActionLabel.NECK), 1e-12);
        assertEquals(2 / 5.0, report.accuracy(ActionLabel.BOTH), 1e-12);
        // dash directions: |0-10| and |0-(-170)| wrapped = 170
        assertEquals((10 + 170) / 2.0, report.dashDirectionError(), 1e-12);
        assertEquals((0 + 5 + 0) / 3.0, report.neckAngleError(), 1e-12);
        assertEquals(Map.of("dash", 3, "noop", 2), report.classCounts(ActionLabel.BODY));

        ValidationReport pooled = ValidationReport.pooled(List.of(report, report));
        assertEquals(report.repeatPreviousBaseline(ActionLabel.BODY), pooled.repeatPreviousBaseline(ActionLabel.BODY));
        assertEquals(report.majorityBaseline(ActionLabel.BOTH), pooled.majorityBaseline(ActionLabel.BOTH));
        Map<String, Object> json = report.toMap();
        @SuppressWarnings("unchecked")
        Map<String, Map<String, Object>> labels = (Map<String, Map<String, Object>>) json.get("labels");
        assertEquals(0.4, labels.get("bodyAccuracy").get("repeatPreviousBaseline"));
        assertEquals("noop", labels.get("bodyAccuracy").get("majorityClass"));
    }

    @Test
    void aNewSequenceHasNoPreviousAction() {
        Observer other = new Observer("HELIOS_base", Side.LEFT, 8);
        List<Scene> test = List.of(scene(5, Action.dash(10)), new Scene(6, other, List.of(), List.of(Action.dash(10))),
                scene(1, Action.dash(10)), scene(2, Action.dash(10)));
        List<List<Action>> predicted = new ArrayList<>();
        test.forEach(s -> predicted.add(s.actions()));
        ValidationReport report = ValidationReport.of(test, test, predicted, new long[4]);
        assertEquals(1 / 4.0, report.repeatPreviousBaseline(ActionLabel.BODY), 1e-12,
                "another player and an earlier cycle start over");
    }

    @Test
    void theNeckPredictionComesFromTheNeighbourHoldingTheSelectedAction() {
        Scene near = scene(1, Action.turn(0), Action.turnNeck(0));
        Scene far = scene(2, Action.dash(50), Action.turnNeck(30));
        List<Neighbour> nearest = List.of(new Neighbour(near, 0, 1), new Neighbour(far, 1, 2));
        assertEquals(List.of(Action.dash(50), Action.turnNeck(30)), Validator.withNeck(Action.dash(50), nearest));
        assertEquals(List.of(Action.turn(0), Action.turnNeck(0)), Validator.withNeck(Action.turn(0), nearest));
        assertEquals(List.of(Action.kick(20, 0), Action.turnNeck(0)), Validator.withNeck(Action.kick(20, 0), nearest),
                "a made-up action takes the nearest scene's neck");
        assertEquals(List.of(), Validator.withNeck(null, nearest));
        assertTrue(Validator.withNeck(Action.turnNeck(30), nearest).size() == 1);
    }
}
