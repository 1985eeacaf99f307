"""Renderer-facing table lookups: what a renderer reads per shading point, batched over
NumPy arrays (the runtime library's lookup::* functions, lookup/*.hpp).

Every function takes its coordinates positionally or by keyword, broadcasts them, returns
an ndarray (a NumPy scalar for scalar input), float32 for float32 input (computed in
float64), NaN for NaN input, and applies `errors` to coordinates outside the table's range:
"nan" (default) gives NaN there, "raise" raises ValueError naming the parameter, its value
and the range, "clamp" reads the nearest edge (the C++ library's default). Renderer-facing
functions take (mu, alpha) in that order: mu = cos(theta) of the direction, alpha the
roughness. `tables` is a table folder (default: the installed tables, or $BRDFTAB_TABLES).
"""
from __future__ import annotations

from . import _conventions as conv
from . import _core

__all__ = ["microfacet_albedo", "microfacet_albedo_avg", "kulla_conty_lobe", "kulla_conty_fresnel_factor",
           "microfacet_albedo_render", "microfacet_albedo_avg_render", "kulla_conty_lobe_render", "render_errors",
           "smith_gbeckmann_g1", "fresnel_dr", "fresnel_avg_conductor", "h_function", "ls_kd", "ls_plane_albedo"]


def _run(core_fn, args, names, errors, **kw):
    errors = conv.check_errors(errors)
    shape, cols, dtype = conv.prepare(list(args), list(names))
    kw["tables"] = conv.tables_folder(kw.get("tables"))
    flat = core_fn([c for c in cols if c is not None], errors=errors, **kw)
    return conv.finish(flat, shape, dtype, shape == ())


def _ndf_p(ndf, p, who):
    if ndf not in ("ggx", "beckmann", "gbeckmann"):
        raise ValueError(f"{who}: ndf = {ndf!r} is not one of 'ggx', 'beckmann', 'gbeckmann'")
    if (ndf == "gbeckmann") != (p is not None):
        raise ValueError(f"{who}: p (the kurtosis) is given exactly for ndf='gbeckmann'")


def microfacet_albedo(mu, alpha, p=None, *, ndf="ggx", quantity="E_corr", precise=True, tables=None, errors="nan"):
    """microfacet_albedo(mu, alpha, p=None, *, ndf='ggx', quantity='E_corr', precise=True, tables=None, errors='nan')

    Directional albedo E(mu) = Integral f(omega_i, omega_o) cos(theta_o) d omega_o of a
    microfacet BRDF with F = 1 (and its split-sum pair), read from the microfacet_albedo
    tables (lookup::microfacet_albedo_batch).

    Parameters
    ----------
    mu : array_like
        cos(theta) of the viewing direction, units 1; table range [1e-6, 1] (mu_lo, mu_hi).
    alpha : array_like
        roughness alpha (GGX, Beckmann) or beta (generalized Beckmann), units 1; table range
        [1e-3, 10] by default.
    p : array_like, optional
        kurtosis of the generalized Beckmann NDF (ndf='gbeckmann' only), units 1.
    ndf : {'ggx', 'beckmann', 'gbeckmann'}
    quantity : {'E_corr', 'E_sep', 'split_scale', 'split_bias'}
        E_corr: height-correlated Smith G2; E_sep: separable G1 G1; split_scale and
        split_bias: Integral f (1 - (1 - cos theta_d)^5) cos and Integral f (1 - cos theta_d)^5 cos
        (the split-sum pair: E with Schlick's F = F0 scale + bias).
    precise : bool
        the float64 'precise' tables (GGX, Beckmann) rather than the float32 'compact' ones.

    Returns
    -------
    E : ndarray, units 1 (an albedo in [0, 1]).
    """
    _ndf_p(ndf, p, "microfacet_albedo")
    args, names = ([mu, alpha, p], ["mu", "alpha", "p"]) if p is not None else ([mu, alpha], ["mu", "alpha"])
    return _run(_core.microfacet_albedo, args, names, errors, ndf=ndf, quantity=quantity, precise=precise, tables=tables)


