#!/usr/bin/env bash
# Usage: sonar_cli.sh COGMAP SRC OUT. Records the calibration corridor through serve + drive,
# checks `cogmap sonar-stats` on it (16 transducers, each fired every 320 ms: 0.31 per 100 ms),
# `--compare`, the CSV, a malformed log (exit 2, file:line) and `cogmap sonar-model`.
set -euo pipefail
cogmap=$1 src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
exp="$src/experiments/corridor_calibration.yaml"
source "$(dirname "$0")/../hw_e2e/serve_pty.sh"
SERVE_CYCLE_MS=20 start_serve "$cogmap" "$exp" "$out"
"$cogmap" drive --port "$dev" --sip-clock --experiment "$exp" --duration 20 --record "$out/sim.log" \
  --out "$out/run" --no-figures >/dev/null
kill $serve_pid 2>/dev/null || true

"$cogmap" sonar-stats "$out/sim.log" --csv "$out/stats.csv" >"$out/stats.txt"
cat "$out/stats.txt"
rows=$(tail -n +2 "$out/stats.csv" | wc -l)
[[ $rows -eq 16 ]] || { echo "expected 16 transducer rows, got $rows"; exit 1; }
# Every transducer fires once per 8 cycles of 40 ms: 0.3125 per 100 ms (the SIP clock keeps
# simulated time, so wall-clock jitter does not enter).
awk -F, 'NR > 1 && ($9 < 0.29 || $9 > 0.33) { print "transducer " $1 ": " $9 " firings/100ms"; bad = 1 }
         END { exit bad }' "$out/stats.csv"
# The side transducers face painted walls 1.1 m away: nearly every firing is an echo.
awk -F, 'NR > 1 && ($2 == 90 || $2 == -90) && $5 < 0.9 { print "side transducer " $1 " echo " $5; bad = 1 }
         END { exit bad }' "$out/stats.csv"

"$cogmap" sonar-stats "$out/sim.log" --compare "$out/sim.log" >"$out/compare.txt"
grep -q "+0.00" "$out/compare.txt" || { echo "self-comparison shows a difference"; cat "$out/compare.txt"; exit 1; }

set +e
msg=$("$cogmap" sonar-stats "$src/hw/testdata/bad_reading.cogmap.log" 2>&1)
rc=$?
set -e
[[ $rc -eq 2 ]] || { echo "malformed log: exit $rc, expected 2"; exit 1; }
[[ $msg == *"bad_reading.cogmap.log:4:"* ]] || { echo "message: $msg"; exit 1; }

"$cogmap" sonar-model --out "$out/model" >/dev/null
for f in echo_probability.png echo_range.png echo_model.csv; do
  [[ -s "$out/model/$f" ]] || { echo "sonar-model wrote no $f"; exit 1; }
done
# Square on, every material answers; glass at 45 degrees does not.
grep -q "^painted_wall,0,1," "$out/model/echo_model.csv"
awk -F, '$1 == "glass" && $2 == 45 && $3 > 0.01 { bad = 1 } END { exit bad }' "$out/model/echo_model.csv"
echo "sonar cli OK"
