// The benchmark sweep of scenes-spark (not a test): 100 configurations, 10 object weights x 5 k
// x 2 selectors of `ball-goal`, each cross-validated over 5 Krislet players of the shared
// recordings (classic-game1, thesis protocol: 5 folds), 500 tasks. Run by spark/bench/run.sh,
// which converts the players first; the numbers are in the README's Spark section.
title 'scenes-spark benchmark: 100 configurations x 5 folds'

for (int player = 1; player <= 5; player++) {
    data "build/spark-bench/scenes/classic-game1/Carleton_${player}.json.gz".toString()
}
metrics 'ball-goal'
weights 'ball=1,goal=1', 'ball=1,goal=0.5', 'ball=1,goal=2', 'ball=2,goal=1', 'ball=1,goal=0.1',
        'ball=1,goal=0.2', 'ball=1,goal=0.3', 'ball=1,goal=3', 'ball=3,goal=1', 'ball=1,goal=0.7'
k 1, 3, 5, 7, 9
selectors 'first-valid', 'vote'
table columns: 'k'
