"""`brdftab export` outputs read back by independent readers: NumPy for .npy (values and
axes equal the HDF5 file's, read with h5py), glslangValidator for the GLSL lookup functions (compiled
to SPIR-V in a compute shader for every table of rank 1 to 3)."""
import glob
import os
import re
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


def test_glsl_compiles_for_every_table_of_rank_1_to_3(tmp_path):
    """Every table of rank 1 to 3 exports a GLSL function that compiles to SPIR-V in a compute
    shader (its results are compared with the CPU lookup on lavapipe by glsl_vulkan_lavapipe).
    One shader per file, holding all its tables' functions (each buffer at its own binding)."""
    validator = shutil.which("glslangValidator")
    assert validator, "glslangValidator missing (Debian glslang-tools; scripts/install-deps.sh)"
    count = 0
    by_file = {}
    for path, name in tables(max_rank=3):
        by_file.setdefault(path, []).append(name)
    for path, names in by_file.items():
        source = "#version 450\nlayout(local_size_x = 1) in;\n"
        calls = []
        for k, name in enumerate(names):
            files = export(path, name, "glsl", tmp_path)
            assert [os.path.basename(f) for f in files] == [f"{ident(name)}.glsl", f"{ident(name)}.f32"]
            snippet = (tmp_path / f"{ident(name)}.glsl").read_text()
            with h5py.File(path, "r") as f:
                v = f[name][name]
                # The .f32 file: the values as float32, row-major.
                np.testing.assert_array_equal(
                    np.fromfile(tmp_path / f"{ident(name)}.f32", dtype="<f4").reshape(v.shape), v[()].astype(np.float32))
            m = re.search(r"^float " + ident(name) + r"\(([^)]*)\) \{$", snippet, re.M)
            assert m, f"{name}: no function {ident(name)}(...)"
            nargs = len(m.group(1).split(","))
            source += f"#define {ident(name)}_BINDING {k + 2}\n" + snippet
            calls.append(f"{ident(name)}(" + ", ".join(f"x[{i}]" for i in range(nargs)) + ")")
            count += 1
        shader = tmp_path / "all.comp"
        shader.write_text(source + "layout(std430, binding = 1) buffer IO { float x[4]; float y; };\n"
                          "void main() {\n  y = 0.0;\n" + "".join(f"  y += {c};\n" for c in calls) + "}\n")
        r = subprocess.run([validator, "-V", str(shader), "-o", str(tmp_path / "out.spv")], capture_output=True, text=True)
        assert r.returncode == 0, path + ":\n" + r.stdout + r.stderr
    assert count >= 10


def test_glsl_refuses_a_4d_table(tmp_path):
    r = subprocess.run([EXE, "export", os.path.join(TABLE_DIR, "ls.h5"), "ls_brdf_modes", "--format",
                        "glsl", "--out", str(tmp_path)], capture_output=True, text=True)
    assert r.returncode == 2
    assert "table 'ls_brdf_modes' has rank 4; the GLSL export covers tables of rank 1 to 3" in r.stderr
    assert [p.name for p in tmp_path.iterdir()] in ([], [".brdftab.lock"])  # no export, at most the writer lock
