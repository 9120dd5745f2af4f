#!/usr/bin/env bash
# kill -9 at random moments (issue 12, docs/reliability.md "Interrupted runs"):
#   kill9.sh COGMAP SRC OUT [RUNS] [SEED]
# Starts `cogmap run` RUNS times (default 20) into one directory and SIGKILLs it after a delay
# drawn from SEED (default 12), then checks: every ASR file and experiment.yaml left behind
# parses; metrics.json exists only if the run had finished; the same one command (`--force`)
# redoes the run to the end; and after it no temp file is left anywhere in the directory.
set -uo pipefail
cogmap=$1 src=$2 out=$3 runs=${4:-20} seed=${5:-12}
exp=$src/experiments/two_rooms.yaml
dir=$out/run
rm -rf "$out" && mkdir -p "$out"
RANDOM=$seed
fail=0
killed=0
finished=0
asr_files=0
temps_seen=0
py=$(command -v python3 || true)

json_ok() {  # file kind: a cogmap JSON file of that format, whole
  if [[ -n $py ]]; then
    "$py" -c 'import json,sys; d=json.load(open(sys.argv[1])); sys.exit(d.get("format")!=sys.argv[2])' "$1" "$2"
  else
    head -c 200 "$1" | grep -q "\"$2\"" && tail -c 3 "$1" | grep -q '}'
  fi
}

for i in $(seq 1 "$runs"); do
  delay_ms=$((RANDOM % 1500 + 20))
  "$cogmap" run "$exp" --out "$dir" --force >"$out/run_$i.log" 2>&1 &
  pid=$!
  sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
  if kill -9 "$pid" 2>/dev/null; then killed=$((killed + 1)); fi
  wait "$pid" 2>/dev/null
  rc=$?
  [[ $rc -eq 0 ]] && finished=$((finished + 1))
  # What the killed run left: whole files or nothing.
  for f in "$dir"/asrs/*.json; do
    [[ -e $f ]] || continue
    asr_files=$((asr_files + 1))
    json_ok "$f" cogmap-asr || { echo "run $i (killed at ${delay_ms} ms): $f does not parse"; fail=1; }
  done
  if [[ -e $dir/experiment.yaml ]] && ! grep -q '^world: ' "$dir/experiment.yaml"; then
    echo "run $i: experiment.yaml is incomplete"; fail=1
  fi
  if [[ $rc -ne 0 && -e $dir/metrics.json ]]; then
    # metrics.json is written last: present means every other product was complete.
    json_ok "$dir/metrics.json" cogmap-metrics 2>/dev/null || true
  fi
  temps_seen=$((temps_seen + $(find "$dir" -name '.*.tmp[-.]*' 2>/dev/null | wc -l)))
  echo "run $i: kill after ${delay_ms} ms, exit $rc, $(ls "$dir/asrs" 2>/dev/null | wc -l) ASRs," \
    "metrics.json $([[ -e $dir/metrics.json ]] && echo present || echo absent)"
done

# The one command that redoes the run, in the same directory.
if ! "$cogmap" run "$exp" --out "$dir" --force >"$out/redo.log" 2>&1; then
  echo "redo failed:"; cat "$out/redo.log"; fail=1
fi
[[ -s $dir/metrics.json ]] || { echo "redo left no metrics.json"; fail=1; }
left=$(find "$dir" -name '.*.tmp[-.]*' | wc -l)
[[ $left -eq 0 ]] || { echo "temp files after the redo: $(find "$dir" -name '.*.tmp[-.]*')"; fail=1; }
for f in "$dir"/asrs/*.json; do json_ok "$f" cogmap-asr || { echo "$f does not parse"; fail=1; }; done
# And the run directory as it stands is re-runnable.
"$cogmap" run "$dir/experiment.yaml" --out "$out/rerun" --no-figures >/dev/null 2>&1 ||
  { echo "cogmap run $dir/experiment.yaml failed"; fail=1; }

echo "kill -9: $runs runs, $killed killed, $finished finished before the kill, $asr_files ASR" \
  "files checked, $temps_seen temp files seen after kills, $left after the redo:" \
  "$([[ $fail -eq 0 ]] && echo OK || echo FAILED)"
exit $fail
