#!/usr/bin/env bash
# A user's robot with no C++: the reaction-wheel pendulum of examples/mujoco/ (an MJCF model
# and a YAML that maps it), copied elsewhere, through every command that runs a plant: exp1,
# exp3, transfer, eval of saved weights, a sweep in two shards and its merge, plot and replay
# (the model drawn from its own shapes); and a MuJoCo error while stepping.
#   test_mujoco_robot.sh CBBG SCRATCH_DIR
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cbbg="$1"
scratch="$2"
rm -rf "$scratch"
mkdir -p "$scratch/robot" "$scratch/work"
cp "$root/examples/mujoco/reaction_wheel.xml" "$root/examples/mujoco/reaction_wheel.yaml" \
  "$scratch/robot/"
cd "$scratch/work"  # the model is found from the YAML's folder, not from here
fail() { echo "mujoco robot: $*" >&2; exit 1; }
config=(--config ../robot/reaction_wheel.yaml --jobs 2)

"$cbbg" run "${config[@]}" --seeds 3 --no-figures --out exp1 >exp1.log
grep -q 'on the mujoco plant' exp1.log || fail "exp1 did not run on the mujoco plant"
grep -q "model: $scratch/robot/reaction_wheel.xml" exp1/config.yaml ||
  fail "config.yaml does not hold the model's absolute path"
# Its one wheel is read for both sides, and it has no pose: steps.csv has no x column.
header="$(head -1 exp1/steps.csv)"
[[ "$header" == *,phi_l,phi_r,* && "$header" != *,x,* ]] || fail "steps.csv's header: $header"

"$cbbg" run "${config[@]}" --experiment exp3 --seeds 2 --no-figures --out exp3 >/dev/null
grep -q '"trials_to_skill"' exp3/summary.json || fail "exp3 has no trials_to_skill"

"$cbbg" run "${config[@]}" --experiment transfer --seeds 2 --no-figures --out transfer \
  --set 'transfer.conditions=[evaluation.body_mass_scale=1.3]' >/dev/null
grep -q 'body_mass_scale=1.3' transfer/figures.csv || fail "transfer has no condition column"

"$cbbg" run "${config[@]}" --seeds 1 --set 'arms=[bg_only]' --no-figures --out learnt \
  --save-weights pendulum.weights >/dev/null
"$cbbg" eval --config ../robot/reaction_wheel.yaml --load-weights pendulum.weights >eval.log
grep -q '1/1' eval.log || fail "eval printed no balance count"

for shard in 1/2 2/2; do
  "$cbbg" run "${config[@]}" --seeds 1 --grid actor.alpha=0.1,0.2 --shard "$shard" \
    --no-figures --out sweep >/dev/null
done
"$cbbg" merge sweep >/dev/null
[ "$(cut -d, -f1 sweep/sweep.csv | sort -u | tr "\n" " ")" = "001 002 point " ] ||
  fail "sweep.csv does not hold the two grid points"

"$cbbg" plot exp1 >/dev/null || fail "plot failed"
"$cbbg" replay exp1 --out replay.html >/dev/null
grep -q 'cbbg-replay-data' replay.html || fail "the replay page holds no trials"
grep -q '"model":{"bodies"' replay.html || fail "the replay page does not draw the model's shapes"

# MuJoCo's own errors while stepping (here a two-wheeler whose <size> leaves its solver too
# little memory) end the run in one line of cbbg's, exit 1, and the run can be resumed.
sed 's/nstack="100000"/nstack="200"/' "$root/plant/mujoco/two_wheeler.xml" >../robot/cramped.xml
status=0
"$cbbg" run --set plant.kind=mujoco --set mujoco.model=../robot/cramped.xml --seeds 1 \
  --no-figures --out cramped >/dev/null 2>cramped.err || status=$?
[ "$status" = 1 ] || fail "a MuJoCo error while stepping exits $status, not 1"
[ "$(wc -l <cramped.err)" = 1 ] && grep -q '^cbbg: MuJoCo stopped the run: Stack overflow' cramped.err ||
  fail "a MuJoCo error while stepping says: $(cat cramped.err)"
[ -d cramped.partial ] || fail "the stopped run left nothing to resume"

# MuJoCo's own log file would land in the working directory: the plant keeps it quiet.
[ ! -e MUJOCO_LOG.TXT ] || fail "MuJoCo wrote MUJOCO_LOG.TXT"
echo "mujoco robot: exp1, exp3, transfer, eval, a sharded sweep, plot and replay ran; a MuJoCo error stopped a run in one line"
