#!/usr/bin/env bash
# The hostile-input suite (issue 12, docs/reliability.md): small generated files that once
# crashed, hung or clobbered something, each run against the real CLI with a time limit.
#   hostile.sh COGMAP SRC OUT CASE   one case (ctest runs each as hostile.CASE)
#   hostile.sh COGMAP SRC OUT --list the case names
#   hostile.sh COGMAP SRC OUT --table every case, as the markdown table of docs/reliability.md
# A case passes when the exit code is the expected one, the output holds the expected text,
# it ends within its time limit and its own extra checks hold (files untouched, no escape).
set -uo pipefail
cogmap=$1 src=$2 out=$3 what=$4
if [[ $what != --list ]]; then  # cases cd elsewhere: every path absolute
  cogmap=$(realpath -m "$cogmap") src=$(realpath -m "$src") out=$(realpath -m "$out")
fi
# A sanitizer build reserves terabytes of address space for its shadow memory: a case that
# caps the address space (ulimit -v) cannot run it, and keeps its other checks.
vlimit='ulimit -v 2000000;'
# (a strong reference: the weak ones are the bag reader's own check for a sanitizer; grep reads
# all of nm's output: with -q it could stop early, nm then dies of SIGPIPE and
# pipefail calls the match a failure)
if [[ $what != --list ]] &&
  (($(nm -D --undefined-only "$cogmap" 2>/dev/null | grep -cE ' U __(asan|tsan|msan)_init$') > 0)); then
  vlimit=''
fi
W=$src/worlds
H='cogmap-log 1 sonar_min_range_m=0.1 sonar_max_range_m=5 sonar_beam_width_rad=0.5236 length_m=0.626 width_m=0.505 max_speed_mps=0.75 max_turn_rate_radps=1.74 max_accel_mps2=0.3 max_decel_mps2=0.6 sonars=2 0.147,0.136,1.5708 0.193,0.119,0.8727'

CASES=(world_tiny_segment world_jog_2mm world_huge_coordinates world_check_tiny_segment
  key_list_world key_list_experiment key_list_mapper key_list_sweep key_list_set
  dev_zero_world dev_zero_experiment dev_urandom_experiment big_experiment big_world
  sweep_ten_million sweep_ten_million_shard cycle_1e9 explore_1e12 duration_flag_huge
  out_is_experiment_folder out_is_foreign_folder name_escapes name_absolute duplicate_key
  second_document text_after_document seed_minus_one sweep_duplicate_seeds sweep_duplicate_values
  log_nan_odometry log_inf_time log_nan_mount log_jump_1e5 log_jump_50m log_max_range_zero log_beam_width_100
  log_min_above_max log_time_backwards log_header_only log_carmen_on_cogmap log_dev_zero
  replay_name_colon replay_name_newline stale_temp_files rerun_run_directory locked_directory
  drive_handshake_wrong_packets drive_handshake_garbage drive_handshake_silent drive_sips_never_parse
  sonar_stats_csv_is_the_log sonar_stats_csv_exists sonar_stats_csv_is_a_directory
  sonar_stats_min_speed_nan sonar_model_user_files sonar_model_range_nan sweep_out_user_results
  sweep_merge_cwd_results sweep_merge_dev_zero sweep_resume_own_directory
  drive_record_is_the_experiment drive_record_exists drive_duration_nan
  sweep_vary_missing_world sweep_vary_unknown_key sweep_merge_negative_run sweep_merge_text_run
  experiment_empty_value log_gzipped log_bom_crlf log_nul_tail log_cut_mid_line
  sonar_stats_stdout_full world_check_stdout_full sweep_merge_write_fails sweep_disk_full
  run_set_missing_world world_start_theta_huge experiment_start_theta_huge world_box_angle_huge
  yaml_nested_5000 log_fifo sonar_stats_fifo room_grid_cells_10mm room_grid_extent_2000m
  log_time_gap_jump set_robot_sonar_key sweep_merge_open_quote run_out_empty sweep_out_empty
  run_out_dangling_link experiment_quoted_number set_int_hex_overflow set_value_not_utf8
  world_check_start_outside run_start_outside bag_undeclared_connection bag_cloud_points_2g
  bag_cloud2_data_1g5 log_player_v1 log_carmen_sonar_only log_carmen_laser_only
  log_player_ranger_bad_geometry experiment_bool_yaml11 experiment_block_scalar_number
  sweep_vary_quoted_number seed_empty set_key_trailing_dot log_reading_time_early
  log_carmen_odom_velocity_garbage log_carmen_later_sonar_mounts log_player_velocity_garbage
  sweep_max_runs_zero drive_port_directory name_control_character)

# A valid cogmap log of 9 frames, moving 1 cm per 100 ms.
good_log() {
  echo "$H"
  for i in 1 2 3 4 5 6 7 8 9; do echo "F 0.$i 0.0$i 0 0 0 0 - 1 0,1.5,1,0.$i"; done
}
short_experiment() {  # name world duration
  printf 'name: %s\nworld: %s\nduration_s: %s\nrobot: {source: sim}\noutput: {figures: false}\n' \
    "$1" "$2" "$3"
}

# The robot side of a P2OS link for `drive`, on a local TCP port (written to $1), one client;
# sets $peer to its pid. Modes ($2): garbage (NMEA text every 100 ms, whatever it is sent: a
# GPS, not a robot), silent (accepts, never answers), bad_sips (a p2at handshake, then SIPs with
# valid checksums cut short after XPOS).
tcp_peer() {
  command -v python3 >/dev/null || { echo "SKIP: no python3"; exit 77; }
  python3 - "$1" "$2" <<'PY' &
import socket, sys, time
port_file, mode = sys.argv[1], sys.argv[2]
def packet(body):  # FA FB count body checksum (big-endian words summed, an odd last byte XORed)
    c = 0
    for i in range(0, len(body) - 1, 2): c = (c + (body[i] << 8 | body[i + 1])) & 0xFFFF
    if len(body) % 2: c ^= body[-1]
    return bytes([0xFA, 0xFB, len(body) + 2, *body, c >> 8, c & 0xFF])
s = socket.socket(); s.bind(("127.0.0.1", 0)); s.listen(1)
open(port_file, "w").write(str(s.getsockname()[1]))
c, _ = s.accept(); c.settimeout(0.1)
buf, step, end = b"", 0, time.time() + 20
while time.time() < end:
    try:
        data = c.recv(256)
        if not data: break
        buf += data
    except socket.timeout: pass
    except OSError: break
    out = b""
    while len(buf) >= 3 and len(buf) >= buf[2] + 3:  # the client's packets arrive whole
        if buf[0] != 0xFA: buf = buf[1:]; continue
        body, buf = buf[3:buf[2] + 1], buf[buf[2] + 3:]
        if step < 3 and body == bytes([step]):  # SYNC0-2 echoed, SYNC2 with the robot's names
            out += packet([2, *b"peer\0Pioneer\0p2at\0"] if step == 2 else [step]); step += 1
        elif step == 3 and body[:1] == b"\x01": step = 4  # OPEN: SIPs from now on
    if mode == "garbage": out = b"$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n"
    if mode == "silent": out = b""
    if mode == "bad_sips" and step == 4: out += packet([0x32, 0, 0, 0])
    try:
        if out: c.sendall(out)
    except OSError: break
PY
  peer=$!
  for _ in $(seq 50); do [[ -s $1 ]] && break; sleep 0.1; done
}

