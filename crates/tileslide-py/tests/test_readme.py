"""The README's Python example runs as written, and says what it gives."""

import re

from conftest import ROOT


def test_the_readme_example_runs_and_its_comments_hold(tmp_path, monkeypatch):
    readme = (ROOT / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", readme, re.S)
    assert len(blocks) == 1
    code = blocks[0].replace('"examples/maps/', f'"{ROOT}/examples/maps/')
    monkeypatch.chdir(tmp_path)
    scope = {}
    exec(compile(code, "README.md", "exec"), scope)
    assert repr(scope["hit"]) == "RayHit(t=0.5, x=8, y=12.5, nx=1, ny=0, cell=(7, 12), tile=1)"
    assert scope["hits"].tolist() == [[0.5, 8.0, 12.5, 1.0, 0.0]]
    assert (tmp_path / "cave.png").read_bytes()[:4] == b"\x89PNG"
