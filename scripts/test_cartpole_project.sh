#!/usr/bin/env bash
# The cart-pole example (examples/cartpole/), built against the installed package, through
# every command a user's project needs, with no edit of the library: its plant, supervisor,
# tile-coded features and arms (a constant-omega and a critic-frozen one) in exp1 and exp3
# over seeds; a resume after a kill giving the same bytes; a 2-point sweep over its own key;
# its own protocol (a curriculum), resumed and swept too, in one process and in shards merged;
# transfer under its own plant parameter;
# `eval` of its saved weights; `plot` and `replay` of its results; an LQR supervisor designed
# from the cart-pole's own linearisation.
#   test_cartpole_project.sh CARTPOLE_PROGRAM SCRATCH_DIR
set -euo pipefail
program="$1"
scratch="$2"
mkdir -p "$scratch"
cd "$scratch"
fail() { echo "cartpole project: $*" >&2; exit 1; }
quick=(--set plant.kind=cartpole --set seeds=3 --set trial.duration=5 --set max_trials=30
       --set log.decimation=10 --jobs 2)
arms='arms=[tiles,tiles_omega_half,tiles_critic_frozen,lean_pd]'

# exp1 over 3 seeds, the user's arms against the user's supervisor alone.
"$program" run "${quick[@]}" --set "$arms" --out exp1 >exp1.log
for file in config.yaml summary.json trials.csv evaluation.csv steps.csv figures/failures.png \
  figures/pitch_tiles_omega_half.png figures/diagram.svg weights/tiles_critic_frozen_seed3.txt; do
  test -s "exp1/$file" || fail "exp1 has no $file"
done
grep -q "^  kind: cartpole$" exp1/config.yaml || fail "config.yaml does not record plant.kind"
# The paper's figures are the two-wheeler's: none beside a cart-pole's.
! grep -q '"paper"' exp1/summary.json || fail "summary.json shows the paper's figures for a cart-pole"
grep -q "^arms: \[tiles, tiles_omega_half, tiles_critic_frozen, lean_pd\]$" exp1/config.yaml ||
  fail "config.yaml does not record the arms that ran"
# The cart-pole has x but no y nor yaw: steps.csv has the columns it has.
head -1 exp1/steps.csv | grep -q ",reward,x$" || fail "steps.csv header: $(head -1 exp1/steps.csv)"
# Its features are 4 tilings of 6 x 6 tiles: 144 weights, filed with the tiles' layout.
grep -q "^tiles.tilings 4$" exp1/weights/tiles_seed1.txt || fail "the weights lack the tiles' layout"
grep -q "^features 144$" exp1/weights/tiles_seed1.txt || fail "the weights are not the tiles' 144"

# exp3 over 2 seeds.
"$program" run "${quick[@]}" --experiment exp3 --set seeds=2 --set max_trials=10 \
  --set 'arms=[tiles,tiles_critic_frozen]' --no-figures --out exp3 >exp3.log
grep -q '"trials_to_skill"' exp3/summary.json || fail "exp3 has no trials to skill"

# Killed after its third task is recorded, resumed: the same bytes as a run never killed.
"$program" run "${quick[@]}" --set "$arms" --no-figures --out reference >/dev/null
set +e
CBBG_FAULT_AT=task:record@3 "$program" run "${quick[@]}" --set "$arms" --no-figures \
  --out resumed >/dev/null 2>&1
status=$?
set -e
[[ $status == 86 ]] || fail "the killed run exited $status, not at the fault point"
[[ ! -e resumed ]] || fail "a killed run published its results"
"$program" run --resume resumed --jobs 2 >/dev/null
diff -r reference resumed >/dev/null || fail "the resumed run differs from the reference"
if find . -name '*cbbg-tmp*' | grep -q .; then fail "a temporary file was left"; fi

# A 2-point sweep over the cart-pole's own key.
"$program" run "${quick[@]}" --set seeds=2 --set 'arms=[tiles,tiles_omega_half]' \
  --grid cartpole.pole_length=0.4,0.6 --out sweep >/dev/null
[[ $(grep -c "^00[12],0\.[46],tiles" sweep/sweep.csv) == 4 ]] ||
  fail "sweep.csv has not its 2 points x 2 arms: $(cat sweep/sweep.csv)"

# eval of its saved weights, rebuilt with the tiles; a changed pole mass reaches the plant,
# a CoM height change (which the cart-pole does not offer) and other tiles are refused.
"$program" eval --set plant.kind=cartpole --load-weights exp1/weights/tiles_seed1.txt \
  --set evaluation.body_mass_scale=1.5 >eval.log
grep -q "tiles, seed 1.*on the cartpole plant" eval.log || fail "eval: $(cat eval.log)"
expect_refusal() {  # expected message, then the command
  local expected="$1"
  shift
  set +e
  local output
  output="$("$@" 2>&1)"
  local code=$?
  set -e
  # One line, under the program's own name.
  [[ $code == 2 && "$output" == "cartpole: error: "*"$expected"* && $(wc -l <<<"$output") == 1 ]] ||
    fail "expected exit 2 and one line 'cartpole: error: ...$expected'; got $code: $output"
}
expect_refusal "evaluation.com_height_scale is 0.5, but plant.kind 'cartpole' has no parameter it changes" \
  "$program" eval --set plant.kind=cartpole --set evaluation.com_height_scale=0.5 \
  --load-weights exp1/weights/tiles_seed1.txt
