#!/usr/bin/env bash
# An output into a folder the user may not write to says so, naming the
# folder (not a hidden lock or temporary file), exits 1 and leaves nothing:
# every tool that writes files, run as an unprivileged user (nobody, through
# setpriv), since root writes into any folder and the tests run as root.
#
#   read_only_folder_test.sh BIN_DIR SCENES_DIR
set -uo pipefail

bin=$(cd "$1" && pwd)
scenes=$(cd "$2" && pwd)
skip=77  # ctest's SKIP_RETURN_CODE for this test
work=$(mktemp -d "${TMPDIR:-/tmp}/orb-read-only.XXXXXX")
trap 'chmod -R u+w "$work"; rm -rf "$work"' EXIT
chmod 755 "$work"
cd "$work" || exit 1

# The unprivileged user: nobody, as setpriv makes it (no capabilities, no groups).
as_user() { setpriv --reuid=65534 --regid=65534 --clear-groups --inh-caps=-all "$@"; }
command -v setpriv >/dev/null || { echo "SKIP: setpriv (util-linux) is missing"; exit $skip; }
[[ $(id -u) != 0 ]] && as_user() { "$@"; }  # already unprivileged: the read-only folder refuses this user itself
# The tools run as copies in this folder, with their data beside them as in
# the build tree: the build tree may lie under a folder closed to others (a
# clone in /root, as on a fresh machine), which nobody could not enter.
mkdir -p tools/bin tools/share
for tool in orb-import orb-render orb-tonemap orb-merge orb-diff; do cp "$bin/$tool" tools/bin/; done
cp -R "$bin/../share/." tools/share/
chmod -R a+rX tools
bin=$work/tools/bin

failures=0
checks=0
problem() {
    printf 'FAIL: %s\n' "$*" >&2
    failures=$((failures + 1))
}

"$bin/orb-import" "$scenes/cornell.scn" -q -o cornell.json || problem "orb-import failed"
"$bin/orb-render" cornell.json --width 8 --height 6 --spp 1 -q -o a.exr || problem "orb-render failed"
"$bin/orb-render" cornell.json --width 8 --height 6 --sample-range 1:1 -q -o b.exr || problem "orb-render failed"
chmod 644 cornell.json a.exr b.exr
mkdir ro
chmod 555 ro

refused() { # STATUS OUTPUT COMMAND...: COMMAND, as nobody, is refused for the folder of OUTPUT
    local expected=$1 output=$2
    shift 2
    checks=$((checks + 1))
    as_user env HOME="$work" XDG_CACHE_HOME="$work/cache" "$@" >out.txt 2>err.txt
    local status=$?
    local tool
    tool=$(basename "$1")
    ((status == expected)) || problem "$tool exited $status, not $expected: $(cat err.txt)"
    grep -q "^$tool: error: ro/$output: cannot write (.*): the folder ro is not writable (Permission denied)$" err.txt ||
        problem "$tool says: $(cat err.txt)"
    grep -q "lock\|tmp" err.txt && problem "$tool names a file the user did not ask for: $(cat err.txt)"
    [[ -z $(ls -A ro) ]] || problem "$tool left files in ro: $(ls -A ro)"
}
refused 1 s.json "$bin/orb-import" cornell.json -o ro/s.json
refused 1 r.exr "$bin/orb-render" cornell.json --width 8 --height 6 --spp 1 -o ro/r.exr
refused 1 r.0001.exr "$bin/orb-render" cornell.json --width 8 --height 6 --spp 1 --frames 1-2 -o ro/r.%04d.exr
refused 1 a.png "$bin/orb-tonemap" a.exr -o ro/a.png
refused 1 m.exr "$bin/orb-merge" a.exr b.exr -o ro/m.exr
refused 2 d.json "$bin/orb-diff" a.exr b.exr --json ro/d.json  # orb-diff: 2 is its error status

echo "read_only_folder_test: $checks checks, $failures failures"
((failures == 0))
