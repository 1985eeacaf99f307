"""SciPy-style argument handling shared by every brdftab function: broadcasting, the dtype
rule (float32 in, float32 out; computed in float64), flattening for the compiled core and
the deprecated-name warnings."""
from __future__ import annotations

import warnings

import numpy as np

ERRORS = ("raise", "nan", "clamp")


def check_errors(errors: str) -> str:
    if errors not in ERRORS:
        raise ValueError(f"errors = {errors!r} is not one of 'raise', 'nan', 'clamp'")
    return errors


def result_dtype(arrays) -> np.dtype:
    """float32 when the inputs are float32 (or float16), else float64 (NumPy's promotion of
    the inputs, Python scalars taking the arrays' kind). Complex input is refused."""
    if not arrays:
        return np.dtype(np.float64)
    t = np.result_type(*arrays)
    if t.kind == "c":
        raise TypeError("complex input is not supported")
    if t.kind not in "biuf":
        raise TypeError(f"input of dtype {t} is not a number")
    return np.dtype(np.float32) if t in (np.float16, np.float32) else np.dtype(np.float64)


def prepare(args, names):
    """Broadcasts the arrays `args` (None entries stay None) and returns
    (shape, flat float64 columns, result dtype)."""
    given = [np.asarray(a) for a in args if a is not None]
    for name, a in zip([n for n, x in zip(names, args) if x is not None], given):
        if a.dtype.kind not in "biufc":
            raise TypeError(f"{name}: expected numbers, got an array of dtype {a.dtype}")
    dtype = result_dtype(given)
    b = np.broadcast_arrays(*given) if given else []
    shape = b[0].shape if b else ()
    it = iter(b)
    cols = [None if a is None else np.ascontiguousarray(next(it), dtype=np.float64).reshape(-1) for a in args]
    return shape, cols, dtype


def finish(flat, shape, dtype, scalar_like):
    """The flat float64 result as an array of `shape` and `dtype` (a NumPy scalar for 0-d)."""
    out = np.asarray(flat).reshape(shape).astype(dtype, copy=False)
    return out[()] if scalar_like else out


def deprecated(old: str, new: str, stacklevel: int = 3) -> None:
    """One DeprecationWarning per call that uses an old name (Python's filters decide how
    often it is shown)."""
    warnings.warn(f"brdftab: '{old}' is deprecated, use '{new}'", DeprecationWarning, stacklevel=stacklevel)


def path_arg(value, name):
    """os.fspath(value) as str (bytes decoded with the file-system encoding), refusing an
    embedded NUL, which the C++ side would read as the end of the path (another file, silently),
    with ValueError naming the parameter, as open() does."""
    import os

    path = os.fsdecode(os.fspath(value))
    if "\0" in path:
        raise ValueError(f"{name}: embedded null byte in the path {path!r}")
    return path


def tables_folder(tables):
    """The table folder to read: `tables` if given, else $BRDFTAB_TABLES, else the tables
    installed with the package (pip), else None (the library's default: ./tables, then the
    installed share/brdftab/tables)."""
    import os

    if tables is not None:
        return path_arg(tables, "tables")
    env = os.environ.get("BRDFTAB_TABLES")
    if env:
        return env
    bundled = os.path.join(os.path.dirname(os.path.abspath(__file__)), "tables")
    if os.path.isfile(os.path.join(bundled, "default.json")):
        return bundled
    return None
