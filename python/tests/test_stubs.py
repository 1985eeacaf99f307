"""The committed type stubs are what python/tools/make_stubs.py generates from the module,
and they parse as Python."""
import ast
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def test_stubs_match_the_module():
    r = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "make_stubs.py"), "--check"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


def test_stubs_parse_and_name_every_function():
    import brdftab
    tree = ast.parse(open(os.path.join(ROOT, "brdftab", "__init__.pyi")).read())
    defs = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    assert set(brdftab.quantities()) <= defs
    tree = ast.parse(open(os.path.join(ROOT, "brdftab", "lookup.pyi")).read())
    defs = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    assert set(brdftab.lookup.__all__) == defs
