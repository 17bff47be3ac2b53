#!/usr/bin/env bash
# orb-farm without a cluster: usage errors (orb-render's own checks of the
# options after -- among them), the --dry-run script, what a re-run submits
# (absent, partial and other renders, stale images), the collect job, and the
# submission itself against fake sbatch, squeue, scancel and scontrol commands
# that record what they were asked.
#
#   farm_cli_test.sh BIN_DIR SCENES_DIR
#
# BIN_DIR holds orb-farm next to orb-render, orb-frames and orb-tonemap.
set -uo pipefail

bin=$(cd "$1" && pwd)
scenes=$(cd "$2" && pwd)
farm=$bin/orb-farm
scene=$scenes/bounce.gltf
work=$(mktemp -d "${TMPDIR:-/tmp}/orb-farm-cli.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1

failures=0
checks=0
current="(setup)"
problem() {
    printf 'FAIL [%s]: %s\n' "$current" "$*" >&2
    failures=$((failures + 1))
}
section() { current=$1; }

# run CMD...: runs it, keeping status, stdout and stderr.
run() {
    "$@" >"$work/out" 2>"$work/err"
    status=$?
    out=$(<"$work/out")
    err=$(<"$work/err")
}
expect_status() {
    checks=$((checks + 1))
    [[ $status == "$1" ]] || problem "exit status $status, expected $1; stderr: $err"
}
expect_in() { # TEXT WHERE(out|err)
    checks=$((checks + 1))
    local text=$1 where=${2:-out}
    [[ ${!where} == *"$text"* ]] || problem "$where lacks '$text'; $where was: ${!where}"
}
expect_not_in() {
    checks=$((checks + 1))
    local text=$1 where=${2:-out}
    [[ ${!where} != *"$text"* ]] || problem "$where has '$text'; $where was: ${!where}"
}
expect_file() {
    checks=$((checks + 1))
    [[ -e $1 ]] || problem "no file $1"
}
expect_no_file() {
    checks=$((checks + 1))
    [[ ! -e $1 ]] || problem "unexpected file $1"
}

# Frame F of the example animation at 8x6 with N samples, as a task of
# `orb-farm ... --spp N` renders it (frame F has its own seed and time), to
# shots/beauty.%04d.exr; more orb-render options may follow.
render_frame() { # F N [OPTIONS...]
    local frame=$1 spp=$2
    shift 2
    "$bin/orb-render" "$scene" --frame "$frame" --width 8 --height 6 --spp "$spp" -q -o shots/beauty.%04d.exr "$@" ||
        problem "could not render frame $frame"
}

# Renders of one job's script: the `exec` line replaced by a print of frame and samples.
task_assignments() { # SCRIPT TASK-COUNT
    local script=$1 count=$2 i
    for ((i = 0; i < count; i++)); do
        SLURM_ARRAY_TASK_ID=$i SLURM_ARRAY_JOB_ID=1 bash -c "$(sed 's/^exec .*/echo "$frame $slice $first:$count"/' <<<"$script")" 2>/dev/null
    done
}

# The text between the Nth "<<'ORB_FARM_SCRIPT'" and its end marker.
nth_script() { # N TEXT
    awk -v n="$1" '/<<.ORB_FARM_SCRIPT.$/ { k++; if (k == n) { on = 1; next } } /^ORB_FARM_SCRIPT$/ { on = 0 } on' <<<"$2"
}

common=("$scene" --frames 1-4 -o shots/beauty.%04d.exr --width 8 --height 6)

# ---------------------------------------------------------------------------
section "usage errors"
usage_case() { # MESSAGE ARGS...
    local message=$1
    shift
    run "$farm" "$@"
    current="usage: $*"
    expect_status 2
    expect_in "orb-farm: error: " err
    expect_in "$message" err
    expect_in "Run with --help" err
    [[ -z $out ]] || problem "stdout not empty: $out"
}
usage_case "no SCENE" --frames 1-4 -o b.%04d.exr
usage_case "no frames: give --frames" "$scene" -o b.%04d.exr
usage_case "no output: give -o PATTERN" "$scene" --frames 1-4
usage_case "frame list '3-1': the range 3-1 ends before it starts" "$scene" --frames 3-1 -o b.%04d.exr
usage_case "'b.exr' has no frame number" "$scene" --frames 1-4 -o b.exr
usage_case "PATTERN must end in .exr" "$scene" --frames 1-4 -o b.%04d.png
usage_case "put the frame number in the file name, not in a folder name" "$scene" --frames 1-4 -o s/%04d/b.exr
usage_case "--slices 2 needs --spp N" "${common[@]}" --slices 2
usage_case "--slices 5 is more than --spp 4" "${common[@]}" --slices 5 --spp 4
usage_case "--slices: expected a whole number >= 1, got '0'" "${common[@]}" --slices 0
usage_case "--spp: expected a whole number >= 1, got '1e3'" "${common[@]}" --spp 1e3
usage_case "--width: expected a whole number >= 1, got '-3'" "$scene" --frames 1 -o b.%04d.exr --width=-3
usage_case "--fps: expected a positive number, got 'abc'" "${common[@]}" --fps abc
usage_case "--fps: expected a positive number, got '0'" "${common[@]}" --fps 0
usage_case "--tonemap exr would overwrite the rendered frames" "${common[@]}" --tonemap exr
usage_case "--poll: expected a whole number of seconds >= 1" "${common[@]}" --poll 0
usage_case "--time-limit: expected a Slurm time" "${common[@]}" --time-limit soon
usage_case "unknown option --bogus" "${common[@]}" --bogus
usage_case "--dry-run submits nothing to wait for" "${common[@]}" --dry-run --wait
usage_case "--sbatch-arg --array=1-3: orb-farm sets that option itself" "${common[@]}" --sbatch-arg=--array=1-3
usage_case "--sbatch-arg: expected an sbatch option" "${common[@]}" --sbatch-arg account
usage_case "--keep-slices takes no value" "${common[@]}" --keep-slices=yes
usage_case "--frames needs a value" "$scene" -o b.%04d.exr --frames
usage_case "one SCENE only" "${common[@]}" other.json
usage_case "the scene must be a file the nodes can read, not stdin" - --frames 1 -o b.%04d.exr
usage_case "--tonemap bmp: such images keep no record of the frame they were made from" "${common[@]}" --tonemap bmp
# Options after -- that orb-farm gives the tasks itself, or that make no sense for a task.
usage_case "-- --frame: orb-farm gives each orb-render task that option itself" "${common[@]}" -- --frame 3
usage_case "-- -o: orb-farm gives each orb-render task that option itself" "${common[@]}" -- -oother.exr
usage_case "-- --sample-range: orb-farm gives each orb-render task that option itself" "${common[@]}" -- --sample-range=0:4
usage_case "-- --skip-existing: orb-farm gives each orb-render task that option itself" "${common[@]}" -- --skip-existing
usage_case "-- --resume: the tasks continue partial frames and slices themselves" "${common[@]}" -- --resume x.exr
usage_case "-- --claim: Slurm gives each frame (or slice) to one task" "${common[@]}" -- --claim
usage_case "-- --stats-json: every task would write the same file" "${common[@]}" -- --stats-json s.json
usage_case "-- --list-devices: renders no frames" "${common[@]}" -- --list-devices
usage_case "-- --half with --slices 2: orb-merge sums FLOAT slices only" "${common[@]}" --slices 2 --spp 4 -- --half
# The rest orb-render checks itself (orb-render --missing, on this host), with its own message.
usage_case "--mode: nosuch not in {global,direct}" "${common[@]}" -- --mode nosuch
usage_case "--mode: nosuch not in {global,direct}" "${common[@]}" --slices 2 --spp 4 --dry-run -- --mode nosuch
usage_case "--spp: At Most 1 required but received 2" "${common[@]}" --spp 4 -- --spp 8
usage_case "--passes: " "${common[@]}" -- --passes beauty,nosuch
usage_case "unexpected argument 'extra.json' after SCENE " "${common[@]}" -- extra.json
checks=$((checks + 1))
[[ ! -e shots && ! -e b.%04d.exr ]] || problem "a usage error created files: $(ls)"

section "failures and help"
run "$farm" missing.json --frames 1 -o b.%04d.exr
expect_status 1
expect_in "orb-farm: error: missing.json: no such readable file" err
echo '{ "spheres": [' >broken.json
run "$farm" broken.json --frames 1 -o b.%04d.exr --dry-run
expect_status 1
expect_in "orb-farm: error: $work/broken.json:2:1: invalid JSON" err
[[ -z $out ]] || problem "a scene orb-render cannot read gave a script: $out"
rm broken.json
run "$farm" --help
expect_status 0
expect_in "Usage: orb-farm SCENE --frames LIST -o PATTERN"
run "$farm" --version
expect_status 0
expect_in "orb-farm (Orb) "

# ---------------------------------------------------------------------------
section "dry run: frames x slices"
# No Slurm command on PATH: a dry run needs none, and must create nothing.
run env PATH=/usr/bin:/bin "$farm" "${common[@]}" --slices 2 --spp 16 --tonemap png --partition gpu \
    --gres gpu:2 --time-limit 10:00 --cpus-per-task 4 --max-running 3 --sbatch-arg=--account=anim \
    --dry-run -- --mode direct --seed 7
expect_status 0
expect_no_file shots
expect_in "# 8 render task(s): slices of 4 frame(s), 2 slices a frame"
expect_in "# 1 collect job, frames 1-4"
expect_in "--array=0-7%3"
expect_in "--gres=gpu:2"
expect_in "--time=10:00"
expect_in "--cpus-per-task=4"
expect_in "--partition=gpu"
expect_in "--output=$work/shots/orb-farm/logs/render-%A_%a.log"
expect_in "--output=$work/shots/orb-farm/logs/collect-%j.log"
expect_in "--job-name=orb-farm:beauty "
expect_in "--job-name=orb-farm:beauty:collect"
expect_in "--dependency=afterany:\$render_job_1 <<"
expect_in "task_frames=(1 1 2 2 3 3 4 4)"
expect_in "task_slices=(1 2 1 2 1 2 1 2)"
# The tasks continue what a killed task left partial, and skip what is finished.
expect_in "--sample-range \"\$first:\$count\" -o $work/shots/orb-farm/slices/beauty.%04d.s\${slice}of2.exr --mode direct --seed 7 --skip-existing"
# The collect job judges with the same scene and orb-render options.
expect_in "--collect $scene --frames 1-4 -o $work/shots/beauty.%04d.exr --slices 2 --spp 16 --width 8 --height 6 --tonemap png -- --mode direct --seed 7"
checks=$((checks + 1))
[[ $(grep -c -- '--account=anim' <<<"$out") == 2 ]] || problem "--account=anim is not on both sbatch lines"
# Only the render tasks ask for GPUs.
checks=$((checks + 1))
[[ $(grep -c -- '--gres' <<<"$out") == 1 ]] || problem "--gres is on more than the render job"
render_script=$(nth_script 1 "$out")
run task_assignments "$render_script" 8
expect_in "1 1 0:8
1 2 8:8
2 1 0:8
2 2 8:8
3 1 0:8
3 2 8:8
4 1 0:8
4 2 8:8"
# The dry run is itself a shell script.
checks=$((checks + 1))
bash -n <<<"$(PATH=/usr/bin:/bin "$farm" "${common[@]}" --slices 2 --spp 16 --dry-run)" || problem "the dry run is not valid shell"

section "dry run: uneven slices cover every sample once"
run "$farm" "$scene" --frames 7 -o shots/b.%04d.exr --slices 3 --spp 10 --dry-run
expect_status 0
run task_assignments "$(nth_script 1 "$out")" 3
expect_in "7 1 0:3
7 2 3:3
7 3 6:4"

section "dry run: one task per frame"
run "$farm" "$scene" --frames 1-9x4,2 -o shots/b.####.exr --spp 32 --fps 30 --dry-run
expect_status 0
expect_in "# 4 render task(s), frames 1-2,5,9"
expect_in "task_frames=(1 5 9 2)"
expect_in "--frame \"\$frame\" --fps 30 --spp 32 -o $work/shots/b.####.exr --skip-existing"
expect_not_in "collect"
expect_not_in "--sample-range"

section "dry run: --orbit reaches every task with the whole frame list"
run "$farm" "$scene" --frames 1-4 -o shots/turn.%04d.exr --width 8 --height 6 --spp 1 --dry-run -- --orbit 360
expect_status 0
expect_in "-o $work/shots/turn.%04d.exr --orbit 360 --orbit-frames 1-4 --skip-existing"
# A task of frame 3 renders exactly what orb-render --frames 1-4 --orbit 360 asks of frame 3.
orbit_script=$(nth_script 1 "$out")
mkdir -p shots
(cd "$work" && SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_JOB_ID=1 bash -c "$orbit_script" 2>/dev/null) ||
    problem "the orbit task script failed"
run "$bin/orb-render" "$scene" --frames 1-4 -o shots/turn.%04d.exr --width 8 --height 6 --spp 1 --orbit 360 --missing
expect_status 0
checks=$((checks + 1))
[[ $out == $'1\n2\n4' ]] || problem "frame 3 of the orbit task is not the frame orb-render --frames asks for: missing $out"
# The user's own --orbit-frames is kept.
run "$farm" "$scene" --frames 3-4 -o shots/turn.%04d.exr --dry-run -- --orbit 90 --orbit-frames 1-8
expect_status 0
expect_in "--orbit 90 --orbit-frames 1-8 --skip-existing"
expect_not_in "--orbit-frames 3-4"
rm -rf shots

section "orb-render's options given to orb-farm: the scene's (an importer's), and any other"
# A PLY cloud's --radius, given before -- as orb-import and orb-render take it, reaches every task.
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n' >cloud.ply
cloud=(cloud.ply --frames 1-2 -o shots/c.%04d.exr --width 8 --height 6 --spp 2)
run "$farm" "${cloud[@]}" --radius 0.25 --dry-run -- --seed 3
expect_status 0
expect_in "--radius=0.25 --seed 3 --skip-existing"
mkdir -p shots
(cd "$work" && SLURM_ARRAY_TASK_ID=0 SLURM_ARRAY_JOB_ID=1 bash -c "$(nth_script 1 "$out")" 2>/dev/null) ||
    problem "the task script failed"
# Its frame is what orb-render --radius 0.25 renders, not the cloud read without it.
run "$bin/orb-render" cloud.ply --frames 1-2 -o shots/c.%04d.exr --width 8 --height 6 --spp 2 --seed 3 --radius 0.25 --missing
checks=$((checks + 1))
[[ $out == 2 ]] || problem "frame 1 of the task is not orb-render --radius 0.25's: missing '$out'"
run "$bin/orb-render" cloud.ply --frames 1-2 -o shots/c.%04d.exr --width 8 --height 6 --spp 2 --seed 3 --missing
checks=$((checks + 1))
[[ $out == $'1\n2' ]] || problem "--radius did not change the scene the task rendered: missing '$out'"
# A flag of another importer's group is taken, and orb-render's warning passed on.
run "$farm" "${cloud[@]}" --cell --dry-run
expect_status 0
expect_in "--cell --skip-existing"
expect_in "ignored --cell (Molecule input): the input is read as ply" err
rm -rf shots
# Checked by orb-render before anything is submitted or created.
usage_case "--radius: expected a radius > 0, got '-1'" "${cloud[@]}" --radius=-1
usage_case "unknown option --radiuss" "${cloud[@]}" --radiuss 1
usage_case "--non-spheres needs a value" "${cloud[@]}" --non-spheres
usage_case "--cell takes no value" "${cloud[@]}" --cell=yes

section "dry run: more tasks than MaxArraySize"
mkdir -p "$work/fake-slurm"
cat >"$work/fake-slurm/scontrol" <<'EOF'
#!/bin/bash
[[ $* == "show config" ]] && printf 'Configuration data as of now\nMaxArraySize            = 3\nMaxJobCount = 10000\n'
EOF
chmod +x "$work/fake-slurm/scontrol"
run env PATH="$work/fake-slurm:$PATH" "$farm" "${common[@]}" --slices 2 --spp 4 --dry-run
expect_status 0
expect_in "render_job_1=\$(sbatch"
expect_in "render_job_3=\$(sbatch"
expect_not_in "render_job_4"
expect_in "--dependency=afterany:\$render_job_1:\$render_job_2:\$render_job_3"
checks=$((checks + 1))
[[ $(grep -c -- '--array=0-2 ' <<<"$out") == 2 && $(grep -c -- '--array=0-1 ' <<<"$out") == 1 ]] ||
    problem "8 tasks with MaxArraySize 3 are not arrays of 3, 3 and 2"
chunk_tasks=""
for n in 1 2 3; do
    script=$(nth_script "$n" "$out")
    chunk_tasks+=$(task_assignments "$script" "$(grep -o 'task_frames=([^)]*)' <<<"$script" | wc -w)")$'\n'
done
checks=$((checks + 1))
[[ $chunk_tasks == $'1 1 0:2\n1 2 2:2\n2 1 0:2\n2 2 2:2\n3 1 0:2\n3 2 2:2\n4 1 0:2\n4 2 2:2\n' ]] ||
    problem "the three arrays do not cover the 8 tasks once each: $chunk_tasks"

# ---------------------------------------------------------------------------
section "re-run: only frames not finished"
mkdir -p shots
render_frame 1 4
render_frame 3 4
render_frame 4 2 # stopped short of 4 samples, as a task killed or out of time leaves a frame
run "$farm" "${common[@]}" --spp 4 --dry-run
expect_status 0
expect_in "task_frames=(2 4)"
expect_in "--array=0-1 "
expect_in "orb-farm: frame 4: $work/shots/beauty.0004.exr: holds 2 of 4 spp" err
expect_not_in "frame 1:" err
# Fewer samples: frame 4's 2 are enough.
run "$farm" "${common[@]}" --spp 2 --dry-run
expect_in "task_frames=(2)"
# More samples: every frame is partial; its task continues it from its samples.
run "$farm" "${common[@]}" --spp 5 --dry-run
expect_in "task_frames=(1 2 3 4)"
expect_in "frame 1: $work/shots/beauty.0001.exr: holds 4 of 5 spp" err
# The options after -- are part of the render asked for: another seed is another render.
run "$farm" "${common[@]}" --spp 4 --dry-run -- --seed 9
expect_in "task_frames=(1 2 3 4)"
expect_in "frame 3: $work/shots/beauty.0003.exr: rendered with another seed" err
# So are the scene's time (--fps) and the size.
run "$farm" "${common[@]}" --spp 4 --fps 30 --dry-run
expect_in "task_frames=(1 2 3 4)"
expect_in "rendered at scene time" err
run "$farm" "$scene" --frames 1-4 -o shots/beauty.%04d.exr --width 16 --height 12 --spp 4 --dry-run
expect_in "task_frames=(1 2 3 4)"
expect_in "frame 1: $work/shots/beauty.0001.exr: rendered at 8x6, 16x12 asked" err
# Without --spp a frame needs the scene's own count (more than 4).
run "$farm" "${common[@]}" --dry-run
expect_in "task_frames=(1 2 3 4)"

section "re-run: only slices not finished"
mkdir -p shots/orb-farm/slices
render_slice() { # FRAME K START:COUNT
    "$bin/orb-render" "$scene" --frame "$1" --width 8 --height 6 --sample-range "$3" -q \
        -o "shots/orb-farm/slices/beauty.%04d.s${2}of2.exr" || problem "could not render frame $1's slice $2"
}
render_slice 2 1 0:2
render_slice 2 2 2:1 # slice 2 (samples 2:2) stopped short: partial
render_slice 4 2 0:2 # another render: slice 2 holds samples 2:2
run "$farm" "${common[@]}" --spp 4 --slices 2 --dry-run
expect_status 0
expect_in "task_frames=(2 4 4)"
expect_in "task_slices=(2 1 2)"
expect_in "--collect $scene --frames 2,4 "
expect_in "frame 2, slice 2 of 2: $work/shots/orb-farm/slices/beauty.0002.s2of2.exr: holds the samples 2:1 of 2:2" err
expect_in "frame 4, slice 2 of 2: $work/shots/orb-farm/slices/beauty.0004.s2of2.exr: holds the samples 0:2, 2:2 asked" err
expect_not_in "frame 2, slice 1" err

section "collect: merges finished slices into finished frames"
render_slice 2 2 2:2
run "$farm" --collect "$scene" --frames 2 -o shots/beauty.%04d.exr --spp 4 --slices 2 --width 8 --height 6
expect_status 0
expect_in "merged 1 of 1 frames" err
expect_in "all 1 frames are finished" err
expect_no_file shots/orb-farm/slices/beauty.0002.s1of2.exr
# orb-merge's frame is what orb-render itself counts as finished with the same options.
checks=$((checks + 1))
[[ -z $("$bin/orb-render" "$scene" --frames 2 --width 8 --height 6 --spp 4 -o shots/beauty.%04d.exr --missing 2>&1) ]] ||
    problem "orb-render does not count the merged frame 2 as finished"
# The options after -- reach the collect job's judgement: slices of seed 7 merge into frames of seed 7.
rm -f shots/orb-farm/slices/*
"$bin/orb-render" "$scene" --frame 4 --width 8 --height 6 --sample-range 0:2 --seed 7 -q -o shots/orb-farm/slices/beauty.%04d.s1of2.exr
"$bin/orb-render" "$scene" --frame 4 --width 8 --height 6 --sample-range 2:2 --seed 7 -q -o shots/orb-farm/slices/beauty.%04d.s2of2.exr
run "$farm" --collect "$scene" --frames 4 -o shots/beauty.%04d.exr --spp 4 --slices 2 --width 8 --height 6 -- --seed 7
expect_status 0
expect_in "merged 1 of 1 frames" err
run "$farm" "${common[@]}" --spp 4 --dry-run -- --seed 7
expect_in "task_frames=(1 2 3)"
render_frame 4 4 # back to seed 0

section "--denoise: a whole frame's task denoises it; slices are denoised once merged"
run "$farm" "${common[@]}" --spp 4 --denoise --dry-run
expect_status 0
expect_in "--spp 4 -o $work/shots/beauty.%04d.exr --denoise --skip-existing"
run "$farm" "${common[@]}" --spp 4 --slices 2 --denoise --dry-run -- --passes=beauty,depth
expect_status 0
expect_in "--passes=beauty,depth,albedo,normal --skip-existing"
expect_in "--denoise -- --passes=beauty,depth,albedo,normal"
expect_not_in "--denoise --skip-existing"
usage_case "-- --denoise: use orb-farm --denoise" "${common[@]}" --dry-run -- --denoise
rm -f shots/orb-farm/slices/*
for k in 1 2; do
    "$bin/orb-render" "$scene" --frame 3 --width 8 --height 6 --sample-range $(((k - 1) * 2)):2 --passes beauty,albedo,normal \
        -q -o "shots/orb-farm/slices/beauty.%04d.s${k}of2.exr" || problem "could not render frame 3's guided slice $k"
done
run "$farm" --collect "$scene" --frames 3 -o shots/beauty.%04d.exr --spp 4 --slices 2 --width 8 --height 6 --denoise \
    -- --passes beauty,albedo,normal
expect_status 0
expect_in "merged 1 of 1 frames" err
checks=$((checks + 1))
oiiotool --info -v shots/beauty.0003.exr | grep -q 'orb:denoised:' || problem "the collect job did not denoise frame 3"
expect_no_file shots/orb-farm/slices/beauty.f3.merged.exr
expect_no_file shots/orb-farm/slices/beauty.0003.s1of2.exr
render_frame 3 4 # back to a plain frame

section "re-run: images that are absent or stale"
rm -f shots/*.png
render_frame 2 4
"$bin/orb-tonemap" shots/beauty.%04d.exr --frames 1,3,4 -o shots/beauty.%04d.png -q || problem "orb-tonemap failed"
run "$farm" "${common[@]}" --spp 4 --tonemap png --dry-run
expect_status 0
expect_not_in "render_job"
expect_in "collect_job=\$(sbatch"
expect_in "--collect $scene --frames 2 "
expect_not_in "--dependency"
"$bin/orb-tonemap" shots/beauty.0002.exr -o shots/beauty.0002.png -q
run "$farm" "${common[@]}" --spp 4 --tonemap png --dry-run
expect_status 0
expect_in "all 4 frames are finished, with their png images; nothing to submit" err
[[ -z $out ]] || problem "a dry run with nothing to do printed a script: $out"
# Frame 3 rendered again (more samples than asked: still finished): its image is stale.
# Frame 4's image is damaged.
render_frame 3 6
echo image >shots/beauty.0004.png
run "$farm" "${common[@]}" --spp 4 --tonemap png --dry-run
expect_status 0
expect_not_in "render_job"
expect_in "--collect $scene --frames 3-4 "
expect_in "frame 3: $work/shots/beauty.0003.png: its source $work/shots/beauty.0003.exr was rendered again" err
expect_in "frame 4: $work/shots/beauty.0004.png: does not read whole" err

# ---------------------------------------------------------------------------
section "collect: makes stale images again and reports what is missing"
png1_before=$(stat -c %i shots/beauty.0001.png)
run "$farm" --collect "$scene" --frames 1-4 -o shots/beauty.%04d.exr --spp 4 --width 8 --height 6 --tonemap png
expect_status 0
for f in 1 2 3 4; do expect_file "shots/beauty.000$f.png"; done
expect_in "beauty.0003.png: its source $work/shots/beauty.0003.exr was rendered again" err
expect_in "skipped 2 of 4 outputs that are current" err
expect_in "all 4 frames are finished, with their png images" err
checks=$((checks + 1))
[[ $(stat -c %i shots/beauty.0001.png) == "$png1_before" ]] || problem "the current image of frame 1 was made again"
rm shots/beauty.0003.exr
render_frame 4 1
run "$farm" --collect "$scene" --frames 1-4 -o shots/beauty.%04d.exr --spp 4 --width 8 --height 6
expect_status 1
expect_in "orb-farm: error: 2 of 4 frames are not finished: 3-4" err
expect_in "frame 3: $work/shots/beauty.0003.exr: not rendered" err
expect_in "frame 4: $work/shots/beauty.0004.exr: holds 1 of 4 spp" err
expect_in "(no task of it was submitted by orb-farm)" err
expect_in "run the same orb-farm command again" err

# ---------------------------------------------------------------------------
section "submission against fake Slurm commands"
fake=$work/fake-slurm
rm -rf shots "$fake"
mkdir -p "$fake"
cat >"$fake/sbatch" <<'EOF'
#!/bin/bash
# Records the options and the script; answers with the next job id, or fails on request.
d=$(dirname "$0")
n=$(( $(cat "$d/count" 2>/dev/null || echo 0) + 1 ))
echo "$n" >"$d/count"
if [[ -f $d/fail-at && $(<"$d/fail-at") == "$n" ]]; then
    echo "sbatch: error: Batch job submission failed: Invalid partition name specified" >&2
    exit 1
fi
printf '%s\n' "$@" >"$d/job-$((100 + n)).args"
cat >"$d/job-$((100 + n)).sh"
echo "$((100 + n))"
EOF
cat >"$fake/squeue" <<'EOF'
#!/bin/bash
# The queue: the file "queue" for -u; for -j, one line of "states" per call until it runs out.
d=$(dirname "$0")
echo "$*" >>"$d/squeue.calls"
if [[ $* == *" -u "* || $* == "-h -u"* ]]; then cat "$d/queue" 2>/dev/null; exit 0; fi
if [[ -s $d/states ]]; then head -n 1 "$d/states" | tr ' ' '\n'; sed -i 1d "$d/states"; fi
exit 0
EOF
cat >"$fake/scancel" <<'EOF'
#!/bin/bash
echo "$*" >>"$(dirname "$0")/scancel.calls"
EOF
chmod +x "$fake"/*
fake_path="$fake:$PATH"

section "options after -- are checked before Slurm or the disk is touched"
run env PATH="$fake_path" "$farm" "${common[@]}" --slices 2 --spp 4 --tonemap png -- --mode nosuch
expect_status 2
expect_in "orb-farm: error: --mode: nosuch not in {global,direct}" err
[[ -z $out ]] || problem "stdout not empty: $out"
expect_no_file shots
expect_no_file "$fake/count"
expect_no_file "$fake/squeue.calls"

run env PATH="$fake_path" "$farm" "${common[@]}" --slices 2 --spp 4 --tonemap png
expect_status 0
expect_in "101
102"
expect_in "submitted 8 render task(s): slices of 4 frame(s), 2 slices a frame as job 101" err
expect_in "submitted the collect job 102 for frame(s) 1-4, after job 101" err
expect_file "$fake/job-101.sh"
checks=$((checks + 1))
grep -qx -- "--dependency=afterany:101" "$fake/job-102.args" || problem "the collect job does not wait for the render job"
grep -qx -- "--comment=orb-farm $work/shots/beauty.%04d.exr" "$fake/job-101.args" || problem "no orb-farm comment on the render job"
expect_file shots/orb-farm/logs/render-101.sh
expect_file shots/orb-farm/logs/collect-102.sh
checks=$((checks + 1))
cmp -s "$fake/job-101.sh" shots/orb-farm/logs/render-101.sh || problem "the saved render script differs from the submitted one"
checks=$((checks + 1))
grep -q -- "--sample-range \"\$first:\$count\" -o .* --skip-existing\$" "$fake/job-101.sh" ||
    problem "the render tasks do not pass --skip-existing: $(grep '^exec' "$fake/job-101.sh")"
checks=$((checks + 1))
[[ $(sed -n 3p shots/orb-farm/logs/render-101.tasks) == "101_2 2 1 $work/shots/orb-farm/logs/render-101_2.log" ]] ||
    problem "task table line 3: $(sed -n 3p shots/orb-farm/logs/render-101.tasks)"

section "a second submission while the first is queued"
printf '101 orb-farm %s\n102 orb-farm %s\n7 orb-farm %s\n' "$work/shots/beauty.%04d.exr" \
    "$work/shots/beauty.%04d.exr" "$work/other/beauty.%04d.exr" >"$fake/queue"
run env PATH="$fake_path" "$farm" "${common[@]}" --slices 2 --spp 4
expect_status 1
expect_in "job(s) 101 102 for $work/shots/beauty.%04d.exr are still queued or running" err
expect_no_file "$fake/job-103.sh"
run env PATH="$fake_path" "$farm" "${common[@]}" --slices 2 --spp 4 --force -q
expect_status 0
expect_in "103
104"
[[ -z $err ]] || problem "-q printed: $err"
rm -f "$fake/queue"

section "sbatch refuses the collect job"
echo 6 >"$fake/fail-at"
run env PATH="$fake_path" "$farm" "${common[@]}" --slices 2 --spp 4
expect_status 1
expect_in "sbatch refused the collect job: sbatch: error: Batch job submission failed: Invalid partition name specified" err
expect_in "cancelled job(s) 105 submitted before it" err
checks=$((checks + 1))
[[ $(tail -n 1 "$fake/scancel.calls") == 105 ]] || problem "scancel was not asked to cancel job 105"
rm -f "$fake/fail-at"

section "--wait reports frames that did not arrive"
printf 'PENDING PENDING RUNNING\nRUNNING\n' >"$fake/states"
run env PATH="$fake_path" "$farm" "${common[@]}" --spp 4 --wait --poll 1
expect_status 1
expect_in "waiting: 2 pending, 1 running" err
expect_in "waiting: 1 running" err
expect_in "orb-farm: error: 4 of 4 frames are not finished: 1-4" err
expect_in "log $work/shots/orb-farm/logs/render-107_0.log does not exist: the task never started" err
checks=$((checks + 1))
grep -q -- "-h -r -j 107 -o %T" "$fake/squeue.calls" || problem "--wait did not ask squeue about job 107"

printf '%d checks, %d failed\n' "$checks" "$failures"
((failures == 0))