# Hand-made one-chunk ROS bags (stdout): tiny_bag.py cloud | cloud2 | undeclared says which.
tiny_bag() { python3 "$src/tests/hostile/tiny_bag.py" "$1"; }

# Sets: cmd (array), want_rc, want_text, limit_s; may define check() for extra assertions.
setup() {
  local d=$1
  check() { return 0; }
  limit_s=10
  case $what in
    world_tiny_segment)
      printf 'name: w\nwalls: {polylines: [[[0,0],[0.002,0],[5,0]]]}\nstart: {x_m: 2, y_m: 2}\n' >"$d/w.yaml"
      short_experiment e w.yaml 5 >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="w.yaml:2: walls.polylines[0][1]: wall segment of 0.002 m is shorter" ;;
    world_jog_2mm)
      printf 'name: w\nwalls:\n  polylines:\n    - [[0,0],[3,0],[3,0.002],[6,0.002],[6,4],[0,4],[0,0]]\nstart: {x_m: 2, y_m: 2}\n' >"$d/w.yaml"
      short_experiment e w.yaml 5 >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="w.yaml:4: walls.polylines[0][2]: wall segment of 0.002 m" ;;
    world_huge_coordinates)
      printf 'name: w\nwalls: {polylines: [[[3e6,0],[3e6,5]]]}\nstart: {x_m: 2, y_m: 2}\n' >"$d/w.yaml"
      short_experiment e w.yaml 5 >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="coordinate 3e+06 m is beyond the +/-1000 m" ;;
    world_check_tiny_segment)
      printf 'name: w\nwalls: {polylines: [[[0,0],[0.001,0]]]}\nstart: {x_m: 2, y_m: 2}\n' >"$d/w.yaml"
      cmd=("$cogmap" world check "$d/w.yaml"); want_rc=1
      want_text="ERROR $d/w.yaml:2: walls.polylines[0][1]: wall segment of 0.001 m" ;;
    key_list_world)
      printf 'name: w\n? [a, b]\n: 1\nwalls: {polylines: []}\nstart: {x_m: 0, y_m: 0}\n' >"$d/w.yaml"
      cmd=("$cogmap" world check "$d/w.yaml"); want_rc=1
      want_text="w.yaml:2: a key must be a plain name" ;;
    key_list_experiment)
      printf 'name: e\n? [a, b]: 1\nworld: %s/two_rooms.yaml\n' "$W" >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:2: a key must be a plain name" ;;
    key_list_mapper)
      printf 'name: e\nworld: %s/two_rooms.yaml\nmapper:\n  ? [grid]\n  : bayes\n' "$W" >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:4: mapper: a key must be a plain name" ;;
    key_list_sweep)
      short_experiment e "$W/two_rooms.yaml" 5 >"$d/e.yaml"
      printf 'base: e.yaml\nseeds: [1]\nvary:\n  ? [mapper.grid]\n  : [bayes]\n' >"$d/s.sweep.yaml"
      cmd=("$cogmap" sweep "$d/s.sweep.yaml" --out "$d/sw"); want_rc=2
      want_text="s.sweep.yaml:4: vary: a key must be a plain name" ;;
    key_list_set)
      short_experiment e "$W/two_rooms.yaml" 5 >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --set 'mapper={? [a]: 1}' --out "$d/run"); want_rc=2
      want_text="e.yaml:1: mapper: value is not valid: a key must be a plain name" ;;
    dev_zero_world)
      cmd=("$cogmap" world check /dev/zero); want_rc=1
      want_text="ERROR /dev/zero: not a regular file" ;;
    dev_zero_experiment)
      cmd=("$cogmap" run /dev/zero --out "$d/run"); want_rc=2
      want_text="/dev/zero: not a regular file" ;;
    dev_urandom_experiment)
      cmd=("$cogmap" run /dev/urandom --out "$d/run"); want_rc=2
      want_text="/dev/urandom: not a regular file" ;;
    big_experiment)
      { short_experiment e "$W/two_rooms.yaml" 5; head -c 2000000 /dev/zero | tr '\0' '#'; echo; } >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml: larger than the 1048576-byte limit" ;;
    big_world)
      { printf 'name: w\nwalls:\n  polylines:\n'; for i in $(seq 0 40000); do echo "    - [[$i, 0], [$i, 0.5]]"; done; } >"$d/w.yaml"
      cmd=("$cogmap" world check "$d/w.yaml"); want_rc=1
      want_text="w.yaml: larger than the 1048576-byte limit" ;;
    sweep_ten_million|sweep_ten_million_shard)
      short_experiment e "$W/two_rooms.yaml" 5 >"$d/e.yaml"
      { echo 'base: e.yaml'; echo 'seeds: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]';
        echo 'vary:'; for k in cell_scale_mm occupied_threshold vertex_tolerance_cells \
          polyline_gap_cells douglas_peucker_cells window_m; do
          echo "  mapper.$k: [$(seq -s ', ' 11 20)]"; done; } >"$d/s.sweep.yaml"
      cmd=("$cogmap" sweep "$d/s.sweep.yaml" --out "$d/sw")
      [[ $what == *shard ]] && cmd+=(--shard 3/1000)
      want_rc=2; want_text="the sweep has more than 10000 runs" ;;
    cycle_1e9)
      printf 'name: e\nworld: %s/two_rooms.yaml\nrobot: {cycle_s: 1e-9}\n' "$W" >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:3: robot.cycle_s: cycle_s must be in [0.01, 10] seconds" ;;
    explore_1e12)
      printf 'name: e\nworld: %s/two_rooms.yaml\nduration_s: 1e12\ncontroller: {type: explore}\n' "$W" >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:3: duration_s: must be at most 14400 s" ;;
    duration_flag_huge)
      cmd=("$cogmap" drive --tcp 127.0.0.1:9 --duration 1e12 --out "$d/run"); want_rc=2
      want_text="--duration 1e+12 is above the 14400 s run-duration limit" ;;
    out_is_experiment_folder)
      mkdir -p "$d/mine"; { echo '# my own comment'; short_experiment e "$W/two_rooms.yaml" 5; } >"$d/mine/exp.yaml"
      echo precious >"$d/mine/notes.txt"
      sum=$(cat "$d/mine/exp.yaml" "$d/mine/notes.txt" | md5sum)
      cmd=("$cogmap" run "$d/mine/exp.yaml" --out "$d/mine" --set duration_s=3 --force); want_rc=2
      want_text="is the folder of the input"
      check() { [[ $(cat "$d/mine/exp.yaml" "$d/mine/notes.txt" | md5sum) == "$sum" ]] && [[ $(ls -A "$d/mine" | wc -l) -eq 2 ]]; } ;;
    out_is_foreign_folder)
      short_experiment e "$W/two_rooms.yaml" 5 >"$d/e.yaml"
      mkdir -p "$d/home/figures"; echo mine >"$d/home/map.svg"; echo mine >"$d/home/thesis.tex"
      echo png >"$d/home/figures/holiday.png"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/home" --force); want_rc=2
      want_text="which no cogmap run wrote"
      check() { [[ -s $d/home/map.svg && -s $d/home/figures/holiday.png && ! -e $d/home/.cogmap-lock ]]; } ;;
    name_escapes|name_absolute)
      local name='../../escaped'; [[ $what == name_absolute ]] && name=/abs/olute
      mkdir -p "$d/cwd/sub"; short_experiment "$name" "$W/two_rooms.yaml" 2 >"$d/cwd/sub/e.yaml"
      cmd=(bash -c "cd '$d/cwd/sub' && '$cogmap' run e.yaml"); want_rc=0
      want_text="outputs in runs/_"
      check() { [[ $(find "$d" -name metrics.json | wc -l) -eq 1 && -n $(find "$d/cwd/sub/runs" -name metrics.json) ]]; } ;;
    duplicate_key)
      printf 'name: e\nworld: %s/two_rooms.yaml\nduration_s: 5\nduration_s: 600\n' "$W" >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:4: duration_s: duplicate key" ;;
    second_document)
      printf 'name: e\nworld: %s/two_rooms.yaml\n---\nname: other\n' "$W" >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:3: a second YAML document" ;;
    text_after_document)  # found by scripts/fuzz: yaml-cpp's LoadAll loops for ever on it
      printf '[1],\n' >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:1: a second YAML document (or text after the end of the first)" ;;
    seed_minus_one)
      short_experiment e "$W/two_rooms.yaml" 5 >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --seed -1 --out "$d/run"); want_rc=2
      want_text="--seed '-1': expected a whole number" ;;
    sweep_duplicate_seeds)
      short_experiment e "$W/two_rooms.yaml" 5 >"$d/e.yaml"
      printf 'base: e.yaml\nseeds:\n  - 1\n  - 1\n' >"$d/s.sweep.yaml"
      cmd=("$cogmap" sweep "$d/s.sweep.yaml" --out "$d/sw"); want_rc=2
      want_text="s.sweep.yaml:4: seeds[1]: seed 1 is listed twice (also line 3)" ;;
    sweep_duplicate_values)
      short_experiment e "$W/two_rooms.yaml" 5 >"$d/e.yaml"
      printf 'base: e.yaml\nseeds: [1]\nvary:\n  mapper.cell_scale_mm: [55, "55"]\n' >"$d/s.sweep.yaml"
      cmd=("$cogmap" sweep "$d/s.sweep.yaml" --out "$d/sw"); want_rc=2
      want_text="s.sweep.yaml:4: vary.mapper.cell_scale_mm[1]: value '55' repeats '55'" ;;
    log_nan_odometry)
      good_log | sed 's/^F 0.5 0.05/F 0.5 nan/' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:6: expected odometry x_m (a finite number), got 'nan'" ;;
    log_inf_time)
      good_log | sed 's/^F 0.5 /F inf /' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:6: expected time_s (a finite number), got 'inf'" ;;
    log_reading_time_early)  # found by fuzzing (session 56): mapped at the pose of 1000 s before
      good_log | sed '3s/0,1.5,1,0.2$/0,1.5,1,-999.8/' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:3: reading 1 fired at -999.8 s, more than 1 s outside its frame's interval (0.1 s, 0.2 s]"
      check() { [[ ! -e $d/run ]]; } ;;
    log_carmen_odom_velocity_garbage)  # fuzzing, session 56: tv rv accel were never read (exit 0)
      printf '%s\n' 'ODOM 0 0 0 abc 0 0 1100000000.000000 p2at 0.0' \
        'SONAR 0.261799 2 1.50 2.25 0.147 0.136 1.570796 0.193 0.119 0.872665 1100000000.050000 p2at 0.05' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:1: expected tv at field 5, got 'abc'"
      check() { [[ ! -e $d/run ]]; } ;;
    log_carmen_later_sonar_mounts)  # fuzzing, session 56: only the first SONAR line's were read
      printf '%s\n' 'ODOM 0 0 0 0 0 0 1100000000.000000 p2at 0.0' \
        'SONAR 0.261799 2 1.50 2.25 0.147 0.136 1.570796 0.193 0.119 0.872665 1100000000.050000 p2at 0.05' \
        'ODOM 0.05 0 0 0 0 0 1100000000.100000 p2at 0.1' \
        'SONAR 0.261799 2 1.40 4.20 0.147 0.136 1.570796 abc nan 1e999 1100000000.150000 p2at 0.15' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:4: expected sonar x at field 9, got 'abc'"
      check() { [[ ! -e $d/run ]]; } ;;
    log_player_velocity_garbage)  # fuzzing, session 56: position2d vx vy va were never read
      printf '%s\n' '## Player version 2.0.5' '## File version 0.3.0' \
        '1130174476.000 16777343 6665 sonar 00 004 001 0002 +0.147 +0.136 +1.571 +0.193 +0.119 +0.873' \
        '1130174476.100 16777343 6665 position2d 00 001 001 +00.000 +00.000 +0.000 abc nan xyz 0' \
        '1130174476.100 16777343 6665 sonar 00 001 001 0002 +1.500 +2.250' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:4: expected vx at field 11, got 'abc'"
      check() { [[ ! -e $d/run ]]; } ;;
    sweep_max_runs_zero)  # fuzzing, session 56: the message printed 309 digits of DBL_MAX
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      printf 'base: e.yaml\nseeds: [1]\n' >"$d/s.sweep.yaml"
      cmd=("$cogmap" sweep "$d/s.sweep.yaml" --max-runs 0 --out "$d/sw"); want_rc=2
      want_text="--max-runs: '0' is not a whole number of 1 or more"
      check() { [[ ! -e $d/sw ]]; } ;;
    seed_empty)  # fuzzing, session 56: --seed "" (an unset variable) ran with the file's seed
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --seed '' --out "$d/run"); want_rc=2
      want_text="--seed: must not be empty"
      check() { [[ ! -e $d/run ]]; } ;;
    set_key_trailing_dot)  # fuzzing, session 56: "duration_s.=1" set duration_s
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --set duration_s.=1 --out "$d/run"); want_rc=2
      want_text="duration_s.: empty key component (from --set duration_s.=1)"
      check() { [[ ! -e $d/run ]]; } ;;
    log_nan_mount)
      good_log | sed '1s/0.147,0.136,1.5708/nan,0.136,1.5708/' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:1: expected sonar x_m (a finite number), got 'nan'" ;;
    log_jump_1e5)
      good_log | sed 's/^F 0.5 0.05/F 0.5 1e5/' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:6: odometry x_m must be in [-1000, 1000], got 100000" ;;
    log_jump_50m)
      good_log | sed 's/^F 0.5 0.05/F 0.5 50/' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:6: odometry jumps 49.96 m in 0.1 s (at most 1.15 m at max_speed_mps 0.75)" ;;
    log_max_range_zero)
      good_log | sed '1s/sonar_max_range_m=5/sonar_max_range_m=0/' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:1: header: sonar_max_range_m must be in [0.05, 50], got 0" ;;
    log_beam_width_100)
      good_log | sed '1s/sonar_beam_width_rad=0.5236/sonar_beam_width_rad=100/' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:1: header: sonar_beam_width_rad must be in [0.001, 3.14159], got 100" ;;
    log_min_above_max)
      good_log | sed '1s/sonar_min_range_m=0.1/sonar_min_range_m=6/' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:1: header: sonar_min_range_m must be in [0, 5], got 6" ;;
    log_time_backwards)
      good_log | sed 's/^F 0.5 /F 0.05 /' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:6: time goes backwards (0.05 s after 0.4 s)" ;;
    log_header_only)
      echo "$H" >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:1: the log has a header but no frames" ;;
    log_carmen_on_cogmap)
      good_log >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --format carmen --out "$d/run"); want_rc=2
      want_text="l.log: no ODOM or SONAR lines: not a CARMEN log" ;;
    log_player_v1)  # Player 1.x: "expected time host robot interface index type subtype"
      printf '## Player version 1.6.5 \n## File version 0.1.0 \n1100000000.000 myhost 6665 position 00 1100000000.000 +00.000 +00.000 +0.000 +00.000 +00.000 +0.000 0\n' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:2: a Player 1.x log (file version 0.1.0): cogmap reads the files of Player 2.x and 3.x's writelog"
      check() { [[ ! -e $d/run ]]; } ;;
    log_carmen_sonar_only)  # CARMEN's SONAR has no robot pose; was "expected SONAR ... at field 12"
      printf 'SONAR 0.261799 2 1.50 2.25 0.147 0.136 1.570796 0.193 0.119 0.872665 1100000000.050000 p2at 0.05\n' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log: no ODOM line before its 1 SONAR lines: a CARMEN SONAR line has no robot pose"
      check() { [[ ! -e $d/run ]]; } ;;
    log_carmen_laser_only)  # odometry and a laser, no SONAR line
      printf '%s\n' 'ODOM 0 0 0 0 0 0 1100000000.000000 p2at 0.0' \
        'FLASER 3 1.00 1.10 1.20 0.05 0.00 0.01 0.05 0.00 0.01 1100000000.010000 p2at 0.01' \
        'ODOM 0.05 0 0 0 0 0 1100000000.100000 p2at 0.1' \
        'FLASER 3 1.00 1.10 1.20 0.05 0.00 0.01 0.05 0.00 0.01 1100000000.110000 p2at 0.11' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log: no sonar readings (SONAR lines with ranges); lines: ODOM (2 read), FLASER (2 skipped)"
      check() { [[ ! -e $d/run ]]; } ;;
    log_player_ranger_bad_geometry)  # Player 3 (Stage 4): a ranger geometry cut after 1 of 16 poses
      printf '%s\n' '## Player version 3.0.2 ' '## File version 0.3.0 ' \
        '1300000000.000 16777343 6665 ranger 00 004 001 +00.000 +00.000 +00.000 +00.000 +00.000 +00.000 +00.000 +00.000 +00.000 0016 +00.069 +00.136 +00.000 +00.000 +00.000 +01.571' \
        '1300000000.100 16777343 6665 position2d 00 001 001 +00.000 +00.000 +0.000 +00.000 +00.000 +00.000 0' \
        '1300000000.100 16777343 6665 ranger 00 001 001 0002 1.500 2.250 ' >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:3: expected ranger geometry: 16 element poses (px py pz proll ppitch pyaw) then element_sizes_count at field 24, got 'end of line'"
      check() { [[ ! -e $d/run ]]; } ;;
    log_dev_zero)
      cmd=("$cogmap" replay /dev/zero --format cogmap --out "$d/run"); want_rc=2
      want_text="/dev/zero: not a regular file" ;;
    replay_name_colon)
      good_log >"$d/a: b.log"
      cmd=(bash -c "cd '$d' && '$cogmap' replay 'a: b.log' --no-figures"); want_rc=0
      want_text="outputs in runs/replay_a__b" ;;
    replay_name_newline)
      good_log >"$d/x"$'\n'"mapper: {grid: bayes}.log"
      cmd=(bash -c "cd '$d' && '$cogmap' replay \"\$(printf 'x\\nmapper: {grid: bayes}.log')\" --no-figures"); want_rc=0
      want_text="outputs in runs/replay_x_mapper___grid__bayes_"
      check() { local m; m=$(find "$d/runs" -name metrics.json); [[ -n $m ]] && grep -q '"grid": "mhimm"' "$m"; } ;;
    stale_temp_files)
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      "$cogmap" run "$d/e.yaml" --out "$d/run" >/dev/null 2>&1
      touch "$d/run/.grid_066.pgm.tmp-4242-7" "$d/run/asrs/.003.json.tmp-4242-1"
      mkdir -p "$d/run/figures"; touch "$d/run/figures/.room_001_stages.png.tmp.4242.3"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run" --force); want_rc=0
      want_text="outputs in $d/run"
      check() { [[ -z $(find "$d/run" -name '*.tmp[-.]*') ]]; } ;;
    rerun_run_directory)
      mkdir -p "$d/cwd"
      cmd=(bash -c "cd '$d/cwd' && '$cogmap' run '$src/experiments/two_rooms.yaml' --set duration_s=3 --no-figures >/dev/null && '$cogmap' run runs/two_rooms_seed7/experiment.yaml --no-figures && '$cogmap' run runs/two_rooms_seed7/experiment.yaml --out again --no-figures")
      want_rc=0; want_text="outputs in again"
      check() { cmp -s "$d/cwd/runs/two_rooms_seed7/trajectory.csv" "$d/cwd/again/trajectory.csv" && [[ -s $d/cwd/runs/two_rooms_seed7_rerun/metrics.json ]]; } ;;
    locked_directory)
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      "$cogmap" run "$d/e.yaml" --out "$d/run" >/dev/null 2>&1
      cmd=(flock "$d/run/.cogmap-lock" "$cogmap" run "$d/e.yaml" --out "$d/run" --force); want_rc=2
      want_text="another cogmap run is writing this directory" ;;
    drive_handshake_wrong_packets)
      command -v python3 >/dev/null || { echo "SKIP: no python3"; exit 77; }
      python3 - "$d/port" <<'PY' &
