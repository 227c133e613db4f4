// A weighted vote among the k nearest scenes, written as a selector script; it chooses as the
// built-in `vote` selector does (with its default params=copy):
//   scenes validate --selector script:examples/scripts/vote.groovy ...
// Each neighbour votes for the type of its primary action with that type's action weight. The
// type with the most votes wins and the nearest neighbour of that type gives the action (its
// power and direction). On a tie the type whose nearest voter is nearer wins.

Action select(List<Neighbour> nearest, RandomGenerator random) {
    double[] votes = new double[ActionType.values().length]
    for (Neighbour neighbour : nearest) {
        Action action = neighbour.scene().primaryAction()
        if (action != null) {
            votes[action.type().ordinal()] += actionWeights.weight(action.type())
        }
    }
    Action chosen = null
    double best = 0
    for (Neighbour neighbour : nearest) {
        Action action = neighbour.scene().primaryAction()
        if (action != null && votes[action.type().ordinal()] > best) {
            best = votes[action.type().ordinal()]
            chosen = action
        }
    }
    return chosen
}
