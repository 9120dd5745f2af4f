#!/usr/bin/env bash
# CLI smoke test: `cogmap serve --pty` + `cogmap drive --record` + `cogmap replay` give the
# same map; a malformed log is exit 2 with file:line. Usage: serve_drive_replay.sh COGMAP SRC OUT
set -euo pipefail
cogmap=$1 src=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
exp="$src/experiments/two_rooms.yaml"
source "$(dirname "$0")/serve_pty.sh"
start_serve "$cogmap" "$exp" "$out"
"$cogmap" drive --port "$dev" --sip-clock --experiment "$exp" --duration 16 --record "$out/live.log" \
  --out "$out/live" --no-figures
"$cogmap" replay "$out/live.log" --experiment "$exp" --out "$out/replay" --no-figures
cmp "$out/live/map_segments.csv" "$out/replay/map_segments.csv"
set +e
msg=$("$cogmap" replay "$src/hw/testdata/bad_reading.cogmap.log" --out "$out/bad" 2>&1)
rc=$?
set -e
[[ $rc -eq 2 ]] || { echo "malformed log: exit $rc, expected 2"; exit 1; }
[[ $msg == *"bad_reading.cogmap.log:4: expected range_m"* ]] || { echo "message: $msg"; exit 1; }
"$cogmap" replay "$src/hw/testdata/sample.carmen.log" --out "$out/carmen" --no-figures
"$cogmap" replay "$src/hw/testdata/sample.player.log" --out "$out/player" --no-figures
echo "serve/drive/replay OK"
