// Number of neighbours and action selectors on five players' scene files, laid out like the
// thesis' table of k and selectors: one row per selector, one column per k, action accuracy
// in the cells (metric ball-goal). Run from the repository root (see
// docs/results/README.md):
//   scenes experiment docs/results/sweeps/k-selectors.groovy --out-dir my-results

// The scene files: players 1 to 5 of one team, one file each. By default those of the demo's
// first game ('scenes demo' in the repository root writes them); the shipped tables were made
// on the shared Krislet recordings: SWEEP_SCENES=build/krislet/classic-game1/Carleton_
String scenes = System.getenv('SWEEP_SCENES') ?: 'scenes-demo/game1/scenes/Teal_'
title "k and selectors (${scenes}1 to 5, 5 folds, ball-goal): accuracy".toString()

for (int player = 1; player <= 5; player++) {
    data "${scenes}${player}.json.gz".toString()
}
metrics 'ball-goal'
k 1, 3, 5, 7, 9, 15
selectors 'first-valid', 'random', 'vote', 'vote-random'
table rows: 'selector', columns: 'k', measure: 'accuracy'
