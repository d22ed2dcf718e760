"""README.md's Python block runs as written: its ```python block is a doctest, run from the root
of the clone (where its relative paths point)."""

import doctest
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]


def readme_python_blocks():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    return re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)


def test_readme_has_a_python_block():
    blocks = readme_python_blocks()
    assert blocks, "README.md has no ```python block"
    assert all(">>> import chatter" in b for b in blocks[:1])


def test_readme_python_block_runs_as_written(monkeypatch):
    monkeypatch.chdir(ROOT)
    parser, runner = doctest.DocTestParser(), doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    for i, block in enumerate(readme_python_blocks()):
        test = parser.get_doctest(block, {}, f"README.md python block {i + 1}", str(ROOT / "README.md"), 0)
        assert test.examples, f"block {i + 1} has no >>> lines"
        result = runner.run(test)
        assert result.failed == 0, f"README.md python block {i + 1}: {result.failed} of {result.attempted} failed"
