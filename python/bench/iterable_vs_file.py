"""Posting 1,000,000 moves from a Python generator of dicts against the
postc command posting the same moves from a JSON Lines file
(docs/performance.md, "Posting from Python"). Run with a release wheel
installed and a release `postc` binary:

    python python/bench/iterable_vs_file.py target/release/postc [MOVES]
"""

import json
import os
import resource
import pathlib
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "tests"))

import postc  # noqa: E402
from toolpaths import zigzag  # noqa: E402

REPO = pathlib.Path(__file__).resolve().parents[2]
POST = REPO / "corpus" / "posts" / "vectric" / "gcode_mm.pp"


def cpu():
    """CPU seconds of this process (all its threads) and of its children."""
    own = resource.getrusage(resource.RUSAGE_SELF)
    kids = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime


def best(runs, f):
    """The best wall time of `runs` runs, with that run's CPU time."""
    times = []
    result = None
    for _ in range(runs):
        start, start_cpu = time.perf_counter(), cpu()
        result = f()
        times.append((time.perf_counter() - start, cpu() - start_cpu))
    return min(times), result


def main():
    cli = sys.argv[1]
    moves = int(sys.argv[2]) if len(sys.argv) > 2 else 1_000_000
    os.environ["SOURCE_DATE_EPOCH"] = "1767225600"
    with tempfile.TemporaryDirectory() as tmp:
        jsonl = pathlib.Path(tmp) / "zigzag.jsonl"
        with open(jsonl, "w") as f:
            for e in zigzag(moves):
                f.write(json.dumps(e) + "\n")
        out = pathlib.Path(tmp) / "cli.ngc"
        rows = []

        def cli_post(*flags):
            subprocess.run([cli, "-q", "post", *flags, str(POST), str(jsonl), "-o", str(out)], check=True)

        t, _ = best(3, lambda: cli_post("--no-verify"))
        rows.append(("postc post --no-verify, JSON Lines file", t))
        t, _ = best(3, lambda: cli_post())
        rows.append(("postc post (verifying), JSON Lines file", t))
        t, _ = best(3, lambda: sum(1 for _ in zigzag(moves)))
        rows.append(("the generator alone (Python makes the dicts)", t))
        (pathlib.Path(tmp) / "py").mkdir()
        py_out = pathlib.Path(tmp) / "py" / "cli.ngc"
        t, _ = best(3, lambda: postc.post(POST, zigzag(moves), out=py_out, verify=False))
        rows.append(("postc.post(post, generator, out=..., verify=False)", t))
        assert py_out.read_bytes() == out.read_bytes(), "not the command's program"
        t, program = best(3, lambda: postc.post(POST, zigzag(moves), verify=False))
        rows.append(("postc.post(post, generator, verify=False), the text returned", t))
        t, verified = best(3, lambda: postc.post(POST, zigzag(moves)))
        rows.append(("postc.post(post, generator) verifying, the text returned", t))
        assert verified == program

        def serde_path():
            for e in zigzag(moves):
                if isinstance(e, dict) and "Feed" in e:
                    e["Feed"]["feed"] = None  # None: not the fast path; serde reads it
                yield e

        t, slow = best(3, lambda: postc.post(POST, serde_path(), verify=False))
        rows.append(("postc.post(..., verify=False), every move through serde (pythonize)", t))
        assert slow == program
        t, _ = best(3, lambda: sum(len(json.dumps(e)) for e in zigzag(moves)))
        rows.append(("the generator and json.dumps of each event (nothing posted)", t))
        t, _ = best(3, lambda: postc.post(POST, jsonl, verify=False))
        rows.append(("postc.post(post, JSON Lines path, verify=False)", t))
    base = rows[0][1][0]
    print(f"{moves:,} moves, best of 3 (wall time, its ratio to the first row, CPU time of all threads)")
    for name, (wall, used) in rows:
        print(f"| {name} | {wall:.2f} s | {wall / base:.2f} | {used:.2f} s |")


if __name__ == "__main__":
    main()
