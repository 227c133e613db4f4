#!/usr/bin/env bash
# The scenes-spark benchmark (not a test; run it once, on a machine you say the load of):
# local[1] against local[2] on a sweep of 100 configurations (500 tasks), and `scenes experiment`
# on the same sweep (--threads 1 and 2) for the overhead. Needs the shared recordings beside the
# clone. From the repository root:  bash spark/bench/run.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
gradle -q :cli:installDist :spark:installDist
scenes=cli/build/install/scenes/bin/scenes
spark=spark/build/install/scenes-spark/bin/scenes-spark
out=build/spark-bench
mkdir -p "$out" && rm -rf "$out"/local-* "$out"/spark-*
[ -d "$out/scenes/classic-game1" ] || "$spark" convert ../shared/data/krislet/classic-game1 --out-dir "$out/scenes" > "$out/convert.txt"
sweep=spark/bench/sweep-100.groovy
run() {
    local label=$1; shift
    echo "== $label (load average before: $(cut -d' ' -f1-3 /proc/loadavg))"
    /usr/bin/time -f "$label: %e s wall, %U s user, %S s system, %M KB max RSS" "$@" > "$out/$label.txt"
}
run scenes-experiment-threads-1 "$scenes" experiment "$sweep" --out-dir "$out/local-1" --threads 1
run scenes-experiment-threads-2 "$scenes" experiment "$sweep" --out-dir "$out/local-2" --threads 2
run scenes-spark-local-1 "$spark" --master 'local[1]' experiment "$sweep" --out-dir "$out/spark-1"
run scenes-spark-local-2 "$spark" --master 'local[2]' experiment "$sweep" --out-dir "$out/spark-2"
cmp "$out/local-1/sweep-100.csv" "$out/spark-2/sweep-100.csv" && echo "the four tables are equal:"
cmp "$out/local-2/sweep-100.csv" "$out/spark-1/sweep-100.csv" && cmp "$out/local-1/sweep-100.csv" "$out/spark-1/sweep-100.csv" && echo "  same CSV"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
