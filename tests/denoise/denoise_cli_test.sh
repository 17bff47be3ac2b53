#!/usr/bin/env bash
# orb-denoise, orb-render --denoise and the `denoised` layer in orb-tonemap
# and orb-diff, through the real executables and Intel Open Image Denoise as
# scripts/install-deps.sh installs it (a missing OIDN fails this test: CI
# installs it).
#  - quality: a 4-spp Cornell box, denoised, against a 512-spp render of it
#    (relMSE from orb-diff): the denoised frame must beat a plain frame of 8
#    times the samples (32 spp), whose relMSE is about an eighth of the 4-spp
#    frame's (it falls as 1/spp). The reference's own error, about a 16th of
#    the 32-spp frame's, counts against both alike. (Measured at seeds 2 to
#    4: 4 spp 0.050-0.065, 32 spp 0.0091-0.0098, denoised 0.0023.);
#  - every input channel kept bit for bit, the layer and orb:denoised added;
#  - standard input and output, and one result for one input;
#  - orb-render --denoise (one image, --half, PIZ, --frames) and orb-merge
#    --denoise write what orb-denoise adds to the same image without it;
#  - bad input: no OIDN (ORB_OIDN_LIBRARY names nothing), not an EXR, no
#    albedo or normal, output == input, a non-EXR output name, a bad option;
#    each with one message, its exit code, and no output left behind.
#
#   denoise_cli_test.sh BIN_DIR SCENES_DIR
set -uo pipefail

