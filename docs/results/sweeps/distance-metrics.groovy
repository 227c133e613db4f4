// Distance metrics on the shared Krislet data, laid out like the thesis' table of metrics: one
// row per metric, the cross-validated figures as columns. The script version of ball-goal
// runs beside the Java one and must give the same numbers. Regenerate (from the repository
// root, with the shared data beside it; see docs/results/README.md):
//   scenes experiment docs/results/sweeps/distance-metrics.groovy --out-dir docs/results
title 'Distance metrics (Krislet classic game 1, 5 folds, k = 1, first-valid)'

for (int player = 1; player <= 5; player++) {
    data "build/krislet/classic-game1/Carleton_${player}.json.gz".toString()
}
metrics 'random', 'continuous', 'cell', 'projection', 'ball-goal', 'script:examples/scripts/ball-goal.groovy'
k 1
selectors 'first-valid'
table measures: ['accuracy', 'directionAccuracy', 'macroF1', 'kickRecall']