import socket, sys, threading, time
s = socket.socket(); s.bind(("127.0.0.1", 0)); s.listen(1)
open(sys.argv[1], "w").write(str(s.getsockname()[1]))
c, _ = s.accept(); c.settimeout(0.1)
end = time.time() + 20
while time.time() < end:  # a SYNC0 echo every 100 ms, whatever we are sent
    try:
        if not c.recv(64): break
    except socket.timeout: pass
    except OSError: break
    try: c.sendall(bytes([0xFA, 0xFB, 3, 0, 0, 0]))
    except OSError: break
PY
      peer=$!
      for _ in $(seq 50); do [[ -s $d/port ]] && break; sleep 0.1; done
      cmd=("$cogmap" drive --tcp "127.0.0.1:$(cat "$d/port")" --duration 3 --out "$d/run"); want_rc=1
      want_text="P2OS handshake failed: no complete SYNC0-2 exchange"; limit_s=6
      check() { kill "$peer" 2>/dev/null; return 0; } ;;
    drive_handshake_garbage)  # bytes that never decode were exit 1, like a silent robot
      tcp_peer "$d/port" garbage
      cmd=("$cogmap" drive --tcp "127.0.0.1:$(cat "$d/port")" --duration 3 --out "$d/run"); want_rc=2
      want_text="only bytes that do not decode as P2OS came back"; limit_s=6
      check() { kill "$peer" 2>/dev/null; [[ $text == *"none formed a packet; the last discard: "*" bytes at stream offsets "* ]]; } ;;
    name_control_character)  # fuzzing, session 56: an ESC sequence printed raw on the terminal
      printf 'name: "e\\x1b[2J"\nworld: %s/two_rooms.yaml\nduration_s: 2\n' "$W" >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:1: name: holds a control character (byte 0x1b at offset 1); a name is one line of printable text"
      check() { [[ ! -e $d/run && $text != *$'\e'* ]]; } ;;
    drive_port_directory)  # fuzzing, session 56: "open: Is a directory", exit 1 (a failed run)
      cmd=("$cogmap" drive --port "$d" --duration 1 --out "$d/run"); want_rc=2
      want_text="$d: a directory, not a serial port or terminal device"
      check() { [[ ! -e $d/run ]]; } ;;
    drive_handshake_silent)  # a robot that never answers is a failed run, not bad input
      tcp_peer "$d/port" silent
      cmd=("$cogmap" drive --tcp "127.0.0.1:$(cat "$d/port")" --duration 3 --out "$d/run"); want_rc=1
      want_text="last: no reply to SYNC0 within 1000 ms"; limit_s=6
      check() { kill "$peer" 2>/dev/null; [[ $text != *"do not decode"* ]]; } ;;
    drive_sips_never_parse)  # SIPs with valid checksums but an impossible layout: was exit 1
      tcp_peer "$d/port" bad_sips
      cmd=("$cogmap" drive --tcp "127.0.0.1:$(cat "$d/port")" --duration 10 --no-figures --out "$d/run")
      want_rc=2; want_text="bad bytes from the robot side: no SIP could be decoded for 2000 ms"; limit_s=8
      check() { kill "$peer" 2>/dev/null; [[ $text == *"the last: SIP at stream offset "*": SIP too short: field YPOS"* ]]; } ;;
    sonar_stats_csv_is_the_log)  # the table went over its own log, exit 0
      good_log >"$d/l.log"; sum=$(md5sum <"$d/l.log")
      cmd=("$cogmap" sonar-stats "$d/l.log" --csv "$d/l.log" --force); want_rc=2
      want_text="l.log: is the input $d/l.log (the same file), which would be overwritten"
      check() { [[ $(md5sum <"$d/l.log") == "$sum" ]]; } ;;
    sonar_stats_csv_exists)
      good_log >"$d/l.log"; echo mine >"$d/mine.csv"
      cmd=("$cogmap" sonar-stats "$d/l.log" --csv "$d/mine.csv"); want_rc=2
      want_text="mine.csv: already exists; pass --force to replace it, or choose another --csv"
      check() { [[ $(cat "$d/mine.csv") == mine ]]; } ;;
    sonar_stats_csv_is_a_directory)
      good_log >"$d/l.log"
      cmd=("$cogmap" sonar-stats "$d/l.log" --csv "$d"); want_rc=2
      want_text="$d: is a directory, not a file; choose another --csv" ;;
    sonar_model_user_files)
      mkdir -p "$d/home"; echo mine >"$d/home/echo_model.csv"
      cmd=("$cogmap" sonar-model --out "$d/home"); want_rc=2
      want_text="home/echo_model.csv: already exists; pass --force to replace it, or choose another --out"
      check() { [[ $(cat "$d/home/echo_model.csv") == mine && $(ls -A "$d/home" | wc -l) -eq 1 ]]; } ;;
    sweep_out_user_results)
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      printf 'base: e.yaml\nseeds: [1]\n' >"$d/s.sweep.yaml"
      mkdir -p "$d/home"; echo mine >"$d/home/results.csv"
      cmd=("$cogmap" sweep "$d/s.sweep.yaml" --out "$d/home" --no-figures); want_rc=2
      want_text="home: holds results.csv, which no cogmap sweep wrote"
      check() { [[ $(cat "$d/home/results.csv") == mine && $(ls -A "$d/home" | wc -l) -eq 1 ]]; } ;;
    sweep_merge_cwd_results)  # no --out: the merge went over ./results.csv
      mkdir -p "$d/cwd" "$d/shards"; echo mine >"$d/cwd/results.csv"
      printf 'run,seed,asr_count\n0,1,2\n' >"$d/shards/results_shard_1_of_1.csv"
      cmd=(bash -c "cd '$d/cwd' && '$cogmap' sweep --merge ../shards --no-plots"); want_rc=2
      want_text=". (the current directory): holds results.csv, which no cogmap sweep wrote"
      check() { [[ $(cat "$d/cwd/results.csv") == mine ]]; } ;;
    sweep_merge_dev_zero)
      cmd=("$cogmap" sweep --merge /dev/zero --out "$d/m"); want_rc=2
      want_text="/dev/zero: not a regular file or directory (a device, pipe or socket)" ;;
    sweep_resume_own_directory)  # a sweep's own directory, with or without its marker
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      printf 'base: e.yaml\nseeds: [1, 2]\n' >"$d/s.sweep.yaml"
      "$cogmap" sweep "$d/s.sweep.yaml" --out "$d/sw" --no-plots >/dev/null 2>&1
      rm -rf "$d/sw/.cogmap-sweep" "$d/sw/runs/seed=2"  # as a sweep before the marker left it
      cmd=("$cogmap" sweep "$d/s.sweep.yaml" --out "$d/sw" --no-plots); want_rc=0
      want_text="2 runs in shard 1/1: 1 run, 1 already finished, 0 failed"
      check() { [[ -e $d/sw/.cogmap-sweep && $(wc -l <"$d/sw/results.csv") -eq 3 ]]; } ;;
    drive_record_is_the_experiment)  # drive truncated its own experiment file to a log
      printf 'name: e\nworld: none\nrobot: {source: p2os}\n' >"$d/e.yaml"; sum=$(md5sum <"$d/e.yaml")
      cmd=("$cogmap" drive --tcp 127.0.0.1:9 --experiment "$d/e.yaml" --record "$d/e.yaml" --force
           --duration 3 --out "$d/run"); want_rc=2
      want_text="e.yaml: is the input $d/e.yaml (the same file), which would be overwritten"
      check() { [[ $(md5sum <"$d/e.yaml") == "$sum" && ! -e $d/run ]]; } ;;
    drive_record_exists)
      echo mine >"$d/old.log"
      cmd=("$cogmap" drive --tcp 127.0.0.1:9 --record "$d/old.log" --duration 3 --out "$d/run")
      want_rc=2; want_text="old.log: already exists; pass --force to replace it, or choose another --record"
      check() { [[ $(cat "$d/old.log") == mine ]]; } ;;
    sonar_model_range_nan)  # CLI11's Range lets NaN through: echo_model.csv said -nan
      cmd=("$cogmap" sonar-model --out "$d/o" --range nan); want_rc=2
      want_text="--range: 'nan' is not a finite number"
      check() { [[ ! -e $d/o ]]; } ;;
    sonar_stats_min_speed_nan)
      good_log >"$d/l.log"
      cmd=("$cogmap" sonar-stats "$d/l.log" --min-speed nan); want_rc=2
      want_text="--min-speed: 'nan' is not a finite number" ;;
    drive_duration_nan)  # reached an integer conversion
      cmd=("$cogmap" drive --tcp 127.0.0.1:9 --duration nan --out "$d/run"); want_rc=2
      want_text="--duration: 'nan' is not a finite number" ;;
    sweep_vary_missing_world)  # ran the first value's runs, then exit 1 naming e.yaml:1
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      printf 'base: e.yaml\nseeds: [1]\nvary:\n  world:\n    - %s/two_rooms.yaml\n    - missing.yaml\n' \
        "$W" >"$d/s.sweep.yaml"
      cmd=("$cogmap" sweep "$d/s.sweep.yaml" --out "$d/sw" --no-plots); want_rc=2
      want_text="s.sweep.yaml:6: vary.world[1]: world file $d/missing.yaml: cannot open file"
      check() { [[ ! -e $d/sw ]]; } ;;
    run_set_missing_world)  # named e.yaml:1 (the --set value's own line), not the override
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --set world=missing.yaml --out "$d/o"); want_rc=2
      want_text="e.yaml:2: world: world file $d/missing.yaml: cannot open file (from --set world=missing.yaml)"
      check() { [[ ! -e $d/o ]]; } ;;
    sweep_vary_unknown_key)  # named e.yaml, not the sweep's line
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      printf 'base: e.yaml\nseeds: [1]\nvary:\n  mapper.gridd:\n    - himm\n' >"$d/s.sweep.yaml"
      cmd=("$cogmap" sweep "$d/s.sweep.yaml" --out "$d/sw"); want_rc=2
      want_text="s.sweep.yaml:4: vary.mapper.gridd: unknown key (allowed: grid," ;;
    sweep_merge_negative_run)  # -5 was read as 2^64 - 5 and merged, exit 0
      printf 'run,seed,asr_count\n0,1,2\n-5,1,2\n' >"$d/results.csv"
      cmd=("$cogmap" sweep --merge "$d/results.csv" --out "$d/m" --no-plots); want_rc=2
      want_text="results.csv:3: run: '-5' is not a run index (a whole number, 0 or more)"
      check() { [[ ! -e $d/m ]]; } ;;
    sonar_stats_stdout_full)  # exit 0 with nothing printed: stdout's error shows on its last flush
      [[ -w /dev/full ]] || { echo "SKIP: no /dev/full"; exit 77; }
      good_log >"$d/l.log"
      cmd=(bash -c '"$0" sonar-stats "$1" >/dev/full' "$cogmap" "$d/l.log"); want_rc=1
      want_text="cogmap: standard output: write failed: No space left on device" ;;
    world_check_stdout_full)  # the same for a command whose whole answer is on stdout
      [[ -w /dev/full ]] || { echo "SKIP: no /dev/full"; exit 77; }
      cmd=(bash -c '"$0" world check "$1" >/dev/full' "$cogmap" "$W/two_rooms.yaml"); want_rc=1
      want_text="cogmap: standard output: write failed: No space left on device" ;;
    sweep_merge_write_fails)  # a results file that cannot be written was exit 2 (bad input)
      # A file size limit of 0 with SIGXFSZ ignored: every write fails (EFBIG), as on a full disk.
      printf 'run,seed,asr_count\n0,1,2\n' >"$d/results.csv"
      mkdir "$d/m" && echo "cogmap sweep" >"$d/m/.cogmap-sweep"
      printf 'run,seed,asr_count\n0,7,7\n' >"$d/m/results.csv"
      cmd=(bash -c 'trap "" XFSZ; ulimit -f 0; exec "$0" sweep --merge "$1" --out "$2" --no-plots' \
        "$cogmap" "$d/results.csv" "$d/m"); want_rc=1
      want_text="cogmap sweep --merge: $d/m/.results.csv.tmp-"
      check() {  # the previous results file whole, no temp file left
        [[ $(cat "$d/m/results.csv") == $'run,seed,asr_count\n0,7,7' ]] &&
          [[ -z $(find "$d/m" -name '.*.tmp-*') ]]
      } ;;
    sweep_disk_full)  # a full disk: the results file's error hid why every run had failed
      [[ $(id -u) -eq 0 ]] || { echo "SKIP: mounting a small tmpfs needs root"; exit 77; }
      mkdir "$d/fs"
      mount -t tmpfs -o size=64k tmpfs "$d/fs" 2>/dev/null || { echo "SKIP: mount failed"; exit 77; }
      trap "umount $(printf '%q' "$d/fs") 2>/dev/null" EXIT  # $d is local: expanded now
      head -c 60k /dev/zero >"$d/fs/filler"  # one page left: the sweep's marker
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      printf 'base: e.yaml\nseeds: [1]\n' >"$d/s.sweep.yaml"
      cmd=("$cogmap" sweep "$d/s.sweep.yaml" --out "$d/fs/sw" --no-plots); want_rc=1
      want_text="cogmap sweep: failed: seed=1: "
      check() {
        [[ $text == *"results.csv.tmp-"*"No space left on device"* ]] &&
          [[ ! -e $d/fs/sw/results.csv && ! -e $d/fs/sw/runs/seed=1/metrics.json ]] &&
          [[ -z $(find "$d/fs" -name '.*.tmp-*') ]]
      } ;;
    sweep_merge_text_run)  # no line; a quoted field spans two lines, a blank line is skipped
      printf 'run,seed,note\n0,1,"two\nlines"\n\nabc,1,x\n' >"$d/results.csv"
      cmd=("$cogmap" sweep --merge "$d/results.csv" --out "$d/m" --no-plots); want_rc=2
      want_text="results.csv:5: run: 'abc' is not a run index" ;;
    experiment_empty_value)  # yaml-cpp marks an empty value at the next key: line 4
      printf 'name: e\nworld: %s/two_rooms.yaml\nduration_s:\nrobot: {source: sim}\n' "$W" >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:3: duration_s: expected a number" ;;
    log_gzipped)  # "expected a cogmap, CARMEN or Player log line, got '" and raw gzip bytes
      good_log | gzip >"$d/l.log.gz"
      cmd=("$cogmap" replay "$d/l.log.gz" --out "$d/run"); want_rc=2
      want_text="l.log.gz: not a text log: gzip-compressed: decompress it first (gunzip -k FILE)"
      check() { [[ ! -e $d/run ]]; } ;;
    log_bom_crlf)  # a Windows editor's byte order mark: refused as "got 'cogmap-log 1 ...'"
      { printf '\xef\xbb\xbf'; good_log | sed 's/$/\r/'; } >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run" --no-figures); want_rc=0
      want_text="outputs in $d/run" ;;
    log_nul_tail)  # power lost while recording: the message stopped at the first NUL
      { good_log; head -c 4096 /dev/zero; } >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:11: 4096 NUL bytes instead of a line: the end of the file was never written" ;;
    log_cut_mid_line)  # the recording killed while writing its last line
      { good_log; printf 'F 1.0 0.10 0 0 0 0 - 1 0,1.'; } >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2
      want_text="l.log:11: expected reading index,range_m,echo,time_s (1 of 1), got '0,1.' (the last line, cut short" ;;
    world_start_theta_huge)  # 1e308 deg is infinite in radians: Box2D aborted (SIGABRT)
      printf 'name: w\nwalls: {polylines: [[[0,0],[10,0],[10,10],[0,10],[0,0]]]}\nstart: {x_m: 5, y_m: 5, theta_deg: 1e308}\n' >"$d/w.yaml"
      short_experiment e w.yaml 2 >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="w.yaml:3: start.theta_deg: angle 1e+308 deg is beyond the +/-1e+06 deg a file may give"
      check() { [[ ! -e $d/run ]]; } ;;
    experiment_start_theta_huge)  # the same abort from an experiment's start (or --set start=...)
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      printf 'start: {x_m: 1, y_m: 1, theta_deg: -1e308}\n' >>"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:6: start.theta_deg: angle -1e+308 deg is beyond the +/-1e+06 deg a file may give"
      check() { [[ ! -e $d/run ]]; } ;;
    world_box_angle_huge)  # a box of NaN corners: `world check` said OK, the run mapped nothing
      printf 'name: w\nwalls: {polylines: [[[0,0],[10,0],[10,10],[0,10],[0,0]]]}\nobstacles:\n  - {box: {center: [5, 8], size: [1, 1], angle_deg: 1e308}}\nstart: {x_m: 5, y_m: 5}\n' >"$d/w.yaml"
      cmd=("$cogmap" world check "$d/w.yaml"); want_rc=1
      want_text="ERROR $d/w.yaml:4: obstacles[0].box.angle_deg: angle 1e+308 deg is beyond the +/-1e+06 deg" ;;
    yaml_nested_5000)  # past yaml-cpp's own depth guard: "YAML syntax: bad file"
      { printf 'name: e\nx: '; head -c 5000 /dev/zero | tr '\0' '['; head -c 5000 /dev/zero | tr '\0' ']'; echo; } >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:2: YAML syntax: nested more than 64 levels deep" ;;
    log_fifo)  # a named pipe as the log: the ROS bag check opened it and waited for a writer
      mkfifo "$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --out "$d/run"); want_rc=2; limit_s=5
      want_text="cogmap replay: $d/l.log: not a regular file (a device, pipe or directory)"
      check() { [[ ! -e $d/run ]]; } ;;
    sonar_stats_fifo)  # the same hang in sonar-stats
      mkfifo "$d/l.log"
      cmd=("$cogmap" sonar-stats "$d/l.log"); want_rc=2; limit_s=5
      want_text="$d/l.log: not a regular file (a device, pipe or directory)" ;;
    room_grid_cells_10mm)  # 21 000 cells a side: past 11 GB and 90 s on a 200 m diagonal log
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      printf 'mapper: {cell_scale_mm: 10}\n' >>"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:6: mapper.cell_scale_mm: 10 mm cells with max_room_extent_m 200 m allow a room grid of 21000 cells a side"
      check() { [[ ! -e $d/run && $text == *"use cell_scale_mm of at least 53 or max_room_extent_m of at most 30"* ]]; } ;;
    room_grid_extent_2000m)  # the documented maximum extent at the default cell: 9 GB, 53 s
      good_log >"$d/l.log"
      cmd=("$cogmap" replay "$d/l.log" --set mapper.max_room_extent_m=2000 --out "$d/run"); want_rc=2
      want_text="mapper.max_room_extent_m: 100 mm cells with max_room_extent_m 2000 m allow a room grid of 20100 cells a side"
      check() { [[ ! -e $d/run ]]; } ;;
    log_time_gap_jump)  # 2800 m in one step after a 10 000 s gap, within the log's step limit:
      # one room grid held both ends (> 5 GB, killed at 20 s); now the jump starts a new room
      { echo "$H"
        echo "F 0 -990 -990 0 0 0 - 1 0,1.5,1,0"; echo "F 0.1 -990 -990 0 0 0 - 1 0,1.5,1,0.1"
        echo "F 10000 990 990 0 0 0 - 2 0,1.5,1,0.2 1,1.5,1,10000"
        echo "F 10000.1 990 990 0 0 0 - 1 0,1.5,1,10000.1"; } >"$d/l.log"
      cmd=(bash -c "$vlimit"' exec "$0" replay "$1" --out "$2" --no-figures' "$cogmap" "$d/l.log" "$d/run")
      want_rc=0; limit_s=5
      want_text="l.log: 2 rooms, outputs in $d/run"
      check() { (($(stat -c %s "$d/run/grid_000.pgm") < 1000000)) && (($(stat -c %s "$d/run/grid_001.pgm") < 1000000)); } ;;
    set_robot_sonar_key)  # was e.yaml:1 and no word of the override (the run parses the block)
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --set robot.sonar.rays_per_cone=100000 --out "$d/run"); want_rc=2
      want_text="e.yaml:4: robot.sonar.rays_per_cone: must be in [1, 1000] (from --set robot.sonar.rays_per_cone=100000)"
      check() { [[ ! -e $d/run ]]; } ;;
    sweep_merge_open_quote)  # a stray quote swallows the rest of the file: named no line
      printf 'run,seed,x\n0,1,2\n1,2,"oops\n2,3,4\n' >"$d/results.csv"
      cmd=("$cogmap" sweep --merge "$d/results.csv" --out "$d/m" --no-plots); want_rc=2
      want_text="results.csv:3: a quoted field opens here and is never closed"
      check() { [[ ! -e $d/m ]]; } ;;
    run_out_empty|sweep_out_empty)  # --out "" (an unset variable) wrote to runs/<name>_seed<N>
      mkdir -p "$d/cwd"; short_experiment e "$W/two_rooms.yaml" 2 >"$d/cwd/e.yaml"
      printf 'base: e.yaml\nseeds: [1]\n' >"$d/cwd/s.sweep.yaml"
      local sub=(run e.yaml); [[ $what == sweep_out_empty ]] && sub=(sweep s.sweep.yaml)
      cmd=(bash -c "cd '$d/cwd' && '$cogmap' ${sub[*]} --out ''"); want_rc=2
      want_text="--out: must not be empty"
      check() { [[ $(ls -A "$d/cwd" | wc -l) -eq 2 ]]; } ;;
    run_out_dangling_link)  # said "cannot create directory: File exists"
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      ln -s "$d/nowhere" "$d/o"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/o"); want_rc=2
      want_text="o: is a symbolic link to $d/nowhere, which does not exist; create it or choose another --out"
      check() { [[ ! -e $d/nowhere && -L $d/o ]]; } ;;
    experiment_quoted_number)  # a quoted number is a string in YAML: it ran for 2 s, exit 0
      short_experiment e "$W/two_rooms.yaml" "'2'" >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:3: duration_s: expected a number, got the quoted string '2' (write it without quotes)"
      check() { [[ ! -e $d/run ]]; } ;;
    set_int_hex_overflow)  # 0x hex is read for every number key; an int key's range still holds
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --set mapper.em_reference_rooms=0x80000000 --out "$d/run"); want_rc=2
      want_text="mapper.em_reference_rooms: expected an integer in [-2147483648, 2147483647], got '0x80000000' (from --set mapper.em_reference_rooms=0x80000000)"
      check() { [[ ! -e $d/run ]]; } ;;
    set_value_not_utf8)  # yaml-cpp read FF FE as a UTF-16 mark: "name: must not be empty"
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --set $'name=\xff\xfe' --out "$d/run"); want_rc=2
      want_text='e.yaml:1: name: not valid UTF-8 text (byte 0xff at offset 0); a --set value is YAML text, which must be UTF-8 (from --set name=\xff\xfe)'
      check() { [[ ! -e $d/run ]]; } ;;
    experiment_bool_yaml11)  # YAML 1.1's "no" was read as false: exit 0, figures off
      printf 'name: e\nworld: %s\nduration_s: 2\nrobot: {source: sim}\noutput: {figures: no}\n' \
        "$W/two_rooms.yaml" >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:5: output.figures: expected true or false, got 'no': a YAML 1.1 boolean, which YAML 1.2 reads as a string (write false)"
      check() { [[ ! -e $d/run ]]; } ;;
    experiment_block_scalar_number)  # was read as 2: a 2 s run, exit 0
      printf 'name: e\nworld: %s\nduration_s: |\n  2\nrobot: {source: sim}\noutput: {figures: false}\n' \
        "$W/two_rooms.yaml" >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=2
      want_text="e.yaml:3: duration_s: expected a number, got a block scalar (| or >) holding '2'"
      check() { [[ ! -e $d/run ]]; } ;;
    sweep_vary_quoted_number)  # the quotes were lost on the way to --set: 0.5 s runs, exit 0
      short_experiment e "$W/two_rooms.yaml" 2 >"$d/e.yaml"
      printf "base: e.yaml\nseeds: [1]\nvary:\n  duration_s:\n    - 1\n    - '0.5'\n" >"$d/s.sweep.yaml"
      cmd=("$cogmap" sweep "$d/s.sweep.yaml" --out "$d/sw" --no-plots); want_rc=2
      want_text="s.sweep.yaml:6: vary.duration_s[1]: expected a number, got the quoted string '0.5' (write it without quotes)"
      check() { [[ ! -e $d/sw ]]; } ;;
    world_check_start_outside)  # OK and nothing else: the robot would have heard nothing
      printf 'name: w\nwalls: {polylines: [[[0,0],[10,0],[10,10],[0,10],[0,0]]]}\nstart: {x_m: 15, y_m: 5}\n' >"$d/w.yaml"
      cmd=("$cogmap" world check "$d/w.yaml"); want_rc=0
      want_text="w.yaml:3: warning: start (15.00, 5.00) is not enclosed by walls: 23 of 32 directions from it meet no wall or obstacle"
      check() { [[ $("$cogmap" world check "$d/w.yaml" 2>/dev/null) == "OK $d/w.yaml: "* ]]; } ;;
    run_start_outside)  # the run warns once on stderr and runs as before
      printf 'name: w\nwalls: {polylines: [[[0,0],[10,0]]]}\nstart: {x_m: 5, y_m: 2}\n' >"$d/w.yaml"
      short_experiment e w.yaml 1 >"$d/e.yaml"
      cmd=("$cogmap" run "$d/e.yaml" --out "$d/run"); want_rc=0
      want_text="cogmap run: $d/w.yaml:3: warning: start (5.00, 2.00) is not enclosed by walls: 19 of 32"
      check() { [[ -s $d/run/metrics.json && $(grep -c warning: <<<"$text") -eq 1 ]]; } ;;
    bag_undeclared_connection)  # a chunk info names a connection no record declares: "no sonar topic"
      [[ -e $(dirname "$cogmap")/../lib/cogmap/libcogmap_ros_bag_plugin.so ]] ||
        { echo "SKIP: built without the ROS bag reader"; exit 77; }
      command -v python3 >/dev/null || { echo "SKIP: no python3"; exit 77; }
      tiny_bag undeclared >"$d/b.bag"
      cmd=("$cogmap" replay "$d/b.bag" --robot p3dx --out "$d/run"); want_rc=2
      want_text="b.bag: the chunk info record at byte 4742 names connection 1 (1 message in the chunk at byte 4117), but no connection record declares connection 1 (the index declares 0 /RosAria/pose): the bag's index is damaged"
      check() { [[ ! -e $d/run ]]; } ;;
    bag_cloud_points_2g | bag_cloud2_data_1g5)  # was "std::bad_alloc"; 1.5 GB allocated, 5 s
      [[ -e $(dirname "$cogmap")/../lib/cogmap/libcogmap_ros_bag_plugin.so ]] ||
        { echo "SKIP: built without the ROS bag reader"; exit 77; }
      command -v python3 >/dev/null || { echo "SKIP: no python3"; exit 77; }
      if [[ $what == bag_cloud_points_2g ]]; then
        tiny_bag cloud >"$d/b.bag"
        want_text="b.bag: topic /RosAria/sonar, message 0: its points array claims 2147483647 elements (25769803764 bytes) but the message holds only 4 more bytes: the message is damaged"
      else
        tiny_bag cloud2 >"$d/b.bag"
        want_text="b.bag: topic /RosAria/sonar, message 0: its data array claims 1500000000 elements (1500000000 bytes) but the message holds only 9 more bytes: the message is damaged"
      fi
      cmd=("$cogmap" replay "$d/b.bag" --robot p3dx --out "$d/run"); want_rc=2; limit_s=3
      check() { [[ ! -e $d/run ]]; } ;;
    *) echo "unknown case $what"; exit 2 ;;
  esac
}

