// A metric that compares two scenes by the ball and the opponent's goal only, the idea of the
// built-in `ball-goal` metric, written as a script:
//   scenes validate --metric script:examples/scripts/ball-goal.groovy ...
// For each of the two objects: where it is in the grid (a change of distance row counts twice
// as much as a change of angle column, since near or far decides between kicking and dashing)
// plus how far its direction moved. An object one scene sees and the other does not costs
// MISSING; the object weights (ball, goal) scale the two parts.
import groovy.transform.Field

@Field static final double ROW_WEIGHT = 2
@Field static final double MISSING = 10
/** Degrees of direction difference that count as much as one column. */
@Field static final double DEGREES_PER_COLUMN = 18

double distance(Scene query, Scene stored) {
    double total = 0
    if (weights.ball() > 0) {
        total += weights.ball() * compare(find(query, ObjectKind.BALL, Relation.NONE), find(stored, ObjectKind.BALL, Relation.NONE))
    }
    if (weights.goal() > 0) {
        total += weights.goal() * compare(find(query, ObjectKind.GOAL, Relation.OPPONENT), find(stored, ObjectKind.GOAL, Relation.OPPONENT))
    }
    return total
}

/** The first object of a kind and relation, or null when the scene has none. */
SeenObject find(Scene scene, ObjectKind kind, Relation relation) {
    for (SeenObject object : scene.objects()) {
        if (object.kind() == kind && object.relation() == relation) {
            return object
        }
    }
    return null
}

double compare(SeenObject a, SeenObject b) {
    if (a == null || b == null) {
        return a == null && b == null ? 0 : MISSING
    }
    double cells = ROW_WEIGHT * Math.abs(a.cell().row() - b.cell().row()) + Math.abs(a.cell().column() - b.cell().column())
    double turn = Math.abs(a.direction() - b.direction())
    // A direction the server did not send (NaN) leaves only the cells to compare.
    return Double.isNaN(turn) ? cells : cells + turn / DEGREES_PER_COLUMN
}
