#!/usr/bin/env bash
# The Debian package as a user gets it, built by cpack from this build folder
# (the binaries the other tests ran; scripts/package.sh makes the release one
# from a clean clone):
#   - lintian: an error fails the test; its warnings are printed, and the
#     maintainer scripts that ran ldconfig for private modules are gone;
#   - its control fields: name, version, Depends from dpkg-shlibdeps;
#   - its files: the tools in /usr/bin, kernels, OCIO config and scenes in
#     /usr/share/orb, a man page and a bash completion for every tool, the
#     copyright and changelog in /usr/share/doc/orb;
#   - unpacked with dpkg -x into a scratch folder, its tools run from there
#     with no Orb or OCIO environment variable: --version, --help, and the
#     Cornell box imported, rendered and tonemapped through the installed
#     OCIO config, the render equal to the build tree's own.
#
#   deb_test.sh BUILD_DIR BIN_DIR VERSION PROGRAM...
set -uo pipefail

build=$(cd "$1" && pwd)
bin=$(cd "$2" && pwd)
version=$3
shift 3
programs=("$@")
work=$(mktemp -d "${TMPDIR:-/tmp}/orb-deb-test.XXXXXX")
trap 'rm -rf "$work"' EXIT

failures=0
problem() {
    printf 'FAIL: %s\n' "$*" >&2
    failures=$((failures + 1))
}
for tool in cpack lintian dpkg-deb dpkg-shlibdeps; do
    command -v "$tool" >/dev/null ||
        { echo "FAIL: $tool is missing: scripts/install-deps.sh --tests installs it" >&2; exit 1; }
done

# ---- build and lint ----
if ! (cd "$build" && cpack -G DEB -B "$work/out") >"$work/cpack.log" 2>&1; then
    cat "$work/cpack.log" >&2
    echo "FAIL: cpack could not build the package" >&2
    exit 1
fi
debs=("$work"/out/orb_*.deb)
((${#debs[@]} == 1)) && [[ -f ${debs[0]} ]] || { echo "FAIL: expected one orb_*.deb, got: ${debs[*]}" >&2; exit 1; }
deb=${debs[0]}
[[ $(basename "$deb") == orb_${version}-*_amd64.deb ]] || problem "unexpected file name $(basename "$deb")"

lintian --fail-on error "$deb" >"$work/lintian.log" 2>&1
lintian_status=$?
grep -v '^running with root privileges' "$work/lintian.log"
((lintian_status == 0)) || problem "lintian reports errors (status $lintian_status)"
grep -q '^E: ' "$work/lintian.log" && problem "lintian: $(grep '^E: ' "$work/lintian.log")"
grep -q 'maintscript-calls-ldconfig' "$work/lintian.log" && problem "lintian: $(grep 'maintscript-calls-ldconfig' "$work/lintian.log")"
for script in postinst postrm; do
    dpkg-deb -I "$deb" "$script" >/dev/null 2>&1 && problem "the package has a $script: $(dpkg-deb -I "$deb" "$script")"
done
grep -q 'python3' <<<"$(dpkg-deb -f "$deb" Depends)" || problem "Depends does not name python3 (orb-gen needs it)"

# ---- control fields ----
[[ $(dpkg-deb -f "$deb" Package) == orb ]] || problem "Package is not orb"
[[ $(dpkg-deb -f "$deb" Version) == "$version"-* ]] || problem "Version $(dpkg-deb -f "$deb" Version) is not $version-*"
depends=$(dpkg-deb -f "$deb" Depends)
for library in libopenexr libopenimageio libopencolorio ocl-icd-libopencl1 libc6; do
    grep -q "$library" <<<"$depends" || problem "Depends does not name $library: $depends"
done

# ---- files ----
contents=$(dpkg-deb -c "$deb" | awk '{ print $6 }')
expect_file() { grep -qxF -- "./$1" <<<"$contents" || problem "the package has no /$1"; }
for tool in "${programs[@]}"; do
    expect_file "usr/bin/$tool"
    expect_file "usr/share/man/man1/$tool.1.gz"
    expect_file "usr/share/bash-completion/completions/$tool"
done
for file in usr/share/orb/ocio/config.ocio usr/share/orb/kernels/integrator.cl usr/share/orb/scenes/cornell.scn \
    usr/lib/orb/orb_texture_decoder.so usr/lib/orb/orb_legend.so usr/share/doc/orb/copyright usr/share/doc/orb/changelog.Debian.gz \
    usr/share/doc/orb/README.md usr/share/doc/orb/docs/orb-render.md; do
    expect_file "$file"
done
while read -r stray; do
    problem "a file outside Orb's places: $stray"
done < <(grep -v '/$' <<<"$contents" |
    grep -v -E '^\./usr/(bin|lib/orb|share/(orb|man/man1|bash-completion/completions|doc/orb))/')

# ---- unpacked, run with no environment of ours ----
root=$work/root
dpkg -x "$deb" "$root" || { echo "FAIL: dpkg -x failed" >&2; exit 1; }
run_installed() { # TOOL ARG...: the unpacked tool, with a bare environment
    local tool=$1
    shift
    env -i PATH=/usr/bin:/bin HOME="$work/home" XDG_CACHE_HOME="${XDG_CACHE_HOME:-$work/cache}" \
        "$root/usr/bin/$tool" "$@"
}
for tool in "${programs[@]}"; do
    out=$(run_installed "$tool" --version) || problem "$tool --version failed"
    [[ $(head -1 <<<"$out") == "$tool (Orb) $version" ]] || problem "installed $tool --version: $(head -1 <<<"$out")"
    run_installed "$tool" --help >"$work/help" || problem "installed $tool --help failed"
    grep -q "Usage: $tool" "$work/help" || problem "installed $tool --help has no usage line"
done
run_installed orb-render --list-devices >"$work/devices" || problem "installed orb-render --list-devices failed"
grep -q '^index' "$work/devices" || problem "installed orb-render --list-devices: $(cat "$work/devices")"

cd "$work" || exit 1
options=(--spp 4 --width 40 --height 30 --seed 3 -q)
run_installed orb-import "$root/usr/share/orb/scenes/cornell.scn" -o box.json -q || problem "installed orb-import failed"
run_installed orb-render box.json "${options[@]}" -o installed.exr || problem "installed orb-render failed"
run_installed orb-tonemap installed.exr -o installed.png -q || problem "installed orb-tonemap (its OCIO config) failed"
# scripts/orb-gen.py, installed as orb-gen under Debian's python3: its scene renders.
head -1 "$root/usr/bin/orb-gen" | grep -qx '#!/usr/bin/python3' || problem "installed orb-gen's shebang: $(head -1 "$root/usr/bin/orb-gen")"
run_installed orb-gen --preset 10 -o ten.orb || problem "installed orb-gen failed"
run_installed orb-render ten.orb "${options[@]}" -o ten.exr || problem "the installed orb-render failed on orb-gen's scene"
[[ -s installed.png ]] || problem "no PNG from the installed orb-tonemap"
# The unpacked tools make what the build tree's make: same scene, same samples.
"$bin/orb-import" "$root/usr/share/orb/scenes/cornell.scn" -q | "$bin/orb-render" - "${options[@]}" -o built.exr ||
    problem "the build tree's orb-render failed"
run_installed orb-diff built.exr installed.exr --fail-rmse 0 -q >/dev/null ||
    problem "the installed orb-render's image differs from the build tree's"

echo "deb_test: $(basename "$deb"), $failures failures"
((failures == 0))
