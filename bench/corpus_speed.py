#!/usr/bin/python3
"""Speed over the corpus: lumen against POV-Ray on every sample scene lumen renders at >= 40 dB.

    bench/corpus_speed.py [--tsv build/corpus/corpus.tsv] [--lumen build/lumen] [--repeats 3]
                          [--size 640x480] [--threads 2] [--limit 600] [--out FILE] [SUBSTRING ...]

The scenes are the `pass` rows of a corpus report (tools/corpus). Each is rendered at the given
size with +A0.3 (POV-Ray's default anti-aliasing otherwise) and the given thread count, first
frame only, by the two renderers in turn, REPEATS pairs, each in a fresh empty working folder
(scenes may write files). Prints per scene the median wall seconds of each and their ratio,
sorted by ratio, then the geometric mean of the ratios and the scenes above 1/3; writes the same
table as TSV to --out (default docs/corpus_speed.tsv). SUBSTRING arguments keep only the scenes
whose path contains one of them.
"""
import argparse
import csv
import math
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

SCENES = Path("/usr/share/povray-3.7/scenes")
ROOT = Path(__file__).resolve().parent.parent


def wall_seconds(cmd, limit):
    """Runs cmd in a fresh folder; its wall seconds, or None if it failed or ran past limit."""
    with tempfile.TemporaryDirectory() as work:
        start = time.monotonic()
        try:
            done = subprocess.run(cmd, cwd=work, stdout=subprocess.DEVNULL,
                                  stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL,
                                  timeout=limit)
        except subprocess.TimeoutExpired:
            return None
        return time.monotonic() - start if done.returncode == 0 else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tsv", type=Path, default=ROOT / "build/corpus/corpus.tsv")
    ap.add_argument("--lumen", type=Path, default=ROOT / "build/lumen")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--size", default="640x480")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--limit", type=float, default=600)
    ap.add_argument("--out", type=Path, default=ROOT / "docs/corpus_speed.tsv")
    ap.add_argument("only", nargs="*")
    args = ap.parse_args()
    width, height = args.size.split("x")
    with open(args.tsv, newline="") as f:
        scenes = [r["scene"] for r in csv.DictReader(f, delimiter="\t") if r["status"] == "pass"]
    if args.only:
        scenes = [s for s in scenes if any(o in s for o in args.only)]
    if not scenes:
        sys.exit(f"no passing scenes in {args.tsv}" + (" match" if args.only else ""))

    rows = []
    for n, rel in enumerate(scenes, 1):
        scene = SCENES / rel
        opts = [f"+W{width}", f"+H{height}", "+A0.3", "+KFI1", "+KFF1", f"+WT{args.threads}",
                f"+L{scene.parent}", f"+I{scene}"]
        lumen_cmd = [str(args.lumen.resolve())] + opts + ["+Oout.png"]
        pov_cmd = ["povray", "-D", "-V", "+FN"] + opts + ["+Oout.png"]
        lumen, pov = [], []
        for _ in range(args.repeats):  # alternating, so that drifts in speed hit both
            lumen.append(wall_seconds(lumen_cmd, args.limit))
            pov.append(wall_seconds(pov_cmd, args.limit))
        if None in lumen or None in pov:
            print(f"[{n}/{len(scenes)}] {rel}: a render failed or ran past {args.limit} s",
                  file=sys.stderr)
            continue
        row = (rel, statistics.median(lumen), statistics.median(pov))
        rows.append(row + (row[1] / row[2],))
        print(f"[{n}/{len(scenes)}] {rel}: lumen {row[1]:.2f} s, POV-Ray {row[2]:.2f} s, "
              f"ratio {row[1] / row[2]:.3f}", file=sys.stderr, flush=True)

    rows.sort(key=lambda r: r[3])
    print(f"{'scene':<48} {'lumen s':>9} {'POV-Ray s':>10} {'ratio':>7}")
    for rel, l, p, r in rows:
        print(f"{rel:<48} {l:9.2f} {p:10.2f} {r:7.3f}")
    if rows:
        geo = math.exp(sum(math.log(r[3]) for r in rows) / len(rows))
        slow = [r for r in rows if r[3] > 1 / 3]
        print(f"{len(rows)} scenes at {args.size} +A0.3 +WT{args.threads}, {args.repeats} pairs: "
              f"geometric mean ratio {geo:.3f}, {len(slow)} above 0.33")
    with open(args.out, "w", newline="") as f:
        w = csv.writer(f, delimiter="\t")
        w.writerow(["scene", "lumen_s", "povray_s", "ratio"])
        for rel, l, p, r in rows:
            w.writerow([rel, f"{l:.3f}", f"{p:.3f}", f"{r:.4f}"])
    print(f"wrote {args.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
