#!/usr/bin/env bash
# orb-capture-pass end to end on PoCL: a later pass written with every file
# orb-cuda-replay reads; a folder already holding files refused; a capture
# that never came named as a failure.
#   capture_pass_test.sh ORB_CAPTURE_PASS_BINARY SCENE
set -uo pipefail
tool=$1
scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_CACHE_HOME=$work/cache
fail() { echo "FAIL: $*"; exit 1; }

"$tool" "$scene" --out "$work/cap" --skip 2 --seconds 2 --width 64 --height 48 > "$work/log" 2>&1 ||
  { cat "$work/log"; fail "the capture failed"; }
grep -q "captured a pass of" "$work/log" || fail "no line naming the capture"
[[ -s $work/cap/launch.txt && -s $work/cap/program.bin ]] || fail "launch.txt or program.bin missing"
grep -qE '^kernel render_pass' "$work/cap/launch.txt" || fail "no kernel line"
args=$(grep -c '^arg ' "$work/cap/launch.txt")
films=$(grep -c '^arg [0-9]* film ' "$work/cap/launch.txt")
[[ $args -gt $films && $films -gt 0 ]] || fail "arguments: $args, film arguments: $films"
while read -r _ index kind bytes file; do
  [[ $(stat -c %s "$work/cap/$file") == "$bytes" ]] || fail "$file is not $bytes bytes"
  if [[ $kind == film ]]; then [[ -s $work/cap/arg$index.after.bin ]] || fail "arg$index.after.bin missing"; fi
done < <(grep '^arg ' "$work/cap/launch.txt")

# Never over another capture.
"$tool" "$scene" --out "$work/cap" --width 64 --height 48 > "$work/log" 2>&1
[[ $? == 2 ]] || fail "a non-empty --out was not refused with status 2"
grep -q "not empty" "$work/log" || fail "no message for the non-empty folder"

# Fewer passes than --skip: status 1 and a message, nothing written.
"$tool" "$scene" --out "$work/late" --skip 1000000 --seconds 1 --width 64 --height 48 > "$work/log" 2>&1
[[ $? == 1 ]] || fail "a capture that never came did not fail"
grep -q "no pass captured" "$work/log" || fail "no message for the missing capture"
[[ ! -e $work/late ]] || fail "a folder was left for a capture that never came"
echo "ok"
