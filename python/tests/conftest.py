"""Shared fixtures of the Python package's tests: the repository, the
`postc` command they compare with (POSTC_BIN, else target/debug/postc), and
the toolpaths they post."""

import json
import os
import pathlib
import shutil
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
SHARED = REPO.parent / "shared"
POST = REPO / "corpus" / "posts" / "vectric" / "gcode_mm.pp"


def cli_path():
    found = os.environ.get("POSTC_BIN") or shutil.which("postc")
    if found:
        return found
    target = os.environ.get("CARGO_TARGET_DIR", str(REPO / "target"))
    return str(pathlib.Path(target) / "debug" / "postc")


@pytest.fixture(scope="session")
def cli():
    """Runs the `postc` command; returns the completed process."""
    path = cli_path()
    if not os.path.exists(path):
        pytest.fail(f"the postc command is not at {path}: build it (cargo build) or set POSTC_BIN")

    def run(*args, check=True):
        env = dict(os.environ, SOURCE_DATE_EPOCH="1767225600")
        done = subprocess.run([path, "-q", *map(str, args)], capture_output=True, env=env)
        if check and done.returncode != 0:
            raise AssertionError(f"postc {' '.join(map(str, args))} failed:\n{done.stderr.decode()}")
        return done

    return run


@pytest.fixture(autouse=True)
def fixed_clock(monkeypatch):
    """[DATE] and [TIME] print the same in the package and the command."""
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1767225600")


def write_jsonl(path, events):
    """Writes events as the native JSON Lines file the command reads."""
    with open(path, "w") as f:
        for e in events:
            f.write(json.dumps(e) + "\n")
    return path


def read_jsonl(path):
    with open(path) as f:
        return [json.loads(line) for line in f if line.strip()]


def field_posts():
    """Real Vectric posts of the shared corpus (the vendors' and the
    machine makers'); CI has them beside the repository."""
    root = SHARED / "corpus" / "vectric"
    if not root.is_dir():
        if os.environ.get("CI") == "true":
            pytest.fail(f"{root} is missing: CI runs beside ../shared")
        return []
    return sorted(root.glob("*/*.pp"))


def same_bytes(program, expected):
    """Whether a program postc returned is the command's bytes: UTF-8, or
    byte for character when the post writes other bytes."""
    if program.encode("utf-8", "surrogateescape") == expected:
        return True
    return all(ord(c) < 256 for c in program) and program.encode("latin-1") == expected
