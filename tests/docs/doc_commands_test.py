#!/usr/bin/env python3
"""Runs the shell blocks of README.md and docs/tutorial.md, so that they stay true.

    doc_commands_test.py SOURCE_DIR BIN_DIR

Every ```sh block of a document runs, in order, with `bash -e -o pipefail`, in
one temporary folder per document laid out like a clone's root (scenes/,
scripts/ and tests/ linked in, so that the commands run as written from a
clone, test data included), with BIN_DIR first on PATH; a block fails the test when
it exits non-zero. Blocks run scaled down, by the substitutions in
SUBSTITUTIONS (printed with every run), so that both documents take well
under two minutes on two cores. Blocks that cannot run here are listed by
name with the reason in NOT_RUN; an entry that names no block fails the test,
so the list cannot go stale. The farm blocks run on a one-node Slurm cluster
started in the temporary folder (tests/farm/local-slurm.sh); the video block
needs ffmpeg (scripts/install-deps.sh installs it).
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

DOCUMENTS = ["README.md", "docs/tutorial.md"]

# Blocks not run, by "document: section heading", with why.
NOT_RUN = {
    "README.md: Quick start":
        "installs packages, builds and runs the whole test suite: scripts/test.sh is CI itself, and "
        "scripts/check-fresh-machine.sh runs both commands on a pristine Debian 12 root",
    "README.md: Building by hand":
        "a fresh configure, a full build, the whole test suite (ctest would run this test inside itself) "
        "and an install: what scripts/test.sh does in CI",
}

# What the blocks of each document leave in its folder (at the scaled frame range).
EXPECTED_FILES = {
    "README.md": ["cornell.png", "quick.png", "shots/beauty.0002.exr", "shots/beauty.0002.png", "shared/shots/beauty.0002.exr",
                  "shared/shots/beauty.0002.png", "spheres.json", "spheres.png", "cloud.orb", "cloud.png", "4hhb.png", "polymer/f.0010.png", "polymer.mp4"],
    "docs/tutorial.md": ["bounce.json", "preview.png", "shots/beauty.0001.exr", "shots/beauty.0002.exr",
                         "shared/bounce/beauty.0002.exr", "shared/bounce/beauty.0002.png", "png/beauty.0002.png",
                         "reference/bounce.0024.exr", "diff.json", "diff.beauty.png", "diff.normal.png",
                         "bounce.mp4"],
}

SIZE = "--width 32 --height 24"
SPP = "--spp 4"
FRAMES = "1-2"
# (what, pattern, replacement): the documented scaling of every block.
SUBSTITUTIONS = [
    ("frame range 1-48 becomes " + FRAMES, r"(?<![\w.-])1-48(?![\w.-])", FRAMES),
    ("--width/--height/--spp given in the text are dropped", r" --(?:width|height|spp) \d+", ""),
    ("orb-render and orb-farm get " + SIZE + " " + SPP,
     r"(?<![\w/.-])(orb-render|orb-farm)(?= )", r"\1 " + SIZE + " " + SPP),
    ("orb-frames --missing gets " + SIZE + " " + SPP + " (the settings it checks the frames against)",
     r"(?<![\w/.-])orb-frames(?= [^\n]*--missing)", "orb-frames " + SIZE + " " + SPP),
    ("orb-farm polls Slurm every second (--poll 1)", r"(?<![\w/.-])orb-farm(?= )", "orb-farm --poll 1"),
    ("--gres gpu:1 is dropped: the test cluster has no GPUs", r" --gres gpu:1", ""),
    ("/shared/ becomes the test folder's shared/", r"(?<![\w.-])/shared/", "{shared}/"),
    ("orb-gen.py --preset 1m becomes --preset 1k", r"--preset 1m\b", "--preset 1k"),
]


def blocks(path):
    """(section heading, index in the section, text) of every ```sh block."""
    heading, index, found, lines, inside = "", 0, [], [], False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if inside:
                if line.startswith("```"):
                    found.append((heading, index, "".join(lines)))
                    inside, lines = False, []
                else:
                    lines.append(line)
            elif line.startswith("```sh"):
                inside, index = True, index + 1
            elif line.startswith("#"):
                heading, index = line.lstrip("#").strip(), 0
    return found