def microfacet_albedo_avg(alpha, p=None, *, ndf="ggx", quantity="Eavg_corr", tables=None, errors="nan"):
    """microfacet_albedo_avg(alpha, p=None, *, ndf='ggx', quantity='Eavg_corr', tables=None, errors='nan')

    Hemispherical average E_avg = 2 Integral_0^1 E(mu) mu dmu of the directional albedo
    (Kulla & Conty 2017, the E_avg of their energy-compensation lobe), from the E_avg tables.

    Parameters
    ----------
    alpha : array_like
        roughness (beta for ndf='gbeckmann'), units 1.
    p : array_like, optional
        kurtosis (ndf='gbeckmann' only), units 1.
    quantity : {'Eavg_corr', 'Eavg_sep'}
        height-correlated or separable G2.

    Returns
    -------
    E_avg : ndarray, units 1.
    """
    _ndf_p(ndf, p, "microfacet_albedo_avg")
    args, names = ([alpha, p], ["alpha", "p"]) if p is not None else ([alpha], ["alpha"])
    return _run(_core.microfacet_albedo_avg, args, names, errors, ndf=ndf, quantity=quantity, tables=tables)


def kulla_conty_lobe(mu_o, mu_i, alpha, p=None, *, ndf="ggx", precise=True, tables=None, errors="nan"):
    """kulla_conty_lobe(mu_o, mu_i, alpha, p=None, *, ndf='ggx', precise=True, tables=None, errors='nan')

    The Kulla-Conty multiple-scattering lobe (Kulla & Conty 2017, "Revisiting Physically
    Based Shading at Imageworks"):

        f_ms(mu_o, mu_i) = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)),

    with E the height-correlated directional albedo (F = 1) and E_avg its hemispherical
    average, both read from the tables (lookup::kulla_conty_lobe_batch). Adding f_ms to the
    single-scattering BRDF makes its albedo 1 at F = 1; multiply by
    kulla_conty_fresnel_factor for a coloured conductor.

    Parameters
    ----------
    mu_o, mu_i : array_like
        cos(theta) of the outgoing and incident directions, units 1.
    alpha : array_like
        roughness (beta for ndf='gbeckmann'), units 1.
    p : array_like, optional
        kurtosis (ndf='gbeckmann' only), units 1.

    Returns
    -------
    f_ms : ndarray, units sr-1.
    """
    _ndf_p(ndf, p, "kulla_conty_lobe")
    args = [mu_o, mu_i, alpha] + ([p] if p is not None else [])
    names = ["mu_o", "mu_i", "alpha"] + (["p"] if p is not None else [])
    return _run(_core.kulla_conty_lobe, args, names, errors, ndf=ndf, precise=precise, tables=tables)


_RENDER_NOTE = """The render profile (lookup/render.hpp, docs/renderer-integration.md): 80 x 128 float32
    tables on (alpha^(1/4), t(mu; alpha)), evaluated in float like a shader, for GGX and
    Beckmann; range mu in [0, 1] (mu = 0 included), alpha in the tables' range ([0.01, 1] by
    default). Its error (render_errors) is the table's stated error plus the float
    evaluation's, measured when the tables are loaded: ~8e-7 (GGX E), ~5e-6 (Beckmann E),
    ~2e-7 (E_avg). The precise tables (microfacet_albedo, precise=True) are ~1e-8 and slower."""


def microfacet_albedo_render(mu, alpha, *, ndf="ggx", quantity="E_corr", tables=None, errors="nan"):
    """microfacet_albedo_render(mu, alpha, *, ndf='ggx', quantity='E_corr', tables=None, errors='nan')

    Directional albedo E(mu) with F = 1 from the render profile
    (lookup::render::microfacet_albedo_e_corr_batch / _e_sep_batch).

    {note}

    Parameters
    ----------
    mu : array_like
        cos(theta) of the viewing direction, units 1; range [0, 1].
    alpha : array_like
        roughness, units 1.
    ndf : {{'ggx', 'beckmann'}}
    quantity : {{'E_corr', 'E_sep'}}
        height-correlated Smith G2 or separable G1 G1.

    Returns
    -------
    E : ndarray, units 1.
    """
    return _run(_core.microfacet_albedo_render, [mu, alpha], ["mu", "alpha"], errors, ndf=ndf, quantity=quantity,
                tables=tables)


