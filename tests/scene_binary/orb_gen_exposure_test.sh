#!/usr/bin/env bash
# scripts/orb-gen.py's cloud is lit where its camera looks: orb-tonemap's
# automatic exposure (the image's log-average luminance brought to 0.18)
# changes it by less than 1.5 stops. Its earlier lamps, above the box, lit
# only the top, and this cloud needed 4.6 stops (the 1 M preset 4.8): a dark
# front face, and a burnt-out top and floor once brightened.
#
#   orb_gen_exposure_test.sh PYTHON ORB_GEN BIN_DIR
set -euo pipefail
python=$1 orb_gen=$2 bin=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/orb-gen-exposure.XXXXXX")
trap 'rm -rf "$work"' EXIT

"$python" "$orb_gen" --preset 100k -o "$work/cloud.orb"
"$bin/orb-render" "$work/cloud.orb" --width 80 --height 60 --spp 16 -q -o "$work/cloud.exr"
line=$("$bin/orb-tonemap" "$work/cloud.exr" --auto-exposure -o "$work/cloud.png" 2>&1)
stops=$(sed -n 's/.*, exposure \(-\{0,1\}[0-9.]*\) stops$/\1/p' <<<"$line")
echo "$line"
[[ -n $stops ]] || { echo "FAIL: no exposure in: $line" >&2; exit 1; }
awk -v s="$stops" 'BEGIN { exit !(s < 1.5 && s > -1.5) }' ||
    { echo "FAIL: the cloud needs $stops stops of exposure" >&2; exit 1; }
