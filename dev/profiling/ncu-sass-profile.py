#!/usr/bin/env python3
"""Where a kernel's lanes and stalls go, by basic block, from Nsight Compute's
per-instruction source counters (docs/design/speculative-traversal.md). Input: the CSV that

    ncu -i REPORT.ncu-rep --page source --csv --print-source sass > sass.csv

writes for a report taken with --set full. Prints the kernel's totals, the
share of each stall reason, and every basic block (a run of instructions
executed equally often, ended by a branch) holding at least --min-share of
the stall samples: its first instruction's index, length, executions,
active lanes per executed instruction, share of the samples and its most
frequent opcodes, which name what the block does (FFMA/FMNMX runs: box or
sphere tests; LOP3/IMAD/BREV: the sampler's hashing; LDL/STL: local memory).

    dev/profiling/ncu-sass-profile.py sass.csv [--min-share 0.01]
"""
import argparse
import collections
import csv
import gzip
import re


def number(text):
    try:
        return float(text.replace(",", ""))
    except ValueError:
        return 0.0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("csv", help="ncu --page source --csv --print-source sass output (.gz accepted)")
    parser.add_argument("--min-share", type=float, default=0.01, help="smallest share of stall samples to list")
    args = parser.parse_args()
    opener = gzip.open if args.csv.endswith(".gz") else open
    with opener(args.csv, "rt") as f:
        rows = list(csv.reader(f))
    header = rows[1]
    col = {name: i for i, name in enumerate(header)}
    stall_names = [h for h in header if h.startswith("stall_") and "Not Issued" not in h]
    instructions = []
    for row in rows[2:]:
        if len(row) < len(header) - 5:
            continue
        instructions.append({
            "source": row[col["Source"]].strip(),
            "samples": number(row[col["Warp Stall Sampling (All Samples)"]]),
            "warp": number(row[col["Instructions Executed"]]),
            "thread": number(row[col["Thread Instructions Executed"]]),
            "stalls": [number(row[col[h]]) for h in stall_names],
        })
    samples = sum(i["samples"] for i in instructions) or 1.0
    warp = sum(i["warp"] for i in instructions) or 1.0
    thread = sum(i["thread"] for i in instructions)
    print(f"{len(instructions)} instructions, {warp:.4g} warp instructions executed, "
          f"{thread / warp:.2f} active lanes per executed instruction, {samples:.0f} stall samples")
    stalls = [sum(i["stalls"][k] for i in instructions) for k in range(len(stall_names))]
    total = sum(stalls) or 1.0
    ranked = sorted(zip(stall_names, stalls), key=lambda p: -p[1])
    print("stalls: " + " ".join(f"{name[6:]} {100 * value / total:.1f}%" for name, value in ranked[:9]))

    blocks, block = [], None
    for n, ins in enumerate(instructions):
        if block and ins["warp"] == block["warp"] and not block["ended"]:
            block["length"] += 1
            block["samples"] += ins["samples"]
            block["thread"] += ins["thread"]
            block["ops"].append(ins["source"])
        else:
            block = {"start": n, "warp": ins["warp"], "length": 1, "samples": ins["samples"],
                     "thread": ins["thread"], "ops": [ins["source"]], "ended": False}
            blocks.append(block)
        if re.match(r"(@!?U?P\w+ )?(BRA|EXIT|RET|CALL|BSYNC|WARPSYNC|BSSY)", ins["source"]):
            block["ended"] = True
    print(f"{'first':>6} {'length':>6} {'executions':>11} {'lanes':>5} {'samples':>7}  opcodes")
    for b in blocks:
        if b["samples"] < args.min_share * samples or b["warp"] == 0:
            continue
        ops = collections.Counter(re.sub(r"^@!?U?P\w+ ", "", o).split()[0].split(".")[0] for o in b["ops"])
        top = " ".join(f"{op}x{count}" for op, count in ops.most_common(7))
        lanes = b["thread"] / (b["warp"] * b["length"])
        print(f"{b['start']:6d} {b['length']:6d} {b['warp']:11.0f} {lanes:5.1f} {100 * b['samples'] / samples:6.1f}%  {top}")


if __name__ == "__main__":
    main()
