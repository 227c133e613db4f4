package org.scenes.plugins.history;

import java.util.List;
import java.util.Map;
import org.scenes.api.Action;
import org.scenes.api.ActionLabel;
import org.scenes.api.ActionType;
import org.scenes.api.ObjectKind;
import org.scenes.api.Scene;
import org.scenes.api.SeenObject;

/**
 * A scene as the numbers {@code action-history} compares: its see age, the ball, the size of the
 * last action, and per earlier scene its body class, see age and neck class (-1 when there is no
 * earlier scene that far back).
 */
final class HistoryFeatures {
    private static final List<String> BODY_CLASSES = List.of(ActionLabel.NONE, ActionLabel.NO_OP,
            "dash", "turn", "kick", "catch", "move", "tackle");
    private static final List<String> NECK_CLASSES = List.of(ActionLabel.NONE, ActionLabel.NO_OP, "turn_neck");
    private static final int AGE = 0;
    private static final int BALL_SEEN = 1;
    private static final int BALL_DISTANCE = 2;
    private static final int BALL_DIRECTION = 3;
    private static final int BALL_CHANGE = 4;
    private static final int MAGNITUDE = 5;
    private static final int STEPS = 6;

    private final int depth;
    private final double classWeight;
    private final double[] stepWeights;
    private final double ageWeight;
    private final double ageHistoryWeight;
    private final double neckWeight;
    private final double magnitudeWeight;
    private final double ballDistanceWeight;
    private final double ballDirectionWeight;
    private final double ballChangeWeight;
    private final double ballMissing;

    HistoryFeatures(Map<String, Double> options) {
        depth = (int) (double) options.get("depth");
        classWeight = options.get("class");
        stepWeights = new double[depth];
        for (int i = 0; i < depth; i++) {
            stepWeights[i] = Math.pow(options.get("decay"), i);
        }
        ageWeight = options.get("age");
        ageHistoryWeight = options.get("age-history");
        neckWeight = options.get("neck");
        magnitudeWeight = options.get("magnitude");
        ballDistanceWeight = options.get("ball-distance");
        ballDirectionWeight = options.get("ball-direction");
        ballChangeWeight = options.get("ball-change");
        ballMissing = options.get("ball-missing");
    }

    int width() {
        return STEPS + 3 * depth;
    }

    double[] encode(Scene scene) {
        double[] features = new double[width()];
        features[AGE] = scene.seeAge();
        for (SeenObject object : scene.objects()) {
            if (object.kind() == ObjectKind.BALL) {
                features[BALL_SEEN] = 1;
                features[BALL_DISTANCE] = Double.isNaN(object.distance()) ? 0 : Math.log1p(object.distance());
                features[BALL_DIRECTION] = Double.isNaN(object.direction()) ? 0 : object.direction();
                features[BALL_CHANGE] = Double.isNaN(object.distanceChange()) ? 0 : object.distanceChange();
                break;
            }
        }
        Scene earlier = scene.previous();
        features[MAGNITUDE] = earlier == null ? 0 : magnitude(ActionLabel.bodyAction(earlier.actions()));
        for (int i = 0; i < depth; i++) {
            int at = STEPS + 3 * i;
            if (earlier == null) {
                features[at] = features[at + 1] = features[at + 2] = -1;
                continue;
            }
            features[at] = BODY_CLASSES.indexOf(ActionLabel.BODY.of(earlier.actions()));
            features[at + 1] = earlier.seeAge();
            features[at + 2] = NECK_CLASSES.indexOf(ActionLabel.NECK.of(earlier.actions()));
            earlier = earlier.previous();
        }
        return features;
    }

    /** The size of a body action on a scale of about 0 to 1; 0 without one. */
    private static double magnitude(Action body) {
        if (body == null || Double.isNaN(body.first())) {
            return 0;
        }
        return body.type() == ActionType.TURN ? Math.abs(body.first()) / 180 : Math.abs(body.first()) / 100;
    }

    /** The distance of two encoded scenes. */
    double distance(double[] a, int at, double[] b, int bt) {
        return distance(a, at, b, bt, Double.POSITIVE_INFINITY);
    }

    /**
     * The distance, or some value not below {@code bound} as soon as the sum passes it: the past
     * (the large terms) is summed first, in the same order on every path, so values are identical.
     */
    double distance(double[] a, int at, double[] b, int bt, double bound) {
        double total = a[at + AGE] != b[bt + AGE] ? ageWeight : 0;
        for (int i = 0; i < depth; i++) {
            int x = at + STEPS + 3 * i;
            int y = bt + STEPS + 3 * i;
            double step = 0;
            if (a[x] != b[y]) {
                step += classWeight;
            }
            if (a[x + 1] != b[y + 1]) {
                step += ageHistoryWeight;
            }
            if (a[x + 2] != b[y + 2]) {
                step += neckWeight;
            }
            total += stepWeights[i] * step;
        }
        if (total >= bound) {
            return total;
        }
        total += magnitudeWeight * Math.abs(a[at + MAGNITUDE] - b[bt + MAGNITUDE]);
        boolean ballA = a[at + BALL_SEEN] != 0;
        boolean ballB = b[bt + BALL_SEEN] != 0;
        if (ballA && ballB) {
            total += ballDistanceWeight * Math.abs(a[at + BALL_DISTANCE] - b[bt + BALL_DISTANCE])
                    + ballDirectionWeight * Math.abs(a[at + BALL_DIRECTION] - b[bt + BALL_DIRECTION]) / 180
                    + ballChangeWeight * Math.abs(a[at + BALL_CHANGE] - b[bt + BALL_CHANGE]);
        } else if (ballA != ballB) {
            total += ballMissing;
        }
        return total;
    }
}
