// Object weights on five players' scene files, laid out like the thesis' table of weights: one
// row per weight vector (ball/goal/flag/line/players/teammates/opponents/unknown), one column
// per metric, action accuracy in the cells. Run from the repository root (see
// docs/results/README.md):
//   scenes experiment docs/results/sweeps/object-weights.groovy --out-dir my-results

// The scene files: players 1 to 5 of one team, one file each. By default those of the demo's
// first game ('scenes demo' in the repository root writes them); the shipped tables were made
// on the shared Krislet recordings: SWEEP_SCENES=build/krislet/classic-game1/Carleton_
String scenes = System.getenv('SWEEP_SCENES') ?: 'scenes-demo/game1/scenes/Teal_'
title "Object weights (${scenes}1 to 5, 5 folds, k = 1, first-valid): accuracy".toString()

for (int player = 1; player <= 5; player++) {
    data "${scenes}${player}.json.gz".toString()
}
metrics 'continuous', 'cell'
weights '1/1/1/1/0/1/1/1',          // everything, players by team
        '1/1/1/1/1/0/0/0',          // everything, players regardless of team
        'ball=1',
        'ball=1,goal=1',
        'ball=1,goal=1,flag=1',
        'ball=1,goal=1,line=1',
        'ball=1,goal=1,teammates=1,opponents=1,unknown=1',
        'flag=1,line=1'             // the field alone: where the player is
k 1
selectors 'first-valid'
table rows: 'weights', columns: 'metric', measure: 'accuracy'
