// Distance metrics on five players' scene files, laid out like the thesis' table of metrics: one
// row per metric, the cross-validated figures as columns. The script version of ball-goal
// runs beside the Java one and must give the same numbers. Run from the
// repository root (see docs/results/README.md):
//   scenes experiment docs/results/sweeps/distance-metrics.groovy --out-dir my-results

// The scene files: players 1 to 5 of one team, one file each. By default those of the demo's
// first game ('scenes demo' in the repository root writes them); the shipped tables were made
// on the shared Krislet recordings: SWEEP_SCENES=build/krislet/classic-game1/Carleton_
String scenes = System.getenv('SWEEP_SCENES') ?: 'scenes-demo/game1/scenes/Teal_'
title "Distance metrics (${scenes}1 to 5, 5 folds, k = 1, first-valid)".toString()

for (int player = 1; player <= 5; player++) {
    data "${scenes}${player}.json.gz".toString()
}
metrics 'random', 'continuous', 'cell', 'projection', 'ball-goal', 'script:examples/scripts/ball-goal.groovy'
k 1
selectors 'first-valid'
table measures: ['accuracy', 'directionAccuracy', 'macroF1', 'kickRecall']