expect_refusal "was made for tiles.per_axis 6; this diagram has tiles.per_axis 5" \
  "$program" eval --set plant.kind=cartpole --set tiles.per_axis=5 \
  --load-weights exp1/weights/tiles_seed1.txt

# plot draws its own arms again; replay shows a trial of the cart-pole (no y, no yaw).
rm exp1/figures/pitch_tiles_omega_half.png
"$program" plot exp1 >/dev/null
test -s exp1/figures/pitch_tiles_omega_half.png || fail "plot did not draw tiles_omega_half"
"$program" replay exp1 --arm tiles_critic_frozen -o replay.html >/dev/null
test -s replay.html || fail "no replay page"

# Its own protocol, a curriculum, through the same commands: a results directory, a kill
# and resume to the same bytes, a sweep over the protocol's own key.
curriculum=(--experiment curriculum --set 'arms=[tiles,lean_pd]' --no-figures)
listed="$("$program" list)"
grep -q "^  curriculum " <<<"$listed" || fail "list does not show the curriculum"
"$program" run "${quick[@]}" "${curriculum[@]}" --out curriculum >/dev/null
grep -q '"experiment": "curriculum"' curriculum/summary.json || fail "no curriculum results"
[[ $(grep -c "^tiles,1," curriculum/trials.csv) -ge 2 ]] || fail "the curriculum ran one trial"
# Its own per-seed figure: a column of figures.csv, compared across arms in summary.json.
head -1 curriculum/figures.csv | grep -qx "arm,seed,warm_up_trials" ||
  fail "the curriculum's figures.csv: $(head -1 curriculum/figures.csv)"
grep -q '"figure": "warm_up_trials"' curriculum/summary.json ||
  fail "the curriculum's summary does not pair warm_up_trials"
set +e
CBBG_FAULT_AT=task:record@2 "$program" run "${quick[@]}" "${curriculum[@]}" \
  --out curriculum_resumed >/dev/null 2>&1
status=$?
set -e
[[ $status == 86 ]] || fail "the killed curriculum exited $status, not at the fault point"
"$program" run --resume curriculum_resumed --jobs 2 >/dev/null
diff -r curriculum curriculum_resumed >/dev/null || fail "the resumed curriculum differs"
# plot draws its own figure (figures.png) beside exp1's.
"$program" plot curriculum >/dev/null
test -s curriculum/figures/figures.png || fail "plot did not draw the curriculum's own figure"
"$program" run "${quick[@]}" "${curriculum[@]}" --set seeds=2 \
  --grid curriculum.first_angle=0.03,0.08 --out curriculum_sweep >/dev/null
[[ $(grep -c "^00[12],0\.0[38],tiles" curriculum_sweep/sweep.csv) == 2 ]] ||
  fail "the curriculum's sweep.csv: $(cat curriculum_sweep/sweep.csv)"
# The same sweep in two shards, then merged: the bytes of the single-process sweep.
for k in 1 2; do
  "$program" run "${quick[@]}" "${curriculum[@]}" --set seeds=2 \
    --grid curriculum.first_angle=0.03,0.08 --shard "$k/2" --out curriculum_shards >/dev/null
done
"$program" merge curriculum_shards >/dev/null
diff -r curriculum_sweep curriculum_shards >/dev/null ||
  fail "the curriculum's merged shards differ from its single-process sweep"

# Train once, evaluate many, under the cart-pole's own parameter and an evaluation key: each
# condition's figures are those of `eval` of the seed's weights with that setting.
"$program" run "${quick[@]}" --experiment transfer --set transfer.training=exp1 \
  --set 'arms=[tiles,lean_pd]' --no-figures \
  --set 'transfer.conditions=[cartpole.pole_mass=1.5, evaluation.noise_std=0.05]' \
  --out transfer >/dev/null
head -1 transfer/figures.csv | grep -qx "arm,seed,balanced@cartpole.pole_mass=1.5,evaluated@cartpole.pole_mass=1.5,balanced@evaluation.noise_std=0.05,evaluated@evaluation.noise_std=0.05" ||
  fail "transfer's figures.csv header: $(head -1 transfer/figures.csv)"
for seed in 1 2 3; do
  for setting in cartpole.pole_mass=1.5 evaluation.noise_std=0.05; do
    "$program" eval --load-weights "transfer/weights/tiles_seed$seed.txt" --set plant.kind=cartpole \
      --set trial.duration=5 --set seed="$seed" --set "$setting" --out "eval_${seed}_$setting" \
      >/dev/null
    expected="$(awk -F, 'NR > 1 { n += $3; e++ } END { print n "," e }' "eval_${seed}_$setting/evaluation.csv")"
    column="$(head -1 transfer/figures.csv | tr ',' '\n' | grep -nx "balanced@$setting" | cut -d: -f1)"
    got="$(awk -F, -v c="$column" -v s="$seed" '$1 == "tiles" && $2 == s { print $c "," $(c + 1) }' \
      transfer/figures.csv)"
    [[ "$got" == "$expected" ]] || fail "transfer seed $seed under $setting: $got, eval: $expected"
  done
done
grep -q '"figure": "balanced@cartpole.pole_mass=1.5"' transfer/summary.json ||
  fail "transfer's summary does not pair the arms under each condition"

# An LQR supervisor designed from the plant in the loop: the cart-pole's linearisation.
"$program" run "${quick[@]}" --set supervisor.kind=lqr --set 'arms=[pd_only]' --no-figures \
  --out lqr >/dev/null
grep -q '"num_succeeded": 3' lqr/summary.json || fail "the cart-pole's LQR did not balance it"
echo "cartpole project: every command worked"