run_case() {
  local d=$out/$what
  rm -rf "$d" && mkdir -p "$d"
  setup "$d"
  local start end rc
  start=$(date +%s%N)
  text=$(timeout -s KILL $((limit_s + 20)) "${cmd[@]}" 2>&1)
  rc=$?
  end=$(date +%s%N)
  local ms=$(((end - start) / 1000000))
  seconds=$(printf '%d.%02d' $((ms / 1000)) $((ms % 1000 / 10)))
  message=$(printf '%s' "$text" | grep -F -- "$want_text" | head -1)
  [[ -z $message ]] && message=$(printf '%s' "$text" | tail -1)
  got_rc=$rc
  if [[ $rc -ne $want_rc ]]; then verdict="exit $rc, expected $want_rc"
  elif [[ $text != *"$want_text"* ]]; then verdict="output lacks: $want_text"
  elif ((ms > limit_s * 1000)); then verdict="took ${seconds}s > ${limit_s}s"
  elif ! check; then verdict="extra check failed"
  else verdict=ok; fi
}

case $what in
  --list) printf '%s\n' "${CASES[@]}" ;;
  --table)
    echo "| case | exit | message | time |"
    echo "|---|---|---|---|"
    for what in "${CASES[@]}"; do
      run_case
      printf '| %s | %s | `%s` | %s s |%s\n' "$what" "$got_rc" "${message//$out\//}" "$seconds" \
        "$([[ $verdict == ok ]] || echo " FAIL: $verdict")"
    done ;;
  *)
    run_case
    printf '%s: exit %s in %s s: %s\n' "$what" "$got_rc" "$seconds" "$message"
    [[ $verdict == ok ]] || { echo "FAIL: $verdict"; printf '%s\n' "$text" | tail -5; exit 1; }
    ;;
esac
