"""The code of docs/python.md runs as printed: its python blocks in order, in one namespace, from
a directory that holds the source tree's examples/ and the bad deck the page reads (bad.k)."""
import os
import re

from decks import BAD_CONTACT


def test_the_code_of_docs_python_md_runs(tmp_path, source_dir, monkeypatch):
    page = (source_dir / "docs/python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", page, re.S)
    assert len(blocks) >= 6
    os.symlink(source_dir / "examples", tmp_path / "examples")
    (tmp_path / "bad.k").write_text(BAD_CONTACT)
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for number, block in enumerate(blocks, 1):
        try:
            exec(compile(block, f"docs/python.md block {number}", "exec"), namespace)
        except Exception as e:
            raise AssertionError(f"docs/python.md, code block {number} fails: {e!r}") from e
    assert (tmp_path / "t1_out" / "plots" / "energy.png").exists()
    assert (tmp_path / "figures" / "energy.png").exists()
