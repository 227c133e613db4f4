package org.scenes.plugins.history;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.scenes.api.Action;
import org.scenes.api.ActionLabel;
import org.scenes.api.Grid;
import org.scenes.api.Neighbour;
import org.scenes.api.PackedMetric;
import org.scenes.api.PluginConfig;
import org.scenes.api.PluginException;
import org.scenes.api.PluginRegistry;
import org.scenes.api.Scene;
import org.scenes.api.SceneMetric;
import org.scenes.api.TopK;
import org.scenes.internal.match.KnowledgeBase;
import org.scenes.internal.match.Recognizer;
import org.scenes.internal.validate.MatchConfig;
import org.scenes.internal.validate.ValidationReport;
import org.scenes.internal.validate.Validator;

class ActionHistoryTest {
    private static final PluginConfig NO_BALL = PluginConfig.DEFAULT.withOptions(Map.of("ball-distance", "0",
            "ball-direction", "0", "ball-change", "0", "ball-missing", "0"));

    private static List<Scene> remembered(List<Scene> scenes) {
        return KnowledgeBase.transform(scenes, List.of(new HistoryTransformProvider().create(PluginConfig.DEFAULT)));
    }

    @Test
    void scenesDifferByWhatWasDoneBeforeThem() {
        SceneMetric metric = new ActionHistoryMetricProvider().create(NO_BALL);
        Scene now = Synthetic.scene(3, 0, 5, Action.dash(100), null);
        Scene afterTurns = remembered(List.of(Synthetic.scene(1, 0, 5, Action.turn(30), null),
                Synthetic.scene(2, 1, 5, Action.turn(30), null), now)).get(2);
        Scene afterNoOp = remembered(List.of(Synthetic.scene(1, 0, 5, Action.turn(30), null),
                Synthetic.scene(2, 1, 5, Action.turn(0), null), now)).get(2);
        Scene longerTurn = remembered(List.of(Synthetic.scene(1, 0, 5, Action.turn(30), null),
                Synthetic.scene(2, 1, 5, Action.turn(120), null), now)).get(2);
        assertEquals(0, metric.distance(afterTurns, afterTurns));
        // one step back: the class (turn against noop) 16, its neck 0 (both none), and the size 30/180 * 4
        assertEquals(16 + 4 * 30 / 180.0, metric.distance(afterTurns, afterNoOp), 1e-12);
        assertEquals(4 * 90 / 180.0, metric.distance(afterTurns, longerTurn), 1e-12, "same classes: the size tells");
        assertEquals(metric.distance(afterNoOp, afterTurns), metric.distance(afterTurns, afterNoOp));
        // two steps back differ only: decay 0.5 of (class 16 + age 1)
        Scene otherStart = remembered(List.of(Synthetic.scene(1, 1, 5, Action.dash(30), null),
                Synthetic.scene(2, 1, 5, Action.turn(30), null), now)).get(2);
        assertEquals(0.5 * (16 + 1), metric.distance(afterTurns, otherStart), 1e-12);
    }

    @Test
    void theBallCountsWhenWeighted() {
        SceneMetric metric = new ActionHistoryMetricProvider().create(PluginConfig.DEFAULT);
        Scene near = Synthetic.scene(1, 0, 1, Action.dash(100), null);
        Scene far = Synthetic.scene(1, 0, Math.E * Math.E - 1, Action.dash(100), null);
        assertEquals(Math.log(Math.E * Math.E) - Math.log(2), metric.distance(near, far), 1e-12);
        Scene none = new Scene(1, Synthetic.OBSERVER, List.of(), List.of(Action.dash(100)), null, 0);
        assertEquals(2, metric.distance(near, none), 1e-12, "ball-missing");
    }

    @Test
    void thePackedScanOffersTheDistancesOfTheSceneMetric() {
        PackedMetric metric = (PackedMetric) new ActionHistoryMetricProvider().create(PluginConfig.DEFAULT);
        List<Scene> stored = remembered(Synthetic.game(3, 600));
        List<Scene> queries = remembered(Synthetic.game(4, 40));
        PackedMetric.PackedScenes packed = metric.pack(stored);
        Random random = new Random(5);
        for (Scene query : queries) {
            int k = 1 + random.nextInt(20);
            TopK top = new TopK(k);
            packed.scan(query, top);
            List<double[]> exhaustive = new ArrayList<>();
            for (int i = 0; i < stored.size(); i++) {
                exhaustive.add(new double[] {metric.distance(query, stored.get(i)), i});
            }
            exhaustive.sort((a, b) -> a[0] != b[0] ? Double.compare(a[0], b[0]) : Double.compare(a[1], b[1]));
            Recognizer recognizer = new Recognizer(KnowledgeBase.of(Grid.DEFAULT, stored), () -> metric, k);
            List<Neighbour> nearest = recognizer.nearest(query);
            assertEquals(k, top.size());
            // the recognizer splits by see age; compare within the query's age
            List<double[]> sameAge = exhaustive.stream().filter(e -> stored.get((int) e[1]).seeAge() == query.seeAge())
                    .limit(k).toList();
            for (int i = 0; i < k; i++) {
                assertEquals(sameAge.get(i)[0], nearest.get(i).distance(), "rank " + i);
                assertEquals((int) sameAge.get(i)[1], nearest.get(i).index(), "rank " + i);
            }
        }
    }

    @Test
    void badOptionsAreRefused() {
        ActionHistoryMetricProvider provider = new ActionHistoryMetricProvider();
        assertThrows(PluginException.class, () -> provider.create(PluginConfig.DEFAULT.withOptions(Map.of("depth", "9"))));
        assertThrows(PluginException.class, () -> provider.create(PluginConfig.DEFAULT.withOptions(Map.of("depth", "1.5"))));
        assertThrows(PluginException.class, () -> provider.create(PluginConfig.DEFAULT.withOptions(Map.of("class", "-1"))));
    }

    @Test
    void onPlansOverSeveralCyclesTheHistoryBeatsRepeatingTheLastAction() {
        PluginRegistry registry = PluginRegistry.load();
        MatchConfig config = MatchConfig.DEFAULT.withMetric("action-history", Map.of()).withK(25)
                .withSelector("body-vote", Map.of());
        config = new MatchConfig(config.metric(), config.metricOptions(), config.objectWeights(), config.actionWeights(),
                config.k(), config.selector(), config.selectorOptions(), List.of("history"), config.seed());
        List<Scene> train = new ArrayList<>();
        for (int player = 1; player <= 3; player++) {
            train.addAll(remembered(Synthetic.game(player, 2000)));
        }
        List<Scene> test = remembered(Synthetic.game(99, 2000));
        ValidationReport report = Validator.run(KnowledgeBase.of(Grid.DEFAULT, train), test, config, registry, false, () -> { });
        double body = report.accuracy(ActionLabel.BODY);
        double repeat = report.repeatPreviousBaseline(ActionLabel.BODY);
        assertTrue(body > repeat + 0.10, "body " + body + " against repeat previous " + repeat);

        MatchConfig forgetful = new MatchConfig(config.metric(), config.metricOptions(), config.objectWeights(),
                config.actionWeights(), config.k(), config.selector(), config.selectorOptions(), List.of(), config.seed());
        ValidationReport without = Validator.run(KnowledgeBase.of(Grid.DEFAULT, Synthetic.game(1, 2000)),
                Synthetic.game(99, 2000), forgetful, registry, false, () -> { });
        assertTrue(without.accuracy(ActionLabel.BODY) < repeat, "without the transform the past is empty: "
                + without.accuracy(ActionLabel.BODY));
    }
}
