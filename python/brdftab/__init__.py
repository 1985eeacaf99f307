"""brdftab: exact numerics and interpolated tables behind published BRDF models.

    import brdftab
    brdftab.h_iso(0.9, [0.1, 0.5, 1.0])                  # exact H-function, positional
    brdftab.microfacet_albedo_ggx(mu, alpha, method="table")
    brdftab.lookup.kulla_conty_lobe(mu_o, mu_i, alpha)    # renderer-facing lookups
    brdftab.open_dataset("tables/hfunc.h5", "hfunc_iso")  # xarray.Dataset with CF units

Every function follows scipy.special's conventions: positional arguments in the documented
order (or keywords), NumPy broadcasting, an ndarray for one output and a named tuple for
several, float32 in -> float32 out (computed in float64), NaN in -> NaN out, and
errors="nan" (default) | "raise" | "clamp" for elements outside the domain. Long calls
release the GIL and stop on Ctrl-C. See docs/python.md.
"""
from . import _core
from ._core import TableFileError, __version__
from . import _quantities
from ._data import list_tables, open_dataset
from ._table import Table
from . import lookup

_public = _quantities.build(globals())


def quantities() -> list[str]:
    """Names of the quantity functions (those of `brdftab eval`), in the registry's order."""
    return list(_public)


__all__ = ["Table", "TableFileError", "list_tables", "lookup", "open_dataset", "quantities", "__version__", *_public]
