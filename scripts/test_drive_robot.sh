#!/usr/bin/env bash
# cbbg drive against cbbg robot over the loopback address, as a user runs them: a trial with
# a third process forging datagrams at both ends is the simulated trial byte for byte, and
# its results plot and replay; SIGINT at either end, a robot that dies, and a wrong key each
# stop cleanly with the motors at zero and one line. The robots run in lockstep with long
# timeouts, so that a loaded machine (ctest's other tests) changes none of it; the real-time
# misses and timeouts are RealtimeLink's. Every process it starts it stops, by pid.
#   test_drive_robot.sh CBBG SCRATCH_DIR
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cbbg="$1"
scratch="$2"
rm -rf "$scratch"
mkdir -p "$scratch"
cd "$scratch"
fail() { echo "drive/robot: $*" >&2; exit 1; }
pids=()
trap 'for pid in "${pids[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done' EXIT
printf 'a key shared by both ends\n' >key

# Starts `cbbg robot` (analytic) on a port of the system's choice: sets robot_pid, port.
start_robot() {
  local log="$1"
  shift
  "$cbbg" robot --bind 127.0.0.1:0 --set plant.kind=analytic --lockstep --timeout-periods 200 \
    "$@" >"$log" 2>&1 &
  robot_pid=$!
  pids+=("$robot_pid")
  for _ in $(seq 100); do
    port="$(sed -n 's/^cbbg robot: serving on 127.0.0.1:\([0-9]*\),.*/\1/p' "$log")"
    [[ -n "$port" ]] && return 0
    sleep 0.05
  done
  fail "the robot did not start: $(cat "$log")"
}
free_port() { python3 -c 'import socket; s=socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
# Starts a 60 s pd_only drive against the robot into DIR (its log DIR.log): sets drive.
start_drive() {
  "$cbbg" drive --controller pd_only --robot "127.0.0.1:$port" --duration 60 --no-figures \
    --set remote.timeout_periods="${2:-200}" --out "$1" >"$1.log" 2>&1 &
  drive=$!
  pids+=("$drive")
}
column() {  # column NAME of trials.csv's first trial in DIR
  awk -F, -v name="$2" 'NR==1 { for (i = 1; i <= NF; i++) if ($i == name) c = i } NR==2 { print $c }' "$1/trials.csv"
}

# 1. Forged traffic at both ends: refused, counted, never applied.
start_robot robot1.log --key-file key --sessions 1
drive_port="$(free_port)"
python3 "$root/scripts/forge_datagrams.py" 'a key shared by both ends' "$port" "$drive_port" &
forger=$!
pids+=("$forger")
"$cbbg" drive --controller pd_only --robot "127.0.0.1:$port" --bind "127.0.0.1:$drive_port" \
  --key-file key --duration 2 --set remote.timeout_periods=200 --out forged >drive1.log 2>&1 || fail "drive failed: $(cat drive1.log)"
kill -TERM "$forger"
wait "$forger" || true
wait "$robot_pid" || fail "the robot did not end after its session: $(cat robot1.log)"
[[ "$(column forged status)" == success ]] || fail "the trial did not balance: $(cat forged/trials.csv)"
(( "$(column forged refused)" > 0 )) || fail "the controller refused nothing of the forger's"
grep -q 'session over (the controller stopped: the run is over)' robot1.log ||
  fail "the robot's session did not end as asked: $(cat robot1.log)"
refused="$(sed -n 's/.*, \([0-9]*\) refused (.*/\1/p' robot1.log)"
(( ${refused:-0} > 0 )) || fail "the robot refused nothing of the forger's: $(cat robot1.log)"
for reason in malformed forged non_finite other_source; do
  grep -q "[0-9] $reason" robot1.log || fail "the robot counted no $reason datagram: $(cat robot1.log)"
done
"$cbbg" run --experiment pd_only --seeds 1 --set plant.kind=analytic --set trial.duration=2 \
  --no-figures --out simulated >/dev/null
cmp <(cut -d, -f4- simulated/steps.csv) <(cut -d, -f4- forged/steps.csv) ||
  fail "the real-time trial is not the simulated one"
[[ -f forged/figures/pitch_pd_only.png ]] || fail "cbbg drive drew no figures"
"$cbbg" replay forged --out forged.html >/dev/null || fail "cbbg replay refused a drive's results"

# 2. SIGINT at the controller: the trial so far is kept as stopped; the robot is told.
start_robot robot2.log --sessions 1
start_drive interrupted
sleep 1.5
kill -INT "$drive"
wait "$drive" || fail "drive after SIGINT exited $?: $(cat interrupted.log)"
wait "$robot_pid" || fail "the robot did not end after its session"
[[ "$(column interrupted status)" == stopped ]] || fail "SIGINT's trial: $(cat interrupted/trials.csv)"
(( "$(column interrupted steps)" > 50 )) || fail "the interrupted trial kept no ticks"
grep -q 'session over (the controller stopped: stopped by SIGINT): .* 0 refused' robot2.log ||
  fail "the robot was not told of the controller's SIGINT: $(cat robot2.log)"

# 3. SIGINT at the robot: it stops at zero; the controller stops, one line, exit 1.
start_robot robot3.log
start_drive robot_stopped
sleep 1.5
kill -INT "$robot_pid"
wait "$robot_pid" || fail "the robot after SIGINT exited $?"
grep -q '^cbbg robot: stopped by SIGINT, motors at zero$' robot3.log || fail "$(cat robot3.log)"
status=0
wait "$drive" || status=$?
[[ $status == 1 ]] || fail "drive exited $status when the robot stopped: $(cat robot_stopped.log)"
grep -qx "cbbg: error: the robot at 127.0.0.1:$port stopped the session: the robot was stopped by SIGINT; the trials until then are in robot_stopped" robot_stopped.log ||
  fail "drive's line: $(cat robot_stopped.log)"
[[ "$(column robot_stopped status)" == stopped ]] || fail "$(cat robot_stopped/trials.csv)"

# 4. A robot that dies: lost after remote.timeout_periods, zero torque sent, exit 1.
start_robot robot4.log
start_drive robot_died 10
sleep 1
kill -KILL "$robot_pid"
wait "$robot_pid" 2>/dev/null || true
status=0
wait "$drive" || status=$?
[[ $status == 1 ]] || fail "drive exited $status when the robot died: $(cat robot_died.log)"
grep -qx "cbbg: error: the robot at 127.0.0.1:$port sent nothing for 10 periods; the trials until then are in robot_died" robot_died.log ||
  fail "drive's line: $(cat robot_died.log)"

# 5. Another key: no session opens, one line, exit 1; the robot serves on.
start_robot robot5.log --key-file key
status=0
"$cbbg" drive --controller pd_only --robot "127.0.0.1:$port" --set remote.connect_timeout=0.5 \
  --no-figures --out wrong_key >drive5.log 2>&1 || status=$?
[[ $status == 1 ]] || fail "drive with another key exited $status"
grep -qx "cbbg: error: no robot welcomed this controller at 127.0.0.1:$port within 0.5 s (is \`cbbg robot\` serving there, with the same key?); the trials until then are in wrong_key" drive5.log ||
  fail "drive's line: $(cat drive5.log)"
kill -0 "$robot_pid" || fail "the robot stopped serving after a stranger's hello"
kill -INT "$robot_pid"
wait "$robot_pid" || fail "the robot after SIGINT exited $?"
echo "drive/robot: all cases passed"
