"""The example of python/README.md, run as it is written there (from a
folder that has the repository's corpus, as its root has)."""

import os
import pathlib
import re
import subprocess
import sys

from conftest import REPO


def readme_example():
    text = (REPO / "python" / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(blocks) == 1, "python/README.md has one Python example"
    return blocks[0]


def test_the_readme_example_runs(tmp_path):
    (tmp_path / "corpus").symlink_to(REPO / "corpus")
    script = tmp_path / "example.py"
    script.write_text(readme_example())
    done = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True, text=True,
                          env=dict(os.environ, PYTHONWARNINGS="error"))
    assert done.returncode == 0, done.stderr
    assert "G21" in done.stdout
    program = (tmp_path / "pocket.ngc").read_text()
    assert "M30" in program
