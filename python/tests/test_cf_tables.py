"""CF-style table files (CF-1.8), generated here from a small manifest (cf_manifest.json:
every family at test size) rather than read from the committed tables, and opened
  - with brdftab.open_dataset (digest checked, engine chosen), and
  - with plain xarray, naming the engine (the 512-byte digest block hides the HDF5
    signature from xarray's guess), both engines:
every data variable and every axis has UDUNITS `units` and a `long_name`, derived axes state
their map in `formula`, and the file says `Conventions = "CF-1.8"`. An edited file is
refused with a message naming `brdftab seal FILE`."""
import json
import os
import shutil
import subprocess

import h5py
import numpy as np
import pytest
import xarray as xr

import brdftab
from brdftab import _core

HERE = os.path.dirname(os.path.abspath(__file__))
MANIFEST = os.path.join(HERE, "cf_manifest.json")
UDUNITS = {"1", "rad", "sr-1"}


@pytest.fixture(scope="module")
def generated(tmp_path_factory):
    out = tmp_path_factory.mktemp("cf")
    subprocess.run([os.environ["BRDFTAB_EXE"], "generate", "-q", "--manifest", MANIFEST, "--out", str(out)],
                   check=True)
    return out


def test_the_manifest_covers_every_family():
    with open(MANIFEST) as f:
        families = set(json.load(f)["tables"])
    assert families == set(_core.family_names())


def files(directory):
    return sorted(os.path.join(directory, f) for f in os.listdir(directory) if f.endswith(".h5"))


def test_open_dataset_gives_units_and_long_names_everywhere(generated):
    seen = 0
    for path in files(generated):
        for name in brdftab.list_tables(path):
            ds = brdftab.open_dataset(path, name)
            assert ds.attrs["Conventions"] == "CF-1.8"
            var = ds[name]
            assert var.attrs["units"] in UDUNITS, (path, name)
            assert var.attrs["long_name"], (path, name)
            for dim in var.dims:
                axis = ds[dim]
                assert axis.attrs["units"] in UDUNITS, (path, name, dim)
                assert axis.attrs["long_name"], (path, name, dim)
                # a derived coordinate's map is a formula, never a unit
                if dim in ("s", "v", "w", "B", "b"):
                    assert axis.attrs.get("formula"), (path, name, dim)
            # the values are the table's: brdftab.Table at the nodes
            t = brdftab.Table(path, name)
            grids = np.meshgrid(*[ds[d].values for d in var.dims], indexing="ij")
            np.testing.assert_allclose(t(*[g.ravel()[:50] for g in grids]), var.values.ravel()[:50], rtol=1e-12, atol=1e-15)
            seen += 1
    assert seen >= len(_core.family_names())


@pytest.mark.parametrize("engine", ["h5netcdf", "netcdf4"])
def test_plain_xarray_needs_only_the_engine(generated, engine):
    for path in files(generated):
        name = brdftab.list_tables(path)[0]
        with xr.open_dataset(path, engine=engine, group=name) as ds:
            assert ds[name].attrs["units"] in UDUNITS
        with xr.open_dataset(path, engine=engine) as root:
            assert root.attrs["Conventions"] == "CF-1.8"
    with pytest.raises(ValueError):  # without engine=, xarray cannot tell what the file is
        xr.open_dataset(files(generated)[0])


def test_open_dataset_names_the_tables_when_asked_for_none(generated):
    path = os.path.join(generated, "hfunc.h5")
    with pytest.raises(ValueError, match="pass name= one of: .*hfunc_iso"):
        brdftab.open_dataset(path)
    demo = brdftab.open_dataset(os.path.join(generated, "demo.h5"))  # one table: no name needed
    assert "demo_exp_cos" in demo


def test_an_edited_file_is_refused_naming_brdftab_seal(generated, tmp_path):
    path = tmp_path / "demo.h5"
    shutil.copy(os.path.join(generated, "demo.h5"), path)
    with h5py.File(path, "r+") as f:  # a user adds an attribute on purpose
        f.attrs["comment"] = "edited"
    with pytest.raises(brdftab.TableFileError, match=f"brdftab seal {path}"):
        brdftab.open_dataset(path)
