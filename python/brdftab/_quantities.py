"""Every `brdftab eval` quantity as a SciPy-style function (built from the compiled
registry, so that the CLI and Python never disagree about a quantity's parameters, domains
or methods).

    brdftab.h_iso(c, mu, *, method="exact", tables=None, dataset=None, errors="nan")

Positional arguments in the documented order, or keywords; NumPy broadcasting; one output
gives an ndarray (a NumPy scalar for scalar input), several a named tuple; float32 in gives
float32 out (computed in float64); NaN in gives NaN out; outside the domain per `errors`.
"""
from __future__ import annotations

import collections
import inspect
import keyword

from . import _conventions as conv
from . import _core

# Glossary renames done in Python: the old names stay as deprecated aliases.
QUANTITY_RENAMES = {"smith_gb": "smith_gbeckmann"}
PARAMETER_RENAMES = {"kd": "k_d"}
OUTPUT_RENAMES = {"kd": "k_d"}

# Where each family's formulas come from (papers in the project's reference list).
FAMILY_REFERENCES = {
    "demo": "closed form exp(-x) cos(y) (a demonstration table)",
    "smith_gbeckmann": "Holzschuch & Pacanowski 2017, Sec. 4.2, Eq. 38-42 (Smith masking of the generalized Beckmann NDF)",
    "hfunc": "Chandrasekhar, Radiative Transfer (1960), Ch. V; d'Eon, Sec. 3.1, Eq. 19-26 (Lambertian-sphere pseudo-problems)",
    "ghs_sigma_rel": "Holzschuch & Pacanowski 2017, Eq. 22-26 and Sec. 5.2.3 (GHS renormalization)",
    "ls": "d'Eon, A Hitchhiker's guide to the Lambertian-sphere BRDF, Sec. 2-3",
    "fresnel": "the Fresnel equations; F_dr = 2 Integral_0^1 F(mu) mu dmu",
    "microfacet_albedo": "directional albedo E(mu) = Integral f cos (F = 1); Kulla & Conty 2017 energy compensation",
    "htsg": "He, Torrance, Sillion & Greenberg 1991; Li & Torrance, Eq. 4",
    "hazy_gloss": "Barla, Pacanowski & Vangorp 2018, Eq. 1, Eq. 7 and Algorithm 1",
    "hp": "Holzschuch & Pacanowski 2017, Sec. 4, Eq. 34-49 (corrected form)",
    "filip": "Filip et al., highlight-stencil BRDF",
}


def py_name(name: str) -> str:
    """A parameter's Python name: the glossary's (k_d for kd), and a trailing underscore for
    a Python keyword (lambda_ for the wavelength lambda)."""
    name = PARAMETER_RENAMES.get(name, name)
    return name + "_" if keyword.iskeyword(name) else name


def _parameter_units(name: str) -> str:
    """UDUNITS units of a parameter, from its name: angles in radians, lengths in
    micrometres (suffix _um), everything else a dimensionless number."""
    if name.startswith(("theta", "phi")):
        return "rad"
    if name.endswith("_um"):
        return "um"
    if name in ("sigma", "tau", "lambda"):
        return "a length, in one unit for sigma, tau and lambda"
    return "1"


# Outputs that are densities per steradian besides the BRDF values f, f_*.
PER_STERADIAN = {("ls_phase", "p")}
# Outputs that are lengths (in the unit of the lengths given).
LENGTHS = {("htsg_sigma0", "sigma0")}


def _output_units(quantity: str, name: str) -> str:
    """BRDF values (f, f_*) and phase functions in sr-1; lengths in the input's length unit;
    the other outputs are dimensionless."""
    if (quantity, name) in LENGTHS:
        return "a length, in the unit of sigma and tau"
    return "sr-1" if name == "f" or name.startswith("f_") or (quantity, name) in PER_STERADIAN else "1"


def _result_type(pyname: str, outputs):
    fields = [OUTPUT_RENAMES.get(o, o) for o in outputs]
    camel = "".join(w[:1].upper() + w[1:] for w in pyname.split("_"))
    return collections.namedtuple(camel + "Result", fields)


