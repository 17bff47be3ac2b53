#!/usr/bin/env bash
# The man pages and bash completions packaging/cli_reference.py made from each
# tool's --help, and --version, in the build tree:
#   - every option --help lists is in the tool's man page and its completion;
#   - man renders every page without a warning;
#   - the completions offer what the help text says: option names, the words
#     of a choice (--mode global|direct), scene files for a scene, EXRs for
#     an EXR output, directories for a DIR, nothing for a number, and
#     orb-render's devices as `orb-render --list-devices` lists them;
#   - --version names the tool, the project's version, a revision and the
#     libraries built with.
#
#   cli_reference_test.sh BIN_DIR SHARE_DIR VERSION PROGRAM...
set -uo pipefail

bin=$(cd "$1" && pwd)
share=$(cd "$2" && pwd)
version=$3
shift 3
programs=("$@")
work=$(mktemp -d "${TMPDIR:-/tmp}/orb-cli-reference.XXXXXX")
trap 'rm -rf "$work"' EXIT

failures=0
checks=0
problem() {
    printf 'FAIL: %s\n' "$*" >&2
    failures=$((failures + 1))
}
check() { checks=$((checks + 1)); }

((${#programs[@]} >= 7)) || problem "expected at least the seven tools, got: ${programs[*]}"
bash_completion=/usr/share/bash-completion/bash_completion
[[ -r $bash_completion ]] || problem "$bash_completion is missing: install Debian's bash-completion (scripts/install-deps.sh --tests)"
command -v man >/dev/null || problem "man is missing: install Debian's man-db (scripts/install-deps.sh --tests)"

# ---- every option in the man page and the completion; man renders it cleanly ----
for tool in "${programs[@]}"; do
    page=$share/man/man1/$tool.1.gz
    completion=$share/bash-completion/completions/$tool
    [[ -s $page ]] || { problem "$tool: no man page at $page"; continue; }
    [[ -s $completion ]] || { problem "$tool: no completion at $completion"; continue; }
    # The option column: the names at the start of each entry, not the ones
    # the descriptions and examples mention.
    options=$("$bin/$tool" --help | grep -E '^  -' | sed -E 's/^  //; s/  .*//' |
        grep -oE -- '(^|[ ,])--?[A-Za-z0-9][A-Za-z0-9-]*' | sed 's/^[ ,]*//' | sort -u)
    [[ -n $options ]] || problem "$tool --help lists no options"
    roff=$(zcat "$page")
    rendered=$(MANWIDTH=80 man --warnings -l "$page" 2>"$work/man.err")
    [[ -s $work/man.err ]] && problem "$tool: man warns: $(cat "$work/man.err")"
    grep -q "^${tool^^}(1)" <<<"$rendered" || problem "$tool: the rendered page has no ${tool^^}(1) title"
    words=$(grep -oE -- "compgen -W '-[^']*'" "$completion" | head -1)
    for option in $options; do
        check
        grep -qF -- "\\fB${option//-/\\-}\\fR" <<<"$roff" || problem "$tool: $option is not in the man page"
        grep -qE -- "[' ]$option( |')" <<<"$words" || problem "$tool: $option is not among the completion's options"
    done
    bash -n "$completion" || problem "$tool: the completion is not valid bash"
done

# ---- what the completions offer ----
# complete TOOL_PATH WORD...: the candidates bash-completion gives for the
# last WORD of the command line "TOOL WORD...", one a line, sorted.
complete_line() {
    local tool_path=$1
    shift
    (
        cd "$work/files" || exit 1
        # bash-completion's loader would look for a completion by the tool's
        # name; the generated file is sourced directly instead.
        bash -c '
            source "$1" || exit 1
            source "$2" || exit 1
            shift 2
            COMP_WORDS=("$@")
            COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
            COMP_LINE="$*"
            COMP_POINT=${#COMP_LINE}
            function=$(complete -p "$(basename "$1")" | sed -E "s/.* -F ([^ ]+) .*/\1/")
            "$function" "$1" "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD - 1]}"
            printf "%s\n" "${COMPREPLY[@]}"
        ' _ "$bash_completion" "$share/bash-completion/completions/$(basename "$tool_path")" "$tool_path" "$@" |
            sed '/^$/d' | sort
    )
}
expect_offers() { # WHAT EXPECTED... -- TOOL WORD...: every EXPECTED is offered
    local what=$1 expected=()
    shift
    while [[ $1 != -- ]]; do expected+=("$1"); shift; done
    shift
    local offered
    offered=$(complete_line "$@")
    for word in "${expected[@]}"; do
        check
        grep -qxF -- "$word" <<<"$offered" || problem "$what: '$word' not offered for '${*:2}' (offered: $(tr '\n' ' ' <<<"$offered"))"
    done
}
expect_not_offered() { # WHAT UNEXPECTED... -- TOOL WORD...
    local what=$1 unexpected=()
    shift
    while [[ $1 != -- ]]; do unexpected+=("$1"); shift; done
    shift
    local offered
    offered=$(complete_line "$@")
    for word in "${unexpected[@]}"; do
        check
        grep -qxF -- "$word" <<<"$offered" && problem "$what: '$word' offered for '${*:2}'"
    done
}

if [[ -r $bash_completion ]]; then
    mkdir -p "$work/files/shots"  # offered as "shots": bash adds the slash when it shows it
    touch "$work/files/"{box.scn,model.glb,cloud.ply,scene.json,notes.txt,beauty.exr,photo.png}
    render=$bin/orb-render

    expect_offers "option names" --mode --max-depth -- "$render" --m
    expect_offers "choices" global direct -- "$render" --mode ""
    expect_offers "choices" zip piz none -- "$render" --compression ""
    expect_offers "scene files" box.scn model.glb cloud.ply scene.json shots -- "$render" ""
    expect_not_offered "scene files" notes.txt beauty.exr photo.png -- "$render" ""
    expect_offers "an EXR output" beauty.exr -- "$render" -o ""
    expect_not_offered "an EXR output" box.scn photo.png -- "$render" --output ""
    expect_offers "an EXR output after =" beauty.exr -- "$render" --output=""
    expect_offers "a folder" shots -- "$render" --kernel-dir ""
    expect_not_offered "a folder" box.scn beauty.exr -- "$render" --kernel-dir ""
    expect_not_offered "a number" box.scn beauty.exr -- "$render" --spp ""
    # The scene comes once: after it, nothing but options.
    expect_not_offered "a second scene" box.scn -- "$render" box.scn --spp 4 ""
    devices=$("$render" --list-devices 2>/dev/null | awk '$1 ~ /^[0-9]+$/ { print $1 }')
    # shellcheck disable=SC2086 # one word per device index
    expect_offers "devices" all $devices -- "$render" --device ""
    expect_offers "any image for orb-tonemap" beauty.exr photo.png -- "$bin/orb-tonemap" ""
    expect_offers "orb-merge's EXR inputs" beauty.exr -- "$bin/orb-merge" a.exr ""
    expect_not_offered "orb-frames' frame list" box.scn beauty.exr -- "$bin/orb-frames" ""
    expect_offers "orb-frames' file name pattern" beauty.exr -- "$bin/orb-frames" 1-3 ""
    expect_offers "orb-import's environment map" beauty.exr -- "$bin/orb-import" --environment ""
    # Choices too many for a placeholder within 80 columns, listed in the description ("one of: ...").
    expect_offers "orb-import's formats" gltf ply lammps-dump -- "$bin/orb-import" --from ""
    expect_offers "orb-farm's options" --slices --sbatch-arg -- "$bin/orb-farm" --s
fi

# ---- --version ----
for tool in "${programs[@]}"; do
    check
    out=$("$bin/$tool" --version 2>&1) || problem "$tool --version failed: $out"
    [[ $(head -1 <<<"$out") == "$tool (Orb) $version" ]] || problem "$tool --version's first line: $(head -1 <<<"$out")"
    grep -qE '^revision: (git [0-9a-f]{7,}|unknown)' <<<"$out" || problem "$tool --version names no revision: $out"
    for library in OpenCL OpenEXR OpenImageIO OpenColorIO; do
        grep -qE "^  $library +[^ ]" <<<"$out" || problem "$tool --version does not say which $library: $out"
    done
done

echo "cli_reference_test: $checks checks, $failures failures"
((failures == 0))