bin=$(cd "$1" && pwd)
scenes=$(cd "$2" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/orb-denoise-test.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1

failures=0
problem() {
    printf 'FAIL: %s\n' "$*" >&2
    failures=$((failures + 1))
}
# expect_status WANTED MESSAGE_PART COMMAND...: the command exits WANTED and
# says MESSAGE_PART on stderr, in one "orb-xxx: error:" line.
expect_status() {
    local wanted=$1 part=$2 status
    shift 2
    "$@" >"$work/out" 2>"$work/err"
    status=$?
    ((status == wanted)) || problem "$* exited $status, expected $wanted: $(cat "$work/err")"
    grep -qF -- "$part" "$work/err" || problem "$* did not say '$part': $(cat "$work/err")"
    (($(grep -c ': error: ' "$work/err") == 1)) || problem "$* did not print exactly one error: $(cat "$work/err")"
}
relmse() { # REFERENCE TEST [orb-diff options]: the relMSE orb-diff reports
    "$bin/orb-diff" "$@" --json - 2>/dev/null | python3 -c 'import json,sys; print(json.load(sys.stdin)["passes"][0]["metrics"]["relmse"])'
}
no_leftovers() { # WHAT: no file but those listed in keep.txt
    local extra
    extra=$(ls -A | grep -vxF -f keep.txt)
    [[ -z $extra ]] || problem "$1 left behind: $extra"
}

scene=$scenes/cornell.scn
size=(--width 160 --height 120)
"$bin/orb-render" "$scene" "${size[@]}" --spp 512 --seed 1 -q -o reference.exr || problem "rendering the reference failed"
"$bin/orb-render" "$scene" "${size[@]}" --spp 4 --seed 2 --passes beauty,albedo,normal -q -o noisy.exr ||
    problem "rendering the noisy frame failed"

# ---- quality ----
"$bin/orb-denoise" noisy.exr -o denoised.exr -q || problem "orb-denoise noisy.exr failed"
"$bin/orb-render" "$scene" "${size[@]}" --spp 32 --seed 2 -q -o plain32.exr || problem "rendering 32 spp failed"
noisy=$(relmse reference.exr noisy.exr)
plain32=$(relmse reference.exr plain32.exr)
denoised=$(relmse reference.exr denoised.exr --test-pass denoised)
python3 -c "import sys; n, p, d = $noisy, $plain32, $denoised; sys.exit(0 if d < p < n else 1)" ||
    problem "denoised relMSE $denoised is not below 32 spp's $plain32 (4 spp: $noisy)"
echo "relMSE against 512 spp: 4 spp $noisy, 32 spp $plain32, 4 spp denoised $denoised"

# ---- what the output holds ----
"$bin/orb-diff" noisy.exr denoised.exr --all-passes --fail-rmse 0 -q 2>/dev/null ||
    problem "a layer of the input changed in the output"
info=$(oiiotool --info -v denoised.exr)
grep -q 'orb:denoised: "Intel Open Image Denoise 2\.[0-9.]*, RT filter, hdr, albedo and normal' <<<"$info" ||
    problem "no orb:denoised attribute: $info"
grep -q 'denoised.R, denoised.G, denoised.B' <<<"$info" || problem "no denoised.R/G/B channels: $info"
# The layer in the image tools: orb-tonemap shows it, orb-diff compares it.
"$bin/orb-tonemap" denoised.exr --pass denoised -q -o denoised.png || problem "orb-tonemap --pass denoised failed"
"$bin/orb-tonemap" denoised.exr -q -o beauty.png || problem "orb-tonemap of the beauty failed"
cmp -s denoised.png beauty.png && problem "orb-tonemap --pass denoised shows the beauty"
# --layer is --pass under the name the film's layer table uses.
"$bin/orb-tonemap" denoised.exr --layer denoised -q -o layer.png || problem "orb-tonemap --layer denoised failed"
cmp -s layer.png denoised.png || problem "orb-tonemap --layer denoised differs from --pass denoised"
expect_status 1 "no 'denoised' pass" "$bin/orb-tonemap" noisy.exr --pass denoised -o x.png
"$bin/orb-diff" denoised.exr denoised.exr --pass denoised --fail-rmse 0 -q || problem "orb-diff --pass denoised failed"
"$bin/orb-diff" denoised.exr denoised.exr --layer denoised --test-layer denoised --fail-rmse 0 -q || problem "orb-diff --layer/--test-layer denoised failed"
expect_status 2 "no 'denoised' pass" "$bin/orb-diff" reference.exr noisy.exr --test-pass denoised

# Denoising a denoised file replaces the layer; standard input and output
# give the same file as paths do.
"$bin/orb-denoise" denoised.exr -o again.exr -q || problem "orb-denoise of a denoised file failed"
"$bin/orb-diff" denoised.exr again.exr --all-passes --fail-rmse 0 -q 2>/dev/null || problem "denoising again changed the image"
"$bin/orb-denoise" - -o - -q <noisy.exr >piped.exr || problem "orb-denoise - -o - failed"
"$bin/orb-diff" denoised.exr piped.exr --all-passes --fail-rmse 0 -q 2>/dev/null || problem "stdin/stdout gave another image"

# A HALF beauty gives a HALF layer.
"$bin/orb-render" "$scene" --width 32 --height 24 --spp 2 --passes beauty,albedo,normal --half -q -o half.exr &&
    "$bin/orb-denoise" half.exr -o half-denoised.exr -q || problem "denoising a --half render failed"
oiiotool --info -v half-denoised.exr | grep -q 'denoised.R (half)\|channel formats: .*half' ||
    problem "the layer of a HALF image is not HALF"

# orb-render --denoise: the guides are added to the passes, the layer is
# written, checkpoints aside.
"$bin/orb-render" "$scene" --width 32 --height 24 --spp 2 --denoise -q -o rendered.exr --stats-json stats.json ||
    problem "orb-render --denoise failed"
info=$(oiiotool --info -v rendered.exr)
grep -q 'orb:passes: "beauty,albedo,normal"' <<<"$info" || problem "--denoise did not add albedo,normal: $info"
grep -q 'orb:denoised:' <<<"$info" || problem "orb-render --denoise wrote no denoised layer"
# --stats-json reports the denoiser's time (positive), and only with --denoise.
# The whole layer's time holds its parts: the wait for set-up and the filter.
python3 -c 'import json, sys; j = json.load(open(sys.argv[1])); d, s, f = j["denoise_seconds"], j["denoise_setup_seconds"], j["denoise_filter_seconds"]; sys.exit(0 if f > 0 and s >= 0 and d >= s + f else 1)' stats.json ||
    problem "--stats-json has no positive denoise_seconds holding its set-up and filter times: $(cat stats.json)"
"$bin/orb-render" "$scene" --width 32 --height 24 --spp 2 -q -o plain-stats.exr --stats-json plain-stats.json &&
    ! grep -q denoise_seconds plain-stats.json || problem "--stats-json without --denoise has denoise_seconds"

# orb-render --denoise writes the layer in its one encode: the same file as
# rendering the guides and running orb-denoise on it (every layer, the
# denoised one included, value for value; every attribute but the timing),
# for a single image with each writer (ZIP, PIZ), under --half, and for each
# frame of --frames.
same_as_orb_denoise() { # WHAT RENDERED PLAIN: RENDERED (--denoise) against orb-denoise of PLAIN
    local what=$1 rendered=$2 plain=$3
    "$bin/orb-denoise" "$plain" -o "$plain.denoised.exr" -q || { problem "$what: orb-denoise failed"; return; }
    "$bin/orb-diff" "$plain.denoised.exr" "$rendered" --all-passes --fail-rmse 0 -q 2>/dev/null ||
        problem "$what: a layer differs from the plain render's"
    "$bin/orb-diff" "$plain.denoised.exr" "$rendered" --layer denoised --test-layer denoised --fail-rmse 0 -q 2>/dev/null ||
        problem "$what: the denoised layer differs from orb-denoise's"
    diff <(oiiotool --info -v "$plain.denoised.exr" | sed 1,2d | grep -v 'orb:renderSeconds') \
        <(oiiotool --info -v "$rendered" | sed 1,2d | grep -v 'orb:renderSeconds') >/dev/null ||
        problem "$what: the channels or attributes differ from orb-denoise's: $(diff <(oiiotool --info -v "$plain.denoised.exr") <(oiiotool --info -v "$rendered"))"
}
small=(--width 40 --height 30 --spp 3 --seed 5)
for variant in "zip" "piz --compression piz" "half --half"; do
    name=${variant%% *}
    extra=()
    [[ $variant == *" "* ]] && read -ra extra <<<"${variant#* }"
    "$bin/orb-render" "$scene" "${small[@]}" "${extra[@]}" --denoise -q -o "one-$name.exr" &&
        "$bin/orb-render" "$scene" "${small[@]}" "${extra[@]}" --passes beauty,albedo,normal -q -o "one-$name-plain.exr" ||
        problem "rendering $name failed"
    same_as_orb_denoise "--denoise ($name)" "one-$name.exr" "one-$name-plain.exr"
done
"$bin/orb-render" "$scene" "${small[@]}" --frames 1-3 --orbit 360 --denoise -q -o "frame.%d.exr" --stats-json frames.json &&
    "$bin/orb-render" "$scene" "${small[@]}" --frames 1-3 --orbit 360 --passes beauty,albedo,normal -q -o "plain.%d.exr" ||
    problem "rendering --frames failed"
for frame in 1 2 3; do same_as_orb_denoise "--frames, frame $frame" "frame.$frame.exr" "plain.$frame.exr"; done
python3 -c 'import json, sys; f = json.load(open(sys.argv[1]))["frames"]; sys.exit(0 if len(f) == 3 and all(x["denoise_seconds"] > 0 for x in f) else 1)' frames.json ||
    problem "--frames --stats-json lacks a frame's denoise_seconds: $(cat frames.json)"
# orb-merge --denoise (orb-farm's collect job) likewise: the merge denoised in its one encode.
for k in 0 1; do
    "$bin/orb-render" "$scene" --width 40 --height 30 --seed 5 --sample-range $((3 * k)):3 --passes beauty,albedo,normal -q -o "slice$k.exr" ||
        problem "rendering slice $k failed"
done
"$bin/orb-merge" slice0.exr slice1.exr --denoise -q -o merged-denoised.exr &&
    "$bin/orb-merge" slice0.exr slice1.exr -q -o merged.exr || problem "orb-merge failed"
same_as_orb_denoise "orb-merge --denoise" merged-denoised.exr merged.exr

# ---- bad input ----
ls -A >keep.txt
sum=$(sha256sum noisy.exr)
expect_status 1 "ORB_OIDN_LIBRARY" env ORB_OIDN_LIBRARY="$work/nothing-here.so" "$bin/orb-denoise" noisy.exr -o out.exr
grep -qF "scripts/install-deps.sh" "$work/err" || problem "the missing-OIDN message does not say how to install it"
no_leftovers "orb-denoise without OIDN"
expect_status 1 "ORB_OIDN_LIBRARY" env ORB_OIDN_LIBRARY="$work/nothing-here.so" "$bin/orb-render" "$scene" \
    --width 8 --height 8 --spp 1 --denoise -o out.exr
no_leftovers "orb-render --denoise without OIDN"
echo "not an image" >text.exr
echo text.exr >>keep.txt
expect_status 1 "text.exr: not an OpenEXR file" "$bin/orb-denoise" text.exr -o out.exr
expect_status 1 "no albedo layer (albedo.R, albedo.G, albedo.B) and no normal layer" "$bin/orb-denoise" reference.exr -o out.exr
expect_status 1 "the merged image: no albedo layer" "$bin/orb-merge" reference.exr --denoise -o out.exr
expect_status 1 "ORB_OIDN_LIBRARY" env ORB_OIDN_LIBRARY="$work/nothing-here.so" "$bin/orb-merge" noisy.exr --denoise -o out.exr
expect_status 1 "nothing.exr" "$bin/orb-denoise" nothing.exr -o out.exr
expect_status 2 "refusing to overwrite an input" "$bin/orb-denoise" noisy.exr -o ./noisy.exr
expect_status 2 "OpenEXR only" "$bin/orb-denoise" noisy.exr -o out.png
expect_status 2 "unknown denoising device 'gpu'" "$bin/orb-denoise" noisy.exr -o out.exr --device gpu
expect_status 2 "unknown quality 'best'" "$bin/orb-denoise" noisy.exr -o out.exr --quality best
expect_status 2 "missing -o/--output" "$bin/orb-denoise" noisy.exr
[[ $(sha256sum noisy.exr) == "$sum" ]] || problem "an error changed the input"
no_leftovers "the bad-input runs"

if ((failures)); then
    echo "$failures failure(s)" >&2
    exit 1
fi
echo "all checks passed"
