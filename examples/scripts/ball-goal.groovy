// The built-in `ball-goal` metric written as a script: it gives the same distances.
//   scenes validate --metric script:examples/scripts/ball-goal.groovy ...
// Only the ball and the opponent's goal count. For each: where it is in the grid (a change of
// distance row costs ROW, a change of column COLUMN: near or far decides between kicking and
// dashing) plus ANGLE per degree its direction moved, at most 2 MISSING; an object only one
// scene sees costs MISSING. The ball and goal object weights scale the two parts.
//
// This is the fast form of a metric script: encode() turns each scene into numbers once, and
// distance() compares two encodings with arithmetic only, millions of times per validation.
import groovy.transform.Field

@Field static final double ROW = 3
@Field static final double COLUMN = 1
@Field static final double ANGLE = 0.05
@Field static final double MISSING = 10

/** [seen, column, row, direction] of the ball, then of the opponent goal; the first of each listed. */
double[] encode(Scene scene) {
    double[] features = new double[8]
    for (SeenObject object : scene.objects()) {
        int offset
        if (object.kind() == ObjectKind.BALL) {
            offset = 0
        } else if (object.kind() == ObjectKind.GOAL && object.relation() == Relation.OPPONENT) {
            offset = 4
        } else {
            continue
        }
        if (features[offset] == 0) {
            features[offset] = 1
            features[offset + 1] = object.cell().column()
            features[offset + 2] = object.cell().row()
            features[offset + 3] = Double.isNaN(object.direction()) ? 0 : object.direction()
        }
    }
    return features
}

double distance(double[] query, double[] stored, double bound) {
    return weights.ball() * part(query, stored, 0) + weights.goal() * part(query, stored, 4)
}

double part(double[] x, double[] y, int offset) {
    boolean inX = x[offset] != 0
    boolean inY = y[offset] != 0
    if (inX != inY) {
        return MISSING
    }
    if (!inX) {
        return 0
    }
    double cost = COLUMN * Math.abs(x[offset + 1] - y[offset + 1]) + ROW * Math.abs(x[offset + 2] - y[offset + 2]) \
            + ANGLE * Math.abs(x[offset + 3] - y[offset + 3])
    return Math.min(cost, 2 * MISSING)
}

/** Each part is a metric (a missing object is a point MISSING away from all others), so the sum is too. */
boolean isTrueMetric() {
    return true
}
