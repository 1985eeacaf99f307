"""brdftab.open_dataset: a table of a table file as an xarray.Dataset.

Table files are HDF5 (netCDF-4 compatible) with a 512-byte digest block in the HDF5 user
block, so the HDF5 signature is at byte 512, not 0: plain xarray cannot guess the engine
and needs it named, e.g.

    xr.open_dataset("tables/hfunc.h5", engine="h5netcdf", group="hfunc_iso")

(engine="netcdf4" works too). open_dataset checks the digest first, then does exactly that.
"""
from __future__ import annotations

import os

from . import _conventions as conv
from . import _core

ENGINE = "h5netcdf"


def list_tables(path: str | os.PathLike) -> list[str]:
    """The table names in a table file (each a group holding the values and their axes)."""
    return list(_core.list_tables(conv.path_arg(path, "path")))


def open_dataset(path: str | os.PathLike, name: str | None = None):
    """open_dataset(path, name=None) -> xarray.Dataset

    The table `name` of the table file `path` (its values as the data variable `name`, its
    axes as coordinates, each with CF `units` and `long_name`; the file's global attributes,
    `Conventions` among them, in `Dataset.attrs`). name may be left out when the file holds one
    table. The file's digest is checked first: a damaged or edited file raises
    brdftab.TableFileError (OSError), as everywhere else in brdftab.
    """
    import xarray as xr

    path = conv.path_arg(path, "path")
    names = list_tables(path)  # checks the digest
    if name is None:
        if len(names) != 1:
            raise ValueError(f"{path} holds {len(names)} tables; pass name= one of: {', '.join(names)}")
        name = names[0]
    elif name not in names:
        raise ValueError(f"{path} has no table {name!r} (tables: {', '.join(names)})")
    with xr.open_dataset(path, engine=ENGINE) as root:
        global_attrs = dict(root.attrs)
    with xr.open_dataset(path, engine=ENGINE, group=name) as ds:
        out = ds.load()
    out.attrs = {**global_attrs, **out.attrs}
    return out
