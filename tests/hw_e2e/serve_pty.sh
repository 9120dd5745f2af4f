# Sourced by the CLI smoke tests: `start_serve COGMAP EXPERIMENT OUT` starts `cogmap serve --pty`
# in the background (20 ms per SIP, at most 30 s), sets serve_pid and dev (the pty to drive), and
# makes the shell stop the server on exit.
start_serve() {
  local cogmap=$1 exp=$2 out=$3
  "$cogmap" serve --experiment "$exp" --pty --cycle-ms "${SERVE_CYCLE_MS:-50}" --duration 30 \
    >"$out/serve.out" 2>"$out/serve.err" &
  serve_pid=$!
  trap 'kill $serve_pid 2>/dev/null || true' EXIT
  for _ in $(seq 50); do [[ -s "$out/serve.out" ]] && break; sleep 0.1; done
  dev=$(head -1 "$out/serve.out")
  [[ -e "$dev" ]] || { echo "serve printed no device: '$dev'"; exit 1; }
}
