#!/usr/bin/env bash
# The sweep benchmarks of BENCHMARKS.md ("Sweeps"), in one run so that the ratios compare like
# with like on a shared machine. Not part of the test suite. Needs python3 (a venv with numpy is
# made in target/bench-venv on first use). Usage: bash benches/sweep/run.sh [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/../.."
repeats=${1:-3}
out=target/bench-sweep
mkdir -p "$out"
cargo build --release -p halfplane-cli
bin=target/release/halfplane
if [ ! -x target/bench-venv/bin/python ]; then
    python3 -m venv target/bench-venv
    target/bench-venv/bin/pip install --quiet numpy
fi
py=target/bench-venv/bin/python
# wall and CPU (user + system) seconds of a command, as "wall cpu".
timed() {
    /usr/bin/time -f "%e %U %S" -o "$out/time" "$@" > /dev/null 2>&1
    awk '{printf "%8.2f %8.2f", $1, $2 + $3}' "$out/time"
}
echo "repeat  case                               wall_s    cpu_s"
for i in $(seq "$repeats"); do
    printf "%-7s %-34s %s\n" "$i" "halfplane sweep hertz 1e6" "$(timed $bin sweep benches/sweep/hertz-1e6.toml -o $out/hertz-rust.csv)"
    printf "%-7s %-34s %s\n" "$i" "numpy hertz 1e6" "$(timed $py benches/sweep/hertz_numpy.py $out/hertz-numpy.csv)"
    printf "%-7s %-34s %s\n" "$i" "halfplane sweep flat-rounded 1e6" "$(timed $bin sweep benches/sweep/flat-rounded-1e6.toml -o $out/flat-rounded.csv)"
    printf "%-7s %-34s %s\n" "$i" "halfplane sweep flat-rounded+tension" "$(timed $bin sweep benches/sweep/flat-rounded-tension-1e6.toml -o $out/flat-rounded-tension.csv)"
done
printf "%-7s %-34s %s\n" "1" "halfplane sweep march 1000" "$(timed $bin sweep benches/sweep/march-1000.toml -o $out/march.csv)"
$py benches/sweep/hertz_numpy.py --compare $out/hertz-rust.csv $out/hertz-numpy.csv
