"""The Python examples of docs/python.md and the README run as written (in order, one namespace, from the
source folder so that "tables/..." are the committed tables)."""
import os
import re

from conftest import SOURCE_DIR


def test_docs_python_examples_run(monkeypatch):
    text = open(os.path.join(SOURCE_DIR, "docs", "python.md")).read()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(blocks) >= 4
    readme = re.findall(r"```python\n(.*?)```", open(os.path.join(SOURCE_DIR, "README.md")).read(), re.S)
    assert len(readme) == 1
    blocks += readme
    monkeypatch.chdir(SOURCE_DIR)
    monkeypatch.delenv("BRDFTAB_TABLES", raising=False)
    ns = {}
    for i, code in enumerate(blocks):
        exec(compile(code, f"docs/python.md, example {i + 1}", "exec"), ns)
