#!/usr/bin/env bash
# Proves the README's commands on a pristine Debian 12 machine: a bookworm
# root made by mmdebstrap (only apt, ca-certificates, git and sudo in it),
# entered with chroot. In one root it clones the committed HEAD and runs
#   1. ./scripts/quickstart.sh          (must render cornell.exr and cornell.png,
#                                         print no compiler warning, and take at
#                                         most ORB_FRESH_QUICKSTART_LIMIT seconds)
#   2. ./scripts/quickstart.sh again    (a no-op: renders nothing, takes seconds)
#   3. pip install . in a virtual environment (docs/python.md), and a render
#      from numpy arrays with the installed module
#   4. ./scripts/test.sh                (the whole suite passes)
#   5. ./scripts/package.sh             (builds the .deb and the wheel)
# and in a second pristine root installs that .deb with `apt install` and
# renders /usr/share/orb/scenes/cornell.scn to a PNG with the installed tools,
# then installs the wheel in a virtual environment and renders from Python.
# Prints the time of each step; exits non-zero when any step fails.
#
#   scripts/check-fresh-machine.sh [--quickstart-only] [--no-tests] [--keep]
#     --quickstart-only  steps 1 and 2 only
#     --no-tests         skip step 3 (the package and the installed .deb still run)
#     --keep             leave the roots in the work folder for a look afterwards
#
# The pristine root is made once and cached as a tarball in
# ORB_FRESH_CACHE (default /var/cache/orb/fresh-machine); each run unpacks a
# fresh copy; delete the tarball to make it again. Where this machine reaches
# package repositories through a proxy with its own CA bundle and pip settings,
# the host's /etc/resolv.conf, /etc/pip.conf (where present) and CA bundle are
# copied into each root, and nothing else. Needs root (chroot, bind mounts).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cache=${ORB_FRESH_CACHE:-/var/cache/orb/fresh-machine}
quickstart_limit=${ORB_FRESH_QUICKSTART_LIMIT:-300}
run_tests=1 run_package=1 keep=0
for argument in "$@"; do
  case $argument in
  --quickstart-only) run_tests=0 run_package=0 ;;
  --no-tests) run_tests=0 ;;
  --keep) keep=1 ;;
  *) echo "check-fresh-machine: unknown argument '$argument' (expected --quickstart-only, --no-tests or --keep)" >&2; exit 2 ;;
  esac
done
[[ $(id -u) == 0 ]] || { echo "check-fresh-machine: needs root (chroot and bind mounts)" >&2; exit 1; }

say() { echo "check-fresh-machine: $*" >&2; }
fail() { say "FAILED: $*"; exit 1; }

if ! command -v mmdebstrap >/dev/null; then
  say "installing mmdebstrap"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends mmdebstrap >/dev/null
fi

commit=$(git -C "$root" rev-parse HEAD)
[[ -z $(git -C "$root" status --porcelain --untracked-files=no) ]] ||
  say "uncommitted changes in $root are left out: checking commit ${commit:0:12}"

work=$(mktemp -d "${TMPDIR:-/var/tmp}/orb-fresh.XXXXXX")
roots=()