def _doc(pyname, info, names, result):
    methods = info["methods"]
    lines = [f"{pyname}({', '.join(names)}, *, method='exact', tables=None, dataset=None, errors='nan')", "",
             info["description"] + ".", "", f"Reference: {FAMILY_REFERENCES.get(info['family'], info['family'])}.",
             "", "Parameters", "----------"]
    for p, n in zip(info["parameters"], names):
        opt = "" if p["fallback"] is None else f", optional (default {p['fallback']:g})"
        lines += [f"{n} : array_like{opt}", f"    domain {p['domain']}, units {_parameter_units(p['name'])}"]
    lines += ["method : {" + ", ".join(repr(m) for m in methods) + "}",
              "    'exact' computes from the numerics; 'table' interpolates the table files (stated error in",
              "    their max_abs_error attribute); 'fit' a published fit where there is one.",
              "tables : str, optional", "    table folder for method='table' (default: the installed tables)",
              "dataset : str, optional", "    a compact variant or per-material table (as `brdftab eval --dataset`)",
              "errors : {'nan', 'raise', 'clamp'}",
              "    an element outside the domain (or, for tables, the table's range) gives NaN, raises",
              "    ValueError naming it, or is clamped to the nearest edge. NaN in gives NaN out.",
              "", "Returns", "-------"]
    outs = result._fields
    if len(outs) == 1:
        lines += [f"{outs[0]} : ndarray", f"    units {_output_units(info['name'], info['outputs'][0])}"]
    else:
        lines += [f"{result.__name__} : named tuple of ndarrays"]
        lines += [f"    {o}: units {_output_units(info['name'], raw)}" for o, raw in zip(outs, info["outputs"])]
    lines += ["", "float32 input gives float32 output (computed in float64); broadcasting as NumPy."]
    return "\n".join(lines)


def make_function(info, pyname):
    raw = [p["name"] for p in info["parameters"]]
    names = [py_name(n) for n in raw]
    optional = [p["fallback"] is not None for p in info["parameters"]]
    result = _result_type(pyname, info["outputs"])
    single = len(info["outputs"]) == 1
    qname = info["name"]
    P = inspect.Parameter
    sig = inspect.Signature(
        [P(n, P.POSITIONAL_OR_KEYWORD, default=None if opt else P.empty) for n, opt in zip(names, optional)]
        + [P("method", P.KEYWORD_ONLY, default="exact"), P("tables", P.KEYWORD_ONLY, default=None),
           P("dataset", P.KEYWORD_ONLY, default=None), P("errors", P.KEYWORD_ONLY, default="nan")])
    old = {o: n for o, n in PARAMETER_RENAMES.items() if n in names}

    def f(*args, **kwargs):
        for o, n in old.items():
            if o in kwargs:
                conv.deprecated(f"{pyname}({o}=...)", f"{pyname}({n}=...)")
                if n in kwargs:
                    raise TypeError(f"{pyname}: both {o} and {n} given")
                kwargs[n] = kwargs.pop(o)
        try:
            # With a per-material dataset the material's fixed parameters may be left out.
            bound = sig.bind_partial(*args, **kwargs) if kwargs.get("dataset") is not None else sig.bind(*args, **kwargs)
        except TypeError as e:
            raise TypeError(f"{pyname}: {e}") from None
        bound.apply_defaults()
        a = bound.arguments
        errors = conv.check_errors(a["errors"])
        values = [a.get(n) for n in names]
        shape, cols, dtype = conv.prepare(values, names)
        n = 1
        for s in shape:
            n *= s
        flat = _core.evaluate(qname, a["method"], conv.tables_folder(a["tables"]), a["dataset"], errors, cols, n)
        outs = [conv.finish(x, shape, dtype, shape == ()) for x in flat]
        return outs[0] if single else result(*outs)

    f.__name__ = f.__qualname__ = pyname
    f.__signature__ = sig
    f.__doc__ = _doc(pyname, info, names, result)
    f.Result = result
    f.family = info["family"]
    f.methods = tuple(info["methods"])
    return f


def build(namespace: dict) -> list[str]:
    """Adds every quantity's function (and the deprecated aliases) to `namespace`; returns
    the public names, in the registry's order."""
    infos = _core.quantity_info()
    registry = {i["name"] for i in infos}
    public = []
    for info in infos:
        pyname = QUANTITY_RENAMES.get(info["name"], info["name"])
        if info["name"] in QUANTITY_RENAMES and pyname in registry:
            continue  # the compiled registry already has the new name; the old one is an alias below
        namespace[pyname] = make_function(info, pyname)
        public.append(pyname)
    for old, new in QUANTITY_RENAMES.items():
        if new in namespace:
            namespace[old] = _alias(old, namespace[new])
    return public


def _alias(old, new_fn):
    def f(*args, **kwargs):
        conv.deprecated(old, new_fn.__name__)
        return new_fn(*args, **kwargs)

    f.__name__ = f.__qualname__ = old
    f.__signature__ = new_fn.__signature__
    f.__doc__ = f"Deprecated alias of {new_fn.__name__} (one DeprecationWarning per call).\n\n" + new_fn.__doc__
    f.Result = new_fn.Result
    return f
