#!/usr/bin/env bash
# orb-farm on a real one-node Slurm cluster that lives in a temporary folder
# (tests/farm/local-slurm.sh): a 4-frame x 2-slice animation at 64x48, every
# layer, must arrive whole, equal bit for bit to local renders of the same
# samples (orb-diff --fail-threshold 0: no value may differ); a re-run submits
# nothing; a task that fails is reported and a re-run finishes just that; a
# task cancelled mid-render leaves its slice partial, and a re-run submits
# just that slice, whose task continues it from its samples to a frame equal
# bit for bit to an uninterrupted local render.
#
#   farm_slurm_test.sh BIN_DIR SCENES_DIR
#
# Every wait is bounded; the cluster is stopped (by pid) and the folder removed
# however the test ends.
set -uo pipefail

bin=$(cd "$1" && pwd)
scenes=$(cd "$2" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
scene=$scenes/bounce.gltf
started=$EPOCHREALTIME

work=$(mktemp -d "${TMPDIR:-/tmp}/orb-farm-slurm.XXXXXX")
chmod 755 "$work" # munged wants its socket's folders searchable by all
# The daemons are this shell's children, so stopping them also reaps them.
source "$here/local-slurm.sh"
cleanup() {
    local_slurm_stop "$work/cluster"
    rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

failures=0
problem() {
    printf 'FAIL: %s\n' "$*" >&2
    failures=$((failures + 1))
}
# Stops the test at once: later steps depend on this one.
fatal() {
    printf 'FAIL: %s\n' "$*" >&2
    for log in "$work"/cluster/log/*.log; do
        [[ -f $log ]] && { echo "--- $log" >&2; tail -n 15 "$log" >&2; }
    done
    exit 1
}

# Where Debian's Slurm and munge keep their files by default: the cluster must leave them as they were.
system_paths=(/etc/slurm /etc/munge /run/munge /run/slurm /run/slurmctld.pid /run/slurmd.pid /var/run/slurmctld.pid
    /var/run/slurmd.pid /var/lib/slurm /var/spool/slurm /var/spool/slurmd /var/spool/slurmctld /var/log/slurm
    /var/log/munge /var/lib/munge)
system_files() { find "${system_paths[@]}" -printf '%p %s %T@\n' 2>/dev/null | sort; }
system_before=$(system_files)

# Eight render tasks in arrays of at most five: the split into several arrays runs too.
LOCAL_SLURM_EXTRA_CONF="MaxArraySize=5" local_slurm_start "$work/cluster" >/dev/null
[[ $SLURM_CONF == "$work/cluster/slurm.conf" ]] || fatal "the Slurm cluster did not start"

cd "$work" || exit 1
farm=("$bin/orb-farm" "$scene" --frames 1-4 -o shots/beauty.%04d.exr --slices 2 --spp 16 --width 64 --height 48
    --tonemap png --poll 1)
layers=(-- --passes all) # every layer, the variance included, for every render task
# Bounded: orb-farm --wait returns when every job has left the queue.
farm_wait() { timeout 150 "${farm[@]}" --wait "$@" "${layers[@]}"; }

# ---- the whole animation ----
submitted=$EPOCHREALTIME
farm_wait >"$work/out" 2>"$work/err"
status=$?
((status != 124)) || fatal "orb-farm --wait did not finish within 150 s; $(tail -n 5 "$work/err")"
((status == 0)) || fatal "orb-farm --wait failed ($status): $(cat "$work/err")"
farm_seconds=$(awk -v a="$submitted" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }')
grep -q "submitted 8 render task(s): slices of 4 frame(s), 2 slices a frame as job [0-9]* [0-9]*\$" "$work/err" ||
    problem "the 8 tasks were not split into two arrays: $(grep submitted "$work/err")"
[[ $(wc -l <"$work/out") == 3 ]] || problem "expected three job ids on stdout, got: $(cat "$work/out")"

for f in 1 2 3 4; do
    [[ -f shots/beauty.000$f.exr ]] || problem "frame $f did not arrive"
    [[ -s shots/beauty.000$f.png ]] || problem "frame $f has no png"
done
[[ -z $("$bin/orb-frames" 1-4 shots/beauty.%04d.exr --missing --spp 16 --width 64 --height 48 --passes all) ]] ||
    problem "some frames are not complete 16-sample 64x48 renders"
[[ -z $(ls shots/orb-farm/slices) ]] || problem "slices were left after merging: $(ls shots/orb-farm/slices)"
ls shots/orb-farm/logs/render-*_*.log >/dev/null 2>&1 || problem "no render logs next to the outputs"

# Every frame equals a local render of the same 16 samples bit for bit, in
# every layer: the slices' sums are integers, merged exactly.
compare_with_local() { # FRAME
    "$bin/orb-render" "$scene" --frame "$1" --spp 16 --width 64 --height 48 --passes all -q -o "ref.%04d.exr" ||
        { problem "local render of frame $1 failed"; return; }
    local ref farm_frame
    ref=$("$bin/orb-frames" "$1" ref.%04d.exr --paths)
    farm_frame=$("$bin/orb-frames" "$1" shots/beauty.%04d.exr --paths)
    "$bin/orb-diff" "$ref" "$farm_frame" --all-passes --fail-threshold 0 -q >"$work/diff" 2>&1 ||
        problem "frame $1 differs from the local render: $(cat "$work/diff")"
}
for f in 1 2 3 4; do compare_with_local "$f"; done
# Frames differ from each other (the ball moves), so the comparison above could tell them apart.
"$bin/orb-diff" ref.0001.exr ref.0003.exr -q >/dev/null 2>&1 && problem "frames 1 and 3 are identical"

# ---- the same command again submits nothing ----
jobs_before=$(ls shots/orb-farm/logs/*.sh | wc -l)
timeout 60 "${farm[@]}" "${layers[@]}" >"$work/out" 2>"$work/err" || problem "the re-run failed: $(cat "$work/err")"
grep -q "all 4 frames are finished, with their png images; nothing to submit" "$work/err" ||
    problem "the re-run did not say there is nothing to do: $(cat "$work/err")"
[[ -z $(cat "$work/out") ]] || problem "the re-run printed job ids: $(cat "$work/out")"
[[ $(ls shots/orb-farm/logs/*.sh | wc -l) == "$jobs_before" ]] || problem "the re-run submitted jobs"

# ---- a failed task: reported, and a re-run renders only what is missing ----
rm shots/beauty.0003.exr shots/beauty.0003.png
mkdir shots/orb-farm/slices/beauty.0003.s2of2.exr # orb-render cannot write over a folder
farm_wait >"$work/out" 2>"$work/err"
status=$?
((status != 124)) || fatal "orb-farm --wait did not finish within 150 s (failing task)"
((status == 1)) || problem "a failed task gave exit status $status, expected 1"
grep -q "1 of 4 frames are not finished: 3" "$work/err" || problem "the failure report does not name frame 3: $(cat "$work/err")"
grep -q "frame 3, slice 2 of 2 (samples 8:8): .*beauty.0003.s2of2.exr: unreadable (is a directory" "$work/err" ||
    problem "the failure report does not name the slice and why: $(cat "$work/err")"
grep -q "orb-render: error: .*beauty.0003.s2of2.exr" "$work/err" || problem "the failure report does not show the task's log: $(cat "$work/err")"
grep -q "submitted 2 render task(s): slices of 1 frame(s)" "$work/err" || problem "the re-run did not submit just frame 3's slices"

rmdir shots/orb-farm/slices/beauty.0003.s2of2.exr
farm_wait >"$work/out" 2>"$work/err" || problem "finishing frame 3 failed: $(cat "$work/err")"
# Slice 1 of frame 3 survived the failed merge, so only slice 2 is rendered again.
grep -q "submitted 1 render task(s): slices of 1 frame(s), 2 slices a frame" "$work/err" ||
    problem "the last re-run did not submit just the missing slice: $(grep submitted "$work/err")"
compare_with_local 3
[[ -s shots/beauty.0003.png ]] || problem "frame 3 has no png after the re-run"

# ---- a task cancelled mid-render: its slice is continued, not rendered again ----
# One frame in two slices of 12000 samples (about 4.5 s of both cores here),
# each slice checkpointed every half second; slice 2's task is cancelled
# (SIGTERM, as scancel and time limits send it) once its first checkpoint
# exists. The collect job of that submission could only report the slice, so
# it is cancelled too.
long=("$bin/orb-farm" "$scene" --frames 5 -o long/beauty.%04d.exr --slices 2 --spp 24000 --width 64 --height 48
    --poll 1)
checkpoint=long/orb-farm/slices/beauty.0005.s2of2.exr
timeout 60 "${long[@]}" -- --checkpoint 0.5 >"$work/out" 2>"$work/err" || fatal "submitting the long frame failed: $(cat "$work/err")"
long_job=$(head -n 1 "$work/out")
long_collect=$(sed -n 2p "$work/out")
for ((i = 0; i < 300; i++)); do
    [[ -f $checkpoint ]] && break
    sleep 0.1
done
[[ -f $checkpoint ]] || fatal "slice 2 of the long frame wrote no checkpoint within 30 s"
task=$(awk '$3 == 2 { print $1 }' "long/orb-farm/logs/render-$long_job.tasks")
scancel "$task" "$long_collect" || fatal "scancel $task $long_collect failed"
for ((i = 0; i < 600; i++)); do
    [[ -z $(squeue -h 2>/dev/null) ]] && break
    sleep 0.1
done
[[ -z $(squeue -h) ]] || fatal "jobs still queued 60 s after the cancel: $(squeue)"
"$bin/orb-render" "$scene" --frames 5 --width 64 --height 48 --sample-range 12000:12000 -o long/orb-farm/slices/beauty.%04d.s2of2.exr \
    --missing >"$work/out" 2>"$work/err"
grep -q "holds the samples 12000:[0-9]* of 12000:12000" "$work/err" ||
    fatal "the cancelled slice is not partial (was it cancelled too late?): $(cat "$work/err") $(tail -n 3 "long/orb-farm/logs/render-$task.log")"
held=$(sed -n 's/.*holds the samples 12000:\([0-9]*\) of.*/\1/p' "$work/err")
[[ -f long/orb-farm/slices/beauty.0005.s1of2.exr ]] || problem "slice 1 of the long frame was lost"

resubmitted=$EPOCHREALTIME
timeout 150 "${long[@]}" --wait -- --checkpoint 0.5 >"$work/out" 2>"$work/err"
status=$?
continue_seconds=$(awk -v a="$resubmitted" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }')
((status != 124)) || fatal "orb-farm --wait did not finish within 150 s (continuing the cancelled slice)"
((status == 0)) || problem "continuing the cancelled slice failed ($status): $(cat "$work/err")"
grep -q "submitted 1 render task(s): slices of 1 frame(s), 2 slices a frame" "$work/err" ||
    problem "the re-run did not submit just the cancelled slice: $(grep submitted "$work/err")"
grep -q "frame 5, slice 2 of 2: .*holds the samples 12000:$held of 12000:12000" "$work/err" ||
    problem "the re-run did not say why it submits the slice: $(cat "$work/err")"
newest=$(ls long/orb-farm/logs/render-*.tasks | sed 's/.*render-\([0-9]*\)\.tasks$/\1/' | sort -n | tail -n 1)
continued_log=$(awk '{ print $4 }' "long/orb-farm/logs/render-$newest.tasks")
grep -q "holds the samples 12000:$held of 12000:12000: continuing it" "$continued_log" ||
    problem "the task did not continue the slice: $(head -n 5 "$continued_log")"
"$bin/orb-render" "$scene" --frame 5 --spp 24000 --width 64 --height 48 -q -o "ref.%04d.exr" ||
    problem "local render of frame 5 failed"
"$bin/orb-diff" ref.0005.exr long/beauty.0005.exr --all-passes --fail-threshold 0 -q >"$work/diff" 2>&1 ||
    problem "the continued frame 5 differs from an uninterrupted local render: $(cat "$work/diff")"

local_slurm_stop "$work/cluster"
for pid_file in munged slurmctld slurmd; do
    [[ ! -e $work/cluster/$pid_file.pid ]] || problem "$pid_file was not stopped"
done
[[ $(system_files) == "$system_before" ]] || problem "files under /etc, /run or /var changed: $(diff <(echo "$system_before") <(system_files))"

total=$(awk -v a="$started" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }')
printf 'farm_slurm_test: first submission to finished frames: %s s; re-run continuing the cancelled slice: %s s; whole test: %s s\n' \
    "$farm_seconds" "$continue_seconds" "$total"
((failures == 0)) || { printf '%d failures\n' "$failures" >&2; exit 1; }
echo "farm_slurm_test: passed"