def microfacet_albedo_avg_render(alpha, *, ndf="ggx", quantity="Eavg_corr", tables=None, errors="nan"):
    """microfacet_albedo_avg_render(alpha, *, ndf='ggx', quantity='Eavg_corr', tables=None, errors='nan')

    E_avg = 2 Integral_0^1 E(mu) mu dmu from the render profile's 256-point float32 tables
    (lookup::render::microfacet_albedo_eavg_corr / _eavg_sep).

    {note}

    Parameters
    ----------
    alpha : array_like
        roughness, units 1.
    ndf : {{'ggx', 'beckmann'}}
    quantity : {{'Eavg_corr', 'Eavg_sep'}}

    Returns
    -------
    E_avg : ndarray, units 1.
    """
    return _run(_core.microfacet_albedo_avg_render, [alpha], ["alpha"], errors, ndf=ndf, quantity=quantity, tables=tables)


def kulla_conty_lobe_render(mu_o, mu_i, alpha, *, ndf="ggx", tables=None, errors="nan"):
    """kulla_conty_lobe_render(mu_o, mu_i, alpha, *, ndf='ggx', tables=None, errors='nan')

    The Kulla-Conty multiple-scattering lobe (F = 1)
    f_ms = (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)) from the render profile
    (lookup::render::microfacet_albedo_kulla_conty_lobe_batch). Its error is E's amplified by
    1 / (1 - E_avg) (docs/speed.md).

    {note}

    Parameters
    ----------
    mu_o, mu_i : array_like
        cos(theta) of the outgoing and incident directions, units 1; range [0, 1].
    alpha : array_like
        roughness, units 1.

    Returns
    -------
    f_ms : ndarray, units sr-1.
    """
    return _run(_core.kulla_conty_lobe_render, [mu_o, mu_i, alpha], ["mu_o", "mu_i", "alpha"], errors, ndf=ndf,
                tables=tables)


def render_errors(*, ndf="ggx", tables=None):
    """render_errors(*, ndf='ggx', tables=None)

    The render profile's stated errors for one NDF: a dict from quantity ('E_corr', 'E_sep',
    'Eavg_corr', 'Eavg_sep') to (table error, float evaluation error, their sum), max absolute,
    units 1. The table error is the generator's (attribute max_abs_error); the float
    evaluation's is measured when the tables are loaded (lookup::render::MicrofacetAlbedo).
    """
    return _core.render_errors(ndf, conv.tables_folder(tables))


for _f in (microfacet_albedo_render, microfacet_albedo_avg_render, kulla_conty_lobe_render):
    _f.__doc__ = _f.__doc__.format(note=_RENDER_NOTE)
del _f


def kulla_conty_fresnel_factor(f_avg, alpha, p=None, *, ndf="ggx", tables=None, errors="nan"):
    """kulla_conty_fresnel_factor(f_avg, alpha, p=None, *, ndf='ggx', tables=None, errors='nan')

    The Fresnel factor of the Kulla-Conty lobe (Kulla & Conty 2017):

        F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),

    F_avg the cosine-weighted hemispherical average of the Fresnel reflectance
    (brdftab.lookup.fresnel_avg_conductor for a conductor), E_avg from the tables.

    Parameters
    ----------
    f_avg : array_like
        hemispherical Fresnel average, units 1, in [0, 1].
    alpha : array_like
        roughness, units 1.

    Returns
    -------
    F_ms : ndarray, units 1.
    """
    _ndf_p(ndf, p, "kulla_conty_fresnel_factor")
    args = [f_avg, alpha] + ([p] if p is not None else [])
    names = ["f_avg", "alpha"] + (["p"] if p is not None else [])
    return _run(_core.kulla_conty_fresnel_factor, args, names, errors, ndf=ndf, tables=tables)


def smith_gbeckmann_g1(mu, alpha, p, *, tables=None, errors="nan"):
    """smith_gbeckmann_g1(mu, alpha, p, *, tables=None, errors='nan')

    Smith masking G1 = 1 / (1 + Lambda(a, p)) of the generalized Beckmann distribution
    (Holzschuch & Pacanowski 2017, Sec. 4.2, Eq. 38-42) at a = alpha tan(theta),
    tan(theta) = sqrt(1 - mu^2) / mu, read from the precise G1 table on (p, b = a M1(p)).

    Parameters
    ----------
    mu : array_like
        cos(theta), units 1, in [0, 1] (mu = 0 gives G1 = 0).
    alpha : array_like
        roughness beta, units 1, >= 0.
    p : array_like
        kurtosis, units 1, within the table's range.

    Returns
    -------
    G1 : ndarray, units 1.
    """
    return _run(_core.smith_gbeckmann_g1, [mu, alpha, p], ["mu", "alpha", "p"], errors, tables=tables)


