"""brdftab.Table: any table of a table file, read by the runtime library and interpolated
at broadcast coordinates."""
from __future__ import annotations

import os

from . import _conventions as conv
from . import _core


class Table:
    """Table(path, dataset): one table of a brdftab table file (the digest is checked).

    t(x0, x1, ...) interpolates at broadcast coordinates, one per axis in axis order (physical
    values, before the axis transforms), with the file's interpolation scheme. Out of the
    table's range: errors="nan" (default) gives NaN, "raise" raises ValueError naming the axis,
    value and range, "clamp" reads the nearest edge. float32 in gives float32 out; NaN gives NaN.
    """

    def __init__(self, path: str | os.PathLike, dataset: str):
        self.path = conv.path_arg(path, "path")
        self._t = _core.LoadedTable(self.path, dataset)

    def __call__(self, *coords, errors: str = "nan"):
        errors = conv.check_errors(errors)
        names = [a["name"] for a in self.axes]
        if len(coords) != len(names):
            raise TypeError(f"table '{self.name}' has axes ({', '.join(names)}): {len(coords)} coordinates given")
        shape, cols, dtype = conv.prepare(list(coords), names)
        return conv.finish(self._t(cols, errors), shape, dtype, shape == ())

    @property
    def name(self) -> str:
        return self._t.name

    @property
    def rank(self) -> int:
        return self._t.rank

    @property
    def axes(self) -> list[dict]:
        """Per axis: name, transform, n, lo, hi, units."""
        return self._t.axes

    @property
    def max_abs_error(self) -> float:
        """The table's stated maximum absolute interpolation error (measured off-grid)."""
        return self._t.attribute_number("max_abs_error")

    @property
    def max_rel_error(self) -> float:
        return self._t.attribute_number("max_rel_error")

    def attribute(self, key: str) -> str:
        """A dataset attribute as text ("" when absent)."""
        return self._t.attribute_string(key)

    def __repr__(self) -> str:
        axes = ", ".join(f"{a['name']}[{a['n']}]" for a in self.axes)
        return f"<brdftab.Table {self.name}({axes}) from {self.path}>"