def scaled(text, shared):
    for _, pattern, replacement in SUBSTITUTIONS:
        text = re.sub(pattern, replacement.replace("{shared}", shared), text)
    return text


def make_folder(root, source, name):
    folder = os.path.join(root, name)
    os.makedirs(folder)
    # The folders the documents name, as a clone has them: the commands run as written.
    for linked in ("scenes", "scripts", "tests"):
        os.symlink(os.path.join(source, linked), os.path.join(folder, linked))
    return folder


class Cluster:
    """A one-node Slurm cluster in `folder`, started on first use."""

    def __init__(self, source, folder):
        self.script = os.path.join(source, "tests/farm/local-slurm.sh")
        self.folder = folder
        self.started = False

    def start(self, env):
        if self.started:
            return
        # The daemons keep the descriptors they are given: a file, so that
        # nothing waits on a pipe they hold open.
        with open(os.path.join(os.path.dirname(self.folder), "local-slurm.log"), "w") as log:
            subprocess.run(["bash", self.script, "start", self.folder], env=env, stdout=log, stderr=log,
                           stdin=subprocess.DEVNULL, check=True, timeout=120)
        self.started = True
        env["SLURM_CONF"] = os.path.join(self.folder, "slurm.conf")

    def stop(self):
        if self.started:
            subprocess.run(["bash", self.script, "stop", self.folder], stdin=subprocess.DEVNULL,
                           stdout=subprocess.DEVNULL, timeout=60)


def main():
    source, bin_dir = (os.path.abspath(a) for a in sys.argv[1:3])
    for tool in ("ffmpeg", "oiiotool", "sbatch"):
        if shutil.which(tool) is None:
            print(f"FAIL: {tool} not found; scripts/install-deps.sh installs what this test needs")
            return 1
    root = tempfile.mkdtemp(prefix="orb-doc-commands.")
    os.chmod(root, 0o755)  # munged wants its socket's folders searchable by all
    cluster = Cluster(source, os.path.join(root, "cluster"))
    env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ["PATH"])
    print("substitutions: " + "; ".join(what for what, _, _ in SUBSTITUTIONS))
    failures, names_seen = 0, set()
    try:
        for document in DOCUMENTS:
            folder = make_folder(root, source, os.path.basename(document).removesuffix(".md"))
            shared = os.path.join(folder, "shared")
            for heading, index, text in blocks(os.path.join(source, document)):
                name = f"{document}: {heading}"
                names_seen.add(name)
                label = f"{name} (block {index})"
                if name in NOT_RUN:
                    print(f"not run: {label}: {NOT_RUN[name]}")
                    continue
                script = scaled(text, shared)
                if "orb-farm" in script:
                    os.makedirs(shared, exist_ok=True)
                    cluster.start(env)
                started = time.monotonic()
                try:
                    run = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", script], cwd=folder, env=env,
                                         stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=240)
                    status = run.returncode
                    output = run.stdout + run.stderr
                except subprocess.TimeoutExpired as e:
                    status, output = "timed out", (e.stdout or b"").decode() + (e.stderr or b"").decode()
                seconds = time.monotonic() - started
                if status == 0:
                    print(f"ok: {label} ({seconds:.1f} s)")
                else:
                    failures += 1
                    print(f"FAIL: {label}: exit status {status} after {seconds:.1f} s\n--- ran:\n{script}"
                          f"--- output:\n{output}")
            for expected in EXPECTED_FILES[document]:
                if not os.path.isfile(os.path.join(folder, expected)) or os.path.getsize(os.path.join(folder, expected)) == 0:
                    failures += 1
                    print(f"FAIL: {document}: its commands left no {expected}")
        for name in sorted(set(NOT_RUN) - names_seen):
            failures += 1
            print(f"FAIL: NOT_RUN names '{name}', which is no block's section any more")
    finally:
        cluster.stop()
        shutil.rmtree(root, ignore_errors=True)
    print("doc commands: " + ("all ran" if failures == 0 else f"{failures} failure(s)"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