# Unmounts everything under a root, deepest first; true only when nothing is
# left mounted there, so that the root's folder is never removed while it
# still reaches the host's /dev, /proc or /sys.
unmount_root() {
  local dir=$1 mounts
  mapfile -t mounts < <(findmnt -rn -o TARGET | grep -E "^$dir(/|$)" | sort -r)
  ((${#mounts[@]} == 0)) || umount -l "${mounts[@]}" 2>/dev/null || true
  ! findmnt -rn -o TARGET | grep -qE "^$dir(/|$)"
}
cleanup() {
  local dir
  for dir in "${roots[@]}"; do
    unmount_root "$dir" || { say "left $work in place: $dir is still mounted"; return; }
  done
  if ((keep)); then say "roots kept in $work"; else rm -rf "$work"; fi
}
trap cleanup EXIT

step_names=() step_seconds=()
timed() {
  local name=$1 start=$SECONDS
  shift
  say "$name ..."
  "$@" || fail "$name (after $((SECONDS - start)) s)"
  step_names+=("$name") step_seconds+=($((SECONDS - start)))
  say "$name: $((SECONDS - start)) s"
}

make_pristine_tarball() {
  mkdir -p "$cache"
  mmdebstrap --quiet --format=tar --variant=apt --include=ca-certificates,git,sudo bookworm "$cache/bookworm.tar.partial"
  mv "$cache/bookworm.tar.partial" "$cache/bookworm.tar"
}
[[ -s $cache/bookworm.tar ]] || timed "make the pristine bookworm root (cached in $cache)" make_pristine_tarball

# A fresh copy of the pristine root with the host's resolver, pip settings
# and CA bundle, /proc, /sys, /dev and /dev/pts mounted.
new_root() {
  local dir=$1
  mkdir -p "$dir"
  roots+=("$dir")
  tar -C "$dir" -xf "$cache/bookworm.tar"
  cp -L /etc/resolv.conf "$dir/etc/resolv.conf"
  [[ ! -e /etc/pip.conf ]] || cp -L /etc/pip.conf "$dir/etc/pip.conf"
  cp -L /etc/ssl/certs/ca-certificates.crt "$dir/etc/ssl/certs/ca-certificates.crt"
  mount -t proc proc "$dir/proc"
  mount --rbind /sys "$dir/sys" && mount --make-rslave "$dir/sys"
  mount --bind /dev "$dir/dev"
  mount --bind /dev/pts "$dir/dev/pts"
}

# Runs a command as root inside a root, in a login-like clean environment:
# nothing of this machine's environment goes in.
in_root() {
  local dir=$1
  shift
  chroot "$dir" /usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin /bin/bash -c "$*"
}

# ---- the README's two commands, in the first root ----
first=$work/quickstart
new_root "$first"
git clone --quiet --no-local --no-checkout "$root" "$first/root/orb"
git -C "$first/root/orb" checkout --quiet --detach "$commit"

mkdir -p "$cache/last-run"
quickstart_log=$cache/last-run/quickstart.log
# Each line with its time, to see where the minutes went.
stamp_lines() { local line; while IFS= read -r line; do printf '%(%T)T %s\n' -1 "$line"; done; }
run_quickstart() { in_root "$first" 'cd /root/orb && ./scripts/quickstart.sh' 2>&1 | stamp_lines | tee "$quickstart_log"; }
timed "quick start (first run)" run_quickstart
for output in cornell.exr cornell.png; do
  [[ -s $first/root/orb/$output ]] || fail "the quick start did not write $output"
done
say "the quick start's output, each line with its time, is in $quickstart_log"
if grep -E '(^|[^a-z])warning:' "$quickstart_log" >&2; then fail "the quick start's output has warnings (above)"; fi
((step_seconds[-1] <= quickstart_limit)) ||
  fail "the quick start took ${step_seconds[-1]} s, more than $quickstart_limit s"

before=$(stat -c %Y "$first/root/orb/cornell.exr" "$first/root/orb/cornell.png")
timed "quick start (second run)" in_root "$first" 'cd /root/orb && ./scripts/quickstart.sh'
[[ $(stat -c %Y "$first/root/orb/cornell.exr" "$first/root/orb/cornell.png") == "$before" ]] ||
  fail "the second quick start wrote its images again; it should find them finished"
((step_seconds[-1] <= 60)) || fail "the second quick start took ${step_seconds[-1]} s; it should be a no-op"

python_render='import numpy as np, orb; s = orb.Scene.from_arrays(np.random.default_rng(1).normal(size=(1000, 3)), 0.05); i = s.render(64, 48, 4); assert i.beauty.shape == (48, 64, 4) and i.beauty[..., :3].max() > 0; print(orb.devices()[0]["name"])'
timed "pip install . in a venv, a render from numpy arrays" in_root "$first" \
  "cd /root/orb && python3 -m venv --system-site-packages /root/orb-venv && /root/orb-venv/bin/pip install --quiet . &&
   cd /tmp && /root/orb-venv/bin/python -c '$python_render'"

if ((run_tests)); then
  timed "test suite (scripts/test.sh)" in_root "$first" 'cd /root/orb && ./scripts/test.sh'
fi
if ((run_package)); then
  timed "package (scripts/package.sh)" in_root "$first" 'cd /root/orb && ./scripts/package.sh'
  deb=$(find "$first/root/orb/out" -maxdepth 1 -name 'orb_*.deb' | head -1)
  [[ -n $deb ]] || fail "scripts/package.sh wrote no orb_*.deb"

  # ---- the .deb, in a second pristine root ----
  second=$work/package
  new_root "$second"
  cp "$deb" "$second/root/"
  install_deb() {
    in_root "$second" "export DEBIAN_FRONTEND=noninteractive && apt-get update -qq &&
      apt-get install -y -qq ./root/$(basename "$deb") >/dev/null"
  }
  timed "apt install ./$(basename "$deb") (second root)" install_deb
  timed "installed tools render cornell.scn to a PNG" in_root "$second" \
    'cd /tmp && orb-render /usr/share/orb/scenes/cornell.scn --width 160 --height 120 --spp 4 -o cornell.exr &&
     orb-tonemap cornell.exr -o cornell.png && test -s cornell.png'
  wheel=$(find "$first/root/orb/out" -maxdepth 1 -name 'orb-*.whl' | head -1)
  [[ -n $wheel ]] || fail "scripts/package.sh wrote no orb-*.whl"
  cp "$wheel" "$second/root/"
  timed "the wheel in a venv renders from numpy arrays (second root)" in_root "$second" \
    "export DEBIAN_FRONTEND=noninteractive && apt-get install -y -qq python3-venv python3-numpy >/dev/null &&
     python3 -m venv --system-site-packages /root/v && /root/v/bin/pip install --quiet /root/$(basename "$wheel") &&
     cd /tmp && /root/v/bin/python -c '$python_render'"
fi

echo
echo "check-fresh-machine: passed at ${commit:0:12}"
for i in "${!step_names[@]}"; do printf '  %5d s  %s\n' "${step_seconds[$i]}" "${step_names[$i]}"; done
