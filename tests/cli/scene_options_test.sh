#!/usr/bin/env bash
# The options that shape an imported scene are one set, taken with the same
# name and meaning by every tool that reads a scene (orb-farm's share is in
# tests/farm/farm_cli_test.sh), tried on real third-party files:
#   - every option of the importers' groups and of Environment in
#     orb-import --help is in orb-render's and orb-frames' --help, under the
#     same heading;
#   - the same words build the same scene: orb-render FILE OPTIONS renders
#     the image orb-import FILE OPTIONS | orb-render - renders (a Stanford
#     scan's --radius, a Khronos asset's --non-spheres and --environment,
#     haemoglobin's --atom-radius, --no-hydrogens and --cell), and orb-frames
#     --missing --scene FILE OPTIONS judges a frame so rendered finished;
#   - an option no tool has is "unknown option --NAME", in every tool;
#   - a warning never suggests an option the tool at hand rejects.
#
#   scene_options_test.sh BIN_DIR TEST_DATA_DIR
set -uo pipefail

bin=$(cd "$1" && pwd)
data=$(cd "$2" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/orb-scene-options.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1

failures=0
checks=0
problem() {
    printf 'FAIL: %s\n' "$*" >&2
    failures=$((failures + 1))
}

bunny=$data/stanford-bunny/bun_zipper_res4_points.ply
spheres=$data/gltf-sample-assets/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb
haemoglobin=$data/chemfiles-tests-data/4hhb.pdb
polymer=$data/chemfiles-tests-data/polymer-10-frames.lammpstrj
loud=(--width 16 --height 12 --spp 2 --seed 5)
small=("${loud[@]}" -q)

# ---- one set of options, under the same headings ----

# "HEADING<TAB>--option" for each option of the groups HEADING... in TOOL --help.
grouped_options() { # TOOL HEADING...
    local tool=$1
    shift
    "$bin/$tool" --help | awk -v wanted="$(printf '%s\n' "$@")" '
        BEGIN { n = split(wanted, w, "\n"); for (i = 1; i <= n; i++) keep[w[i]] = 1 }
        /^[A-Za-z][^:]*:$/ { heading = substr($0, 1, length($0) - 1); next }
        /^  -/ && (heading in keep) {
            names = substr($0, 3); sub(/  .*/, "", names)
            m = split(names, items, ", ")
            for (i = 1; i <= m; i++) { split(items[i], word, " "); print heading "\t" word[1] }
        }'
}
# The importers' headings, as orb-import --list-formats names them, and the environment's.
mapfile -t headings < <("$bin/orb-import" --list-formats | awk -F '  +' 'NR > 1 && $3 != "-" { print $3 }' | sort -u)
headings+=(Environment)
((${#headings[@]} >= 4)) || problem "expected the glTF, PLY and molecule groups and Environment, got: ${headings[*]}"
# orb-import's --frame picks the frame it writes; orb-render's own --frame renders that frame.
expected=$(grouped_options orb-import "${headings[@]}" | grep -v $'\t--frame$' | sort)
[[ $(wc -l <<<"$expected") -ge 15 ]] || problem "orb-import --help lists too few scene options: $expected"
for tool in orb-render orb-frames; do
    checks=$((checks + 1))
    listed=$(grouped_options "$tool" "${headings[@]}" | sort)
    [[ $listed == "$expected" ]] ||
        problem "$tool's scene options differ from orb-import's: $(diff <(echo "$expected") <(echo "$listed") | grep '^[<>]')"
done

# ---- the same words build the same scene ----

same_scene() { # FILE OPTION...: orb-render FILE OPTIONS renders what orb-import FILE OPTIONS | orb-render - does
    local file=$1
    shift
    checks=$((checks + 1))
    rm -f direct.exr imported.exr imported.json
    "$bin/orb-render" "$file" "$@" "${small[@]}" -o direct.exr 2>direct.err ||
        { problem "orb-render $(basename "$file") $* failed: $(cat direct.err)"; return; }
    # Written beside the input, so that a relative map path means the same file.
    "$bin/orb-import" "$file" "$@" -q -o imported.json || { problem "orb-import $(basename "$file") $* failed"; return; }
    "$bin/orb-render" imported.json "${small[@]}" -o imported.exr || { problem "rendering orb-import's scene failed"; return; }
    "$bin/orb-diff" direct.exr imported.exr --fail-rmse 0 -q >/dev/null ||
        problem "orb-render $(basename "$file") $* differs from orb-import's scene rendered"
}
oiiotool --create 8x4 3 --fill:color=0.2,0.3,0.4 0,0,8,4 -d float -o sky.exr >/dev/null 2>&1 ||
    problem "oiiotool could not make an environment map (scripts/install-deps.sh --tests installs it)"
same_scene "$bunny" --radius 0.002
same_scene "$spheres" --non-spheres bound --environment 0.5,0.6,0.7 --light-units radiometric
same_scene "$spheres" --environment sky.exr --environment-intensity 2 --environment-rotation 30
same_scene "$haemoglobin" --atom-radius covalent --no-hydrogens --cell
same_scene "$polymer" --cell --atom-radius 0.8

# --no-default-light leaves the asset unlit in every tool that reads it.
"$bin/orb-render" "$spheres" --no-default-light "${loud[@]}" -o unlit.exr 2>unlit.err || problem "orb-render --no-default-light failed"
checks=$((checks + 1))
grep -q "the scene has no light" unlit.err || problem "orb-render --no-default-light left a light: $(cat unlit.err)"

# orb-frames --missing judges a frame by the scene the same options build.
"$bin/orb-render" "$bunny" --radius 0.002 "${small[@]}" --frames 1 -o f.%04d.exr || problem "rendering frame 1 failed"
checks=$((checks + 2))
missing=$("$bin/orb-frames" 1 f.%04d.exr --missing --scene "$bunny" --radius 0.002 "${small[@]}") ||
    problem "orb-frames --missing --scene --radius failed"
[[ -z $missing ]] || problem "orb-frames --radius 0.002 judges orb-render --radius 0.002's frame unfinished: $missing"
missing=$("$bin/orb-frames" 1 f.%04d.exr --missing --scene "$bunny" "${small[@]}" 2>/dev/null)
[[ $missing == 1 ]] || problem "orb-frames without --radius judges the frame of another scene finished: '$missing'"

# ---- an option no tool has ----

for tool in orb-import orb-render orb-frames orb-tonemap orb-merge orb-diff orb-denoise orb-farm; do
    checks=$((checks + 1))
    "$bin/$tool" x.json --no-such-option 0.002 >out.txt 2>err.txt
    status=$?
    ((status == 2)) || problem "$tool --no-such-option exited $status"
    grep -q "^$tool: error: unknown option --no-such-option$" err.txt ||
        problem "$tool --no-such-option says: $(cat err.txt)"
done
checks=$((checks + 1))
"$bin/orb-render" "$bunny" --radiuss 0.002 -o x.exr 2>err.txt
grep -qx "orb-render: error: unknown option --radiuss" err.txt || problem "a misspelt option: $(cat err.txt)"

# ---- warnings suggest only options the tool takes ----

# Every --option a warning names is one of the tool's own, or of the tool the
# warning names just before it ("orb-render --frames 1-10", "orb-import --list-formats").
check_suggestions() { # TOOL STDERR-FILE
    local tool=$1 file=$2 mention owner option
    while read -r mention; do
        checks=$((checks + 1))
        owner=$tool option=$mention
        if [[ $mention == orb-* ]]; then owner=${mention%% *} option=${mention#* }; fi
        grep -qE -- "^  (-[a-z], )?$option( |,|$)" <<<"$("$bin/$owner" --help)" ||
            problem "$tool's warning suggests $option, which $owner does not take: $(grep -F -- "$option" "$file")"
    done < <(grep -E 'warning:|^orb-[a-z]+: [^ ]+: ' "$file" | grep -oE -- '(orb-[a-z]+ )?--[a-z][a-z0-9-]*' | sort -u)
}
warned=0
for input in "$spheres" "$bunny" "$polymer" "$haemoglobin"; do
    "$bin/orb-import" "$input" --cell -o scene.json 2>import.err
    check_suggestions orb-import import.err
    "$bin/orb-render" "$input" --cell "${loud[@]}" -o render.exr 2>render.err
    check_suggestions orb-render render.err
    "$bin/orb-frames" 1 g.%04d.exr --missing --scene "$input" --cell "${loud[@]}" >/dev/null 2>frames.err
    check_suggestions orb-frames frames.err
    warned=$((warned + $(grep -c 'warning:' import.err render.err frames.err | awk -F: '{ s += $2 } END { print s }')))
done
((warned >= 8)) || problem "expected the inputs to warn, got $warned warnings"

echo "scene_options_test: $checks checks, $failures failures"
((failures == 0))
