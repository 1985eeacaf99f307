"""`brdftab export` outputs read back by independent readers: NumPy for .npy (values and
axes equal the HDF5 file's, read with h5py), glslangValidator for the GLSL snippet (compiled
in a fragment shader for every 1-D/2-D table)."""
import glob
import os
import shutil
import subprocess

import h5py
import numpy as np
import pytest

EXE = os.environ["BRDFTAB_EXE"]
TABLE_DIR = os.environ["BRDFTAB_TABLE_DIR"]


def tables(max_rank=4):
    out = []
    for path in sorted(glob.glob(os.path.join(TABLE_DIR, "*.h5"))):
        with h5py.File(path, "r") as f:
            out += [(path, n) for n in f if f[n][n].ndim <= max_rank]
    return out


def ident(name):
    """The file and identifier stem export uses: the table name with every character that
    is not a letter, digit or '_' replaced by '_' (e.g. p0.5 -> p0_5)."""
    return "".join(c if c.isalnum() or c == "_" else "_" for c in name)


def export(path, name, fmt, out):
    r = subprocess.run([EXE, "export", path, name, "--format", fmt, "--out", str(out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stdout.split()


def test_npy_holds_the_values_and_axes(tmp_path):
    for path, name in tables():
        files = export(path, name, "npy", tmp_path)
        with h5py.File(path, "r") as f:
            v = f[name][name]
            a = np.load(tmp_path / f"{ident(name)}.npy")
            assert a.dtype == v.dtype and a.shape == v.shape
            np.testing.assert_array_equal(a, v[()])
            for dim in v.dims:
                axis = dim[0].attrs["name"]
                np.testing.assert_array_equal(np.load(tmp_path / f"{ident(name)}.{ident(axis)}.npy"), dim[0][()])
            assert len(files) == 1 + v.ndim


def test_glsl_compiles_for_every_1d_2d_table(tmp_path):
    validator = shutil.which("glslangValidator")
    assert validator, "glslangValidator missing (Debian glslang-tools; scripts/install-deps.sh)"
    count = 0
    for path, name in tables(max_rank=2):
        export(path, name, "glsl", tmp_path)
        snippet = (tmp_path / f"{ident(name)}.glsl").read_text()
        with h5py.File(path, "r") as f:
            rank = f[name][name].ndim
        args = "p.x" if rank == 1 else "p.x, p.y"
        shader = tmp_path / f"{ident(name)}.frag"
        shader.write_text("#version 330 core\nuniform sampler2D tab;\nin vec2 p;\nout vec4 color;\n" + snippet +
                          f"void main() {{ color = vec4({ident(name)}_lookup(tab, {args})); }}\n")
        r = subprocess.run([validator, str(shader)], capture_output=True, text=True)
        assert r.returncode == 0, r.stdout + r.stderr
        count += 1
    assert count >= 10


def test_glsl_refuses_a_3d_table(tmp_path):
    r = subprocess.run([EXE, "export", os.path.join(TABLE_DIR, "ghs_sigma_rel.h5"), "ghs_sigma_rel2_grid", "--format",
                        "glsl", "--out", str(tmp_path)], capture_output=True, text=True)
    assert r.returncode == 2
    assert "has rank 3; GLSL export covers 1-D and 2-D tables" in r.stderr