def fresnel_dr(eta, *, tables=None, errors="nan"):
    """fresnel_dr(eta, *, tables=None, errors='nan')

    Diffuse Fresnel reflectance F_dr(eta) = 2 Integral_0^1 F(eta, mu) mu dmu of a dielectric
    of relative index eta (the fresnel_dr table; eta < 1 through the reciprocity identity
    1 - F_dr(eta) = eta^2 (1 - F_dr(1/eta))).

    Parameters
    ----------
    eta : array_like
        relative index of refraction, units 1, in [1/eta_hi, eta_hi] of the table.

    Returns
    -------
    F_dr : ndarray, units 1.
    """
    return _run(_core.fresnel_dr, [eta], ["eta"], errors, tables=tables)


def fresnel_avg_conductor(n, k, *, tables=None, errors="nan"):
    """fresnel_avg_conductor(n, k, *, tables=None, errors='nan')

    Cosine-weighted hemispherical average F_avg(n, k) = 2 Integral_0^1 F(n + i k, mu) mu dmu of
    the conductor Fresnel reflectance (the two fresnel_avg_conductor tables, joined at n = 1).

    Parameters
    ----------
    n : array_like
        real part of the relative index, units 1.
    k : array_like
        extinction coefficient, units 1.

    Returns
    -------
    F_avg : ndarray, units 1.
    """
    return _run(_core.fresnel_avg_conductor, [n, k], ["n", "k"], errors, tables=tables)


_KINDS = {"iso": 0, "ls0": 1, "ls1": 2, "ls2": 3}


def h_function(c, mu, *, kind="iso", compact=False, tables=None, errors="nan"):
    """h_function(c, mu, *, kind='iso', compact=False, tables=None, errors='nan')

    Chandrasekhar's H-function H(c, mu) (Radiative Transfer, 1960, Ch. V: H(mu) = 1 + mu H(mu)
    Integral_0^1 Psi(mu') H(mu') / (mu + mu') dmu'), isotropic (Psi = c/2) or of the three
    Lambertian-sphere pseudo-problems (d'Eon, Sec. 3.1, Eq. 19-26), from the hfunc tables.

    Parameters
    ----------
    c : array_like
        single-scattering albedo, units 1, in [0, 1].
    mu : array_like
        cos(theta), units 1, in [0, 1].
    kind : {'iso', 'ls0', 'ls1', 'ls2'}
    compact : bool
        the float32 compact table instead of the precise one.

    Returns
    -------
    H : ndarray, units 1.
    """
    if kind not in _KINDS:
        raise ValueError(f"h_function: kind = {kind!r} is not one of {', '.join(map(repr, _KINDS))}")
    return _run(_core.h_function, [c, mu], ["c", "mu"], errors, kind=_KINDS[kind], compact=compact, tables=tables)


def ls_kd(c, *, tables=None, errors="nan"):
    """ls_kd(c, *, tables=None, errors='nan')

    Spherical (bond) albedo k_d(c) = 2 Integral_0^1 A(c, mu) mu dmu of the Lambertian-sphere
    half space with the true phase function (d'Eon, Sec. 2-3), from the ls_kd table.

    Parameters
    ----------
    c : array_like
        single-scattering albedo of the particles, units 1, in [0, 1].

    Returns
    -------
    k_d : ndarray, units 1.
    """
    return _run(_core.ls_kd, [c], ["c"], errors, tables=tables)


def ls_plane_albedo(c, mu, *, tables=None, errors="nan"):
    """ls_plane_albedo(c, mu, *, tables=None, errors='nan')

    Plane (directional-hemispherical) albedo A(c, mu) of the Lambertian-sphere half space
    (d'Eon, Sec. 2-3), from the ls_albedo table.

    Parameters
    ----------
    c : array_like
        single-scattering albedo, units 1, in [0, 1].
    mu : array_like
        cos(theta) of the incident direction, units 1, in [0, 1].

    Returns
    -------
    A : ndarray, units 1.
    """
    return _run(_core.ls_plane_albedo, [c, mu], ["c", "mu"], errors, tables=tables)
