// Number of neighbours and action selectors on the shared Krislet data, laid out like the
// thesis' table of k and selectors: one row per selector, one column per k, action accuracy
// in the cells (metric ball-goal). Regenerate (see docs/results/README.md):
//   scenes experiment docs/results/sweeps/k-selectors.groovy --out-dir docs/results
title 'k and selectors (Krislet classic game 1, 5 folds, ball-goal): accuracy'

for (int player = 1; player <= 5; player++) {
    data "build/krislet/classic-game1/Carleton_${player}.json.gz".toString()
}
metrics 'ball-goal'
k 1, 3, 5, 7, 9, 15
selectors 'first-valid', 'random', 'vote', 'vote-random'
table rows: 'selector', columns: 'k', measure: 'accuracy'
