#!/usr/bin/env bash
# Two things every tool does the same way, through real processes and pipes:
#  - --help shows each option with a placeholder a reader understands and no
#    parser noise (CLI11's type names, ranges, defaults, Needs:/Excludes:);
#    every option a tool registers is still listed;
#  - a reader that closes the pipe early (`| head -1`) ends the tool as it
#    ends `seq`: killed by SIGPIPE (status 141), with nothing on stderr and no
#    temporary or partial file left behind.
#
#   help_and_pipes_test.sh BIN_DIR SCENES_DIR
set -uo pipefail

bin=$(cd "$1" && pwd)
scenes=$(cd "$2" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/orb-help-pipes.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1

failures=0
problem() {
    printf 'FAIL: %s\n' "$*" >&2
    failures=$((failures + 1))
}

# ---- --help ----
tools=(orb-import orb-render orb-tonemap orb-diff orb-merge orb-frames orb-denoise)
noise=('UINT' 'TEXT' 'FLOAT' 'INT:' '{false}' '{true}' 'in [' 'Excludes:' 'Needs:' 'REQUIRED' 'BOOLEAN')
for tool in "${tools[@]}"; do
    help=$("$bin/$tool" --help 2>"$work/err")
    status=$?
    ((status == 0)) || problem "$tool --help exited $status: $(cat "$work/err")"
    [[ -s $work/err ]] && problem "$tool --help wrote to stderr: $(cat "$work/err")"
    # The usage line and the option column (names and placeholders); the
    # descriptions are the tool's own words and may say "FLOAT".
    columns=$(grep -E '^(Usage:|  [^ ])' <<<"$help" | sed -E 's/^  //; s/  .*//')
    for word in "${noise[@]}"; do
        lines=$(grep -F -- "$word" <<<"$columns")
        [[ -z $lines ]] || problem "$tool --help shows parser noise '$word': $lines"
    done
    listed=$(grep -oE -- '(^|[ ,])--[a-z0-9][a-z0-9-]*' <<<"$help" | sed 's/^[ ,]*//' | sort -u)
    for option in --help --version --quiet; do
        grep -qx -- "$option" <<<"$listed" || problem "$tool --help does not list $option"
    done
done

# Wrapped to the terminal's width, 80 columns when not a terminal (a pipe
# here, and the man pages made from --help): orb-farm's and orb-gen's too.
# Under a terminal of 60 columns (a pseudo-terminal python3 opens), 60.
help_in_terminal() { # COLUMNS TOOL: the tool's --help as a terminal that wide shows it
    python3 - "$@" <<'PY'
import fcntl, os, pty, struct, subprocess, sys, termios
columns, tool = int(sys.argv[1]), sys.argv[2]
leader, follower = pty.openpty()
fcntl.ioctl(follower, termios.TIOCSWINSZ, struct.pack("HHHH", 24, columns, 0, 0))
process = subprocess.Popen([tool, "--help"], stdout=follower, stderr=subprocess.DEVNULL, env=dict(os.environ, TERM="dumb"))
os.close(follower)
text = b""
while True:
    try:
        chunk = os.read(leader, 65536)
    except OSError:  # the follower's last writer is gone
        break
    if not chunk:
        break
    text += chunk
process.wait()
sys.stdout.write(text.decode().replace("\r\n", "\n"))
PY
}
for tool in "${tools[@]}" orb-farm orb-gen; do
    long=$("$bin/$tool" --help | awk 'length($0) > 80')
    [[ -z $long ]] || problem "$tool --help (not a terminal) has lines over 80 columns: $long"
    narrow=$(help_in_terminal 60 "$bin/$tool")
    grep -q -- '--help' <<<"$narrow" || problem "$tool --help in a 60-column terminal printed: $narrow"
    long=$(awk 'length($0) > 60' <<<"$narrow")
    [[ -z $long ]] || problem "$tool --help in a 60-column terminal has longer lines: $long"
done

# Options of every kind (flags, numbers, choices, files, lists) are listed
# by name; tests/cli/help_formatter_test.cpp checks the formatter lists any
# option registered, of any kind.
check_listed() { # TOOL OPTION...
    local tool=$1 option help
    shift
    help=$("$bin/$tool" --help)
    for option in "$@"; do
        grep -qE -- "(^|[ ,])$option([ ,]|\$)" <<<"$help" || problem "$tool --help does not list $option"
    done
}
check_listed orb-render --spp --sample-range --seed --mode --width --height --frames --frame --skip-existing \
    --missing --claim --list-devices --passes --output
check_listed orb-import --output --environment
check_listed orb-tonemap --output --frames --skip-existing --missing --view --exposure
check_listed orb-diff --pass --all-passes --fail-flip --fail-rmse --json --diff-image
check_listed orb-merge --output --denoise
check_listed orb-denoise --output --device --quality --prefilter-aux
check_listed orb-frames --missing --paths

# Placeholders: numbers, choices, files.
help=$("$bin/orb-render" --help)
grep -qE -- '--spp N( |$)' <<<"$help" || problem "orb-render --help: --spp has no N placeholder: $(grep -- --spp <<<"$help")"
grep -qE -- '--mode global\|direct( |$)' <<<"$help" || problem "orb-render --help: --mode does not show its choices"
grep -qE -- '--sample-range START:COUNT( |$)' <<<"$help" || problem "orb-render --help: --sample-range placeholder"
grep -qE -- '-o, --output FILE( |$)' <<<"$help" || problem "orb-render --help: -o has no FILE placeholder"

# ---- a reader closing the pipe early ----
# Runs "$@" into `head -c 1`; the tool's status must be 141 (SIGPIPE) or 0
# (it finished before the reader left), stderr empty.
closes_quietly() { # WHAT COMMAND...
    local what=$1 status
    shift
    "$@" 2>"$work/err" | head -c 1 >/dev/null
    status=${PIPESTATUS[0]}
    ((status == 141 || status == 0)) || problem "$what: exit status $status, expected 141 (SIGPIPE) or 0"
    [[ -s $work/err ]] && problem "$what wrote to stderr: $(cat "$work/err")"
    return 0
}

# Output big enough that the reader is gone before the tool is done.
python3 - <<'EOF'
import struct
n = 200000
with open("big.ply", "wb") as f:
    f.write(b"ply\nformat binary_little_endian 1.0\nelement vertex %d\n" % n)
    f.write(b"property float x\nproperty float y\nproperty float z\nend_header\n")
    for i in range(n):
        f.write(struct.pack("<fff", i * 0.01, (i % 100) * 0.1, (i % 7) * 0.3))
EOF

for i in 1 2 3; do  # a race by nature: each way the reader can leave
    closes_quietly "orb-import big.ply -o - | head -c 1" "$bin/orb-import" big.ply -o -
    closes_quietly "orb-render --list-devices | head -c 1" "$bin/orb-render" --list-devices
    closes_quietly "orb-frames 1-1000000 | head -c 1" "$bin/orb-frames" 1-1000000
    closes_quietly "orb-render --help | head -c 1" "$bin/orb-render" --help
done

# Output that outgrows the pipe's buffer: the reader is certainly gone
# before all of it is written, so the status must be SIGPIPE's.
dies_of_sigpipe() { # WHAT COMMAND...
    local what=$1 status
    shift
    "$@" 2>"$work/err" | head -1 >/dev/null
    status=${PIPESTATUS[0]}
    ((status == 141)) || problem "$what: exit status $status, expected 141 (SIGPIPE)"
    [[ -s $work/err ]] && problem "$what wrote to stderr: $(cat "$work/err")"
    return 0
}
dies_of_sigpipe "orb-frames 1-1000000 | head -1" "$bin/orb-frames" 1-1000000
dies_of_sigpipe "orb-tonemap --missing | head -1" "$bin/orb-tonemap" "missing.%04d.exr" --frames 1-100000 --missing \
    -o "out.%04d.png"
dies_of_sigpipe "orb-import big.ply -o - | head -1" "$bin/orb-import" big.ply -o -
dies_of_sigpipe "orb-render (a 4 MB EXR) -o - | head -1" "$bin/orb-render" "$scenes/cornell.json" --spp 1 --width 256 \
    --height 256 --passes all -q --stats-json big-stats.json -o -
[[ -e big-stats.json ]] && problem "orb-render -o - | head -1 left --stats-json's file, for a render it did not deliver"

# An EXR on stdout (orb-render -o -), orb-diff's report (two equal renders:
# a pass, status 0) and a PNG on stdout: small, so either status is fine, but
# never a message or a file left behind.
"$bin/orb-render" "$scenes/cornell.json" --spp 1 --width 64 --height 48 -q -o ref.exr ||
    problem "cannot render the reference"
"$bin/orb-render" "$scenes/cornell.json" --spp 1 --width 64 --height 48 -q -o test.exr ||
    problem "cannot render the test image"
for i in 1 2 3; do
    closes_quietly "orb-render -o - | head -c 1" "$bin/orb-render" "$scenes/cornell.json" --spp 1 --width 64 \
        --height 48 --stats-json stats.json -q -o -
    closes_quietly "orb-diff report | head -c 1" "$bin/orb-diff" ref.exr test.exr --all-passes --json diff.json
    closes_quietly "orb-tonemap -o - | head -c 1" "$bin/orb-tonemap" ref.exr --format png -q -o -
done
# orb-denoise -o - the same way (OIDN as scripts/install-deps.sh installs it).
"$bin/orb-render" "$scenes/cornell.json" --spp 1 --width 64 --height 48 --passes beauty,albedo,normal -q -o guided.exr ||
    problem "cannot render the image to denoise"
for i in 1 2 3; do
    closes_quietly "orb-denoise -o - | head -c 1" "$bin/orb-denoise" guided.exr -q -o -
done
# With the reader gone before it writes, orb-diff still leaves its JSON report whole.
"$bin/orb-diff" ref.exr test.exr --json report.json 2>"$work/err" | true
[[ -s report.json ]] && python3 -c 'import json, sys; json.load(open("report.json"))' ||
    problem "orb-diff with a closed stdout left no whole JSON report"

# No temporary sibling (".NAME.tmp-PID-RANDOM") or partial file anywhere.
left=$(find . -name '.*.tmp-*')
[[ -z $left ]] || problem "temporary files left behind: $left"

if ((failures > 0)); then
    echo "$failures failure(s)" >&2
    exit 1
fi
echo "help and closed pipes: all good"
