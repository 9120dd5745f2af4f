#!/usr/bin/env bash
# Peer test: programs linked against AriaCoda talk to `cogmap serve --tcp`: build-peers.sh's
# sonarProbe (reads sonar) and aria_drive_client.cpp (drives, turns, reads ARIA's odometry).
# Usage: aria_client.sh COGMAP SOURCE_DIR WORK_DIR. Exit 77 (skipped) when the peers are not built.
set -euo pipefail
cogmap=$1 src=$2 work=$3
peers=${COGMAP_PEERS:-}
if [ -z "$peers" ] || [ ! -f "$peers/AriaCoda/lib/libAria.a" ] || [ ! -x "$peers/client/sonarProbe" ]; then
  echo "SKIPPED: peers not built (run scripts/test --peers, or set COGMAP_PEERS to build-peers.sh's folder)"
  exit 77
fi
rm -rf "$work"; mkdir -p "$work"
g++ -std=c++14 -O2 -I"$peers/AriaCoda/include" -o "$work/aria_drive_client" \
  "$src/tests/peers/aria_drive_client.cpp" "$peers/AriaCoda/lib/libAria.a" -lpthread -ldl -lrt
port=$((20000 + RANDOM % 20000))
"$cogmap" serve --experiment "$src/experiments/two_rooms.yaml" --tcp "127.0.0.1:$port" \
  --duration 60 > "$work/serve.log" 2>&1 &
serve=$!
trap 'kill $serve 2>/dev/null || true; wait $serve 2>/dev/null || true' EXIT
for _ in $(seq 1 50); do grep -q "127.0.0.1:$port" "$work/serve.log" 2>/dev/null && break; sleep 0.1; done
sleep 0.5
"$peers/client/sonarProbe" -rh 127.0.0.1 -rrtp "$port" -seconds 4 | tee "$work/probe.log"
sleep 1  # the server takes the next client after the last hangs up
"$work/aria_drive_client" -rh 127.0.0.1 -rrtp "$port" | tee "$work/drive.log"
