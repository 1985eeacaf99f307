"""brdftab.lookup (the renderer-facing table reads) against references that share no code
with them: the exact numerics (quadrature), closed forms and identities written here in
NumPy, and published values; each within the stated error of the tables read."""
import math
import os

import numpy as np
import pytest

import brdftab
from brdftab import lookup
from conftest import TABLES

RNG = np.random.default_rng(30)


def stated(file, name):
    return brdftab.Table(os.path.join(TABLES, file), name).max_abs_error


# A table's stated error is the maximum over the generator's off-grid sample; a fresh sample
# may exceed it. The project's rule (tests/test_family_conformance.cpp): a fresh random point
# set stays within 2x the stated error. Measured here: the precise GGX split_scale 1.11x and
# the GGX E_avg 1.08x their stated errors at this test's points.
SAMPLE_MARGIN = 2.0


def gauss_legendre(n, a, b):
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (b - a) * x + 0.5 * (b + a), 0.5 * (b - a) * w


def test_microfacet_albedo_against_the_exact_quadrature():
    mu = np.concatenate([RNG.uniform(1e-6, 1, 40), [1e-6, 1e-3, 1.0]])
    alpha = np.concatenate([np.exp(RNG.uniform(np.log(0.01), 0, 40)), [0.01, 0.5, 1.0]])
    exact = brdftab.microfacet_albedo_ggx(mu, alpha)
    for q in ("E_corr", "E_sep", "split_scale", "split_bias"):
        got = lookup.microfacet_albedo(mu, alpha, quantity=q, tables=TABLES)
        err = np.max(np.abs(got - getattr(exact, q)))
        assert err <= SAMPLE_MARGIN * stated("microfacet_albedo.h5", f"microfacet_albedo_ggx_{q}_precise"), q
    # The compact tables, their own stated error.
    got = lookup.microfacet_albedo(mu, alpha, ndf="beckmann", precise=False, tables=TABLES)
    err = np.max(np.abs(got - brdftab.microfacet_albedo_beckmann(mu, alpha).E_corr))
    assert err <= SAMPLE_MARGIN * stated("microfacet_albedo.h5", "microfacet_albedo_beckmann_E_corr_compact")


def test_generalized_beckmann_needs_p_and_agrees_with_the_exact_values():
    mu, beta, p = np.array([0.05, 0.4, 0.9]), np.array([0.1, 0.3, 0.8]), np.array([0.7, 1.0, 1.8])
    got = lookup.microfacet_albedo(mu, beta, p, ndf="gbeckmann", tables=TABLES)
    err = np.max(np.abs(got - brdftab.microfacet_albedo_gbeckmann(mu, beta, p).E_corr))
    assert err <= SAMPLE_MARGIN * stated("microfacet_albedo.h5", "microfacet_albedo_gbeckmann_E_corr_compact")
    with pytest.raises(ValueError, match="ndf='gbeckmann'"):
        lookup.microfacet_albedo(mu, beta, ndf="gbeckmann", tables=TABLES)
    with pytest.raises(ValueError, match="ndf='gbeckmann'"):
        lookup.microfacet_albedo(mu, beta, p, tables=TABLES)


def test_microfacet_albedo_avg_against_the_exact_quadrature():
    alpha = np.exp(RNG.uniform(np.log(0.01), 0, 30))
    got = lookup.microfacet_albedo_avg(alpha, tables=TABLES)
    err = np.max(np.abs(got - brdftab.microfacet_albedo_avg_ggx(alpha).Eavg_corr))
    assert err <= SAMPLE_MARGIN * stated("microfacet_albedo.h5", "microfacet_albedo_avg_ggx_Eavg_corr")


def test_kulla_conty_lobe_is_the_formula_and_restores_the_lost_energy():
    alpha = np.array([0.05, 0.3, 0.8])[:, None]
    mu_o = np.array([0.1, 0.5, 0.95])[None, :]
    # The formula (Kulla & Conty 2017) from the table's own E and E_avg reads.
    e_o = lookup.microfacet_albedo(mu_o, alpha, tables=TABLES)
    e_avg = lookup.microfacet_albedo_avg(alpha, tables=TABLES)
    mu_i = 0.37
    e_i = lookup.microfacet_albedo(mu_i, alpha, tables=TABLES)
    np.testing.assert_allclose(lookup.kulla_conty_lobe(mu_o, mu_i, alpha, tables=TABLES),
                               (1 - e_o) * (1 - e_i) / (np.pi * (1 - e_avg)), rtol=1e-14)
    # Energy: the lobe's albedo 2 pi Integral f_ms mu_i dmu_i is the energy the single-scattering
    # BRDF loses, 1 - E(mu_o) (mu_i = t^4 takes E's mu log mu end).
    t, w = gauss_legendre(200, (1e-6) ** 0.25, 1.0)
    mu_n = t ** 4
    f = lookup.kulla_conty_lobe(mu_o[..., None], mu_n, alpha[..., None], tables=TABLES)
    albedo = 2 * np.pi * np.sum(f * mu_n * 4 * t ** 3 * w, axis=-1)
    # Tolerance: E_avg and the integral of E come from different tables (each within its
    # stated error) and the quadrature misses mu < 1e-6 (E_avg weight < 1e-12).
    tol = 4 * (stated("microfacet_albedo.h5", "microfacet_albedo_ggx_E_corr_precise")
               + stated("microfacet_albedo.h5", "microfacet_albedo_avg_ggx_Eavg_corr")) / (1 - e_avg.max())
    assert np.max(np.abs(albedo - (1 - e_o))) <= tol


def test_kulla_conty_fresnel_factor_is_the_formula():
    alpha, f_avg = np.array([0.1, 0.6]), np.array([0.9, 0.4])
    e_avg = lookup.microfacet_albedo_avg(alpha, tables=TABLES)
    np.testing.assert_allclose(lookup.kulla_conty_fresnel_factor(f_avg, alpha, tables=TABLES),
                               f_avg ** 2 * e_avg / (1 - f_avg * (1 - e_avg)), rtol=1e-14)
    # F = 1: the factor is 1 (nothing is absorbed).
    np.testing.assert_allclose(lookup.kulla_conty_fresnel_factor(1.0, alpha, tables=TABLES), 1.0, rtol=1e-15)


def test_smith_gbeckmann_g1_at_p1_is_the_beckmann_closed_form():
    mu = np.array([0.05, 0.3, 0.7, 0.99])
    alpha = 0.4
    nu = mu / (alpha * np.sqrt(1 - mu ** 2))  # 1 / (alpha tan theta)
    lam = np.array([(math.exp(-v * v) / (v * math.sqrt(math.pi)) - math.erfc(v)) / 2 for v in nu])
    got = lookup.smith_gbeckmann_g1(mu, alpha, 1.0, tables=TABLES)
    assert np.max(np.abs(got - 1 / (1 + lam))) <= stated("smith_gbeckmann.h5", "smith_gbeckmann_g1_precise")
    assert lookup.smith_gbeckmann_g1(0.0, alpha, 1.0, tables=TABLES) == 0.0  # grazing: fully masked


def fresnel_dielectric(eta, mu):
    """Unpolarized Fresnel reflectance from outside (index 1) into index eta."""
    s2 = (1 - mu ** 2) / eta ** 2
    ct = np.sqrt(np.maximum(0.0, 1 - s2))
    rs = (mu - eta * ct) / (mu + eta * ct)
    rp = (eta * mu - ct) / (eta * mu + ct)
    return np.where(s2 >= 1, 1.0, 0.5 * (rs ** 2 + rp ** 2))


def test_fresnel_dr_against_quadrature_of_the_fresnel_equations():
    eta = np.array([1.05, 1.33, 1.5, 2.4, 4.0])
    mu, w = gauss_legendre(400, 0.0, 1.0)
    ref = np.array([2 * np.sum(fresnel_dielectric(e, mu) * mu * w) for e in eta])
    assert np.max(np.abs(lookup.fresnel_dr(eta, tables=TABLES) - ref)) <= stated("fresnel.h5", "fresnel_dr") + 1e-10
    # F_avg of a conductor at k = 0 is the dielectric's F_dr (two tables, one identity).
    tol = stated("fresnel.h5", "fresnel_avg_conductor_n_above_1") + stated("fresnel.h5", "fresnel_dr")
    assert np.max(np.abs(lookup.fresnel_avg_conductor(eta, 0.0, tables=TABLES) - ref)) <= tol + 1e-10


def test_h_function_published_value_and_exact():
    # Chandrasekhar (1960), Table XI: H(1) = 2.90781 for c = 1.
    assert abs(lookup.h_function(1.0, 1.0, tables=TABLES) - 2.90781) < 1e-5
    c, mu = RNG.uniform(0, 1, 30), RNG.uniform(0, 1, 30)
    err = np.max(np.abs(lookup.h_function(c, mu, tables=TABLES) - brdftab.h_iso(c, mu)))
    assert err <= stated("hfunc.h5", "hfunc_iso")


def test_ls_spherical_albedo_is_the_cosine_weighted_plane_albedo():
    # k_d(c) = 2 Integral_0^1 A(c, mu) mu dmu: the ls_kd table against the ls_albedo table.
    c = np.array([0.2, 0.6, 0.95])[:, None]
    t, w = gauss_legendre(120, 0.0, 1.0)
    mu = t ** 4
    a = lookup.ls_plane_albedo(c, mu, tables=TABLES)
    kd = 2 * np.sum(a * mu * 4 * t ** 3 * w, axis=-1)
    tol = stated("ls.h5", "ls_kd") + stated("ls.h5", "ls_albedo")
    assert np.max(np.abs(lookup.ls_kd(c[:, 0], tables=TABLES) - kd)) <= tol


def test_table_errors_name_the_parameter():
    with pytest.raises(ValueError, match="quantity = 'E' is not one of"):
        lookup.microfacet_albedo(0.5, 0.5, quantity="E", tables=TABLES)
    with pytest.raises(ValueError, match="kind = 'x'"):
        lookup.h_function(0.5, 0.5, kind="x", tables=TABLES)
    with pytest.raises(brdftab.TableFileError):
        lookup.ls_kd(0.5, tables="/nonexistent")


def test_render_profile_against_the_exact_quadrature_and_the_precise_tables():
    # The render profile (float evaluation of 80 x 128 float32 tables) against the exact
    # numerics, within its stated error (table + float evaluation, render_errors), and against
    # the precise tables, which share no code or values with it beyond the numerics they are
    # filled from.
    mu = np.concatenate([RNG.uniform(1e-6, 1, 30), [1e-6, 1e-3, 1.0]])
    alpha = np.concatenate([np.exp(RNG.uniform(np.log(0.01), 0, 30)), [0.01, 0.5, 1.0]])
    for ndf, exact_fn in (("ggx", brdftab.microfacet_albedo_ggx), ("beckmann", brdftab.microfacet_albedo_beckmann)):
        errs = lookup.render_errors(ndf=ndf, tables=TABLES)
        exact = exact_fn(mu, alpha)
        for q in ("E_corr", "E_sep"):
            table_err, float_err, total = errs[q]
            assert total == pytest.approx(table_err + float_err)
            assert 0 < float_err <= 2e-6 and total <= 1e-5
            got = lookup.microfacet_albedo_render(mu, alpha, ndf=ndf, quantity=q, tables=TABLES)
            assert np.max(np.abs(got - getattr(exact, q))) <= SAMPLE_MARGIN * total, (ndf, q)
        grid = RNG.uniform(0, 1, 2000), np.exp(RNG.uniform(np.log(0.01), 0, 2000))
        precise = lookup.microfacet_albedo(np.maximum(grid[0], 1e-6), grid[1], ndf=ndf, tables=TABLES)
        got = lookup.microfacet_albedo_render(np.maximum(grid[0], 1e-6), grid[1], ndf=ndf, tables=TABLES)
        bound = errs["E_corr"][2] + stated("microfacet_albedo.h5", f"microfacet_albedo_{ndf}_E_corr_precise")
        assert np.max(np.abs(got - precise)) <= SAMPLE_MARGIN * bound, ndf
        a = np.exp(RNG.uniform(np.log(0.01), 0, 200))
        avg = lookup.microfacet_albedo_avg_render(a, ndf=ndf, tables=TABLES)
        ref = lookup.microfacet_albedo_avg(a, ndf=ndf, tables=TABLES)
        bound = errs["Eavg_corr"][2] + stated("microfacet_albedo.h5", f"microfacet_albedo_avg_{ndf}_Eavg_corr")
        assert np.max(np.abs(avg - ref)) <= SAMPLE_MARGIN * bound, ndf


def test_render_profile_conventions_and_the_lobe_formula():
    mu_o, mu_i, alpha = RNG.uniform(0, 1, 50), RNG.uniform(0, 1, 50), np.exp(RNG.uniform(np.log(0.01), 0, 50))
    lobe = lookup.kulla_conty_lobe_render(mu_o, mu_i, alpha, tables=TABLES)
    e_o = lookup.microfacet_albedo_render(mu_o, alpha, tables=TABLES)
    e_i = lookup.microfacet_albedo_render(mu_i, alpha, tables=TABLES)
    e_avg = lookup.microfacet_albedo_avg_render(alpha, tables=TABLES)
    np.testing.assert_allclose(lobe, (1 - e_o) * (1 - e_i) / (math.pi * (1 - e_avg)), rtol=1e-14)
    # Positional and keyword, broadcasting, float32 in and out, NaN in NaN out, mu = 0 inside.
    assert lookup.microfacet_albedo_render(0.5, 0.3, tables=TABLES) == lookup.microfacet_albedo_render(
        mu=0.5, alpha=0.3, tables=TABLES)
    assert lookup.microfacet_albedo_render(np.zeros((2, 1)), np.array([0.1, 0.2, 0.3]), tables=TABLES).shape == (2, 3)
    out = lookup.microfacet_albedo_render(np.float32([0.0, 0.5, np.nan]), np.float32(0.3), tables=TABLES)
    assert out.dtype == np.float32 and np.isfinite(out[:2]).all() and np.isnan(out[2])
    # Outside the range: NaN by default, the edge with errors="clamp", a named error with "raise".
    assert np.isnan(lookup.microfacet_albedo_render(1.5, 0.3, tables=TABLES))
    assert lookup.microfacet_albedo_render(1.5, 0.3, errors="clamp", tables=TABLES) == lookup.microfacet_albedo_render(
        1.0, 0.3, tables=TABLES)
    assert lookup.microfacet_albedo_avg_render(5.0, errors="clamp", tables=TABLES) == lookup.microfacet_albedo_avg_render(
        1.0, tables=TABLES)
    with pytest.raises(ValueError, match=r"parameter 'alpha': value 0.001 is outside the table range \[0.01, 1\]"):
        lookup.microfacet_albedo_render(0.5, 1e-3, errors="raise", tables=TABLES)
    with pytest.raises(ValueError, match="'gbeckmann' is not one of 'ggx', 'beckmann'"):
        lookup.microfacet_albedo_render(0.5, 0.3, ndf="gbeckmann", tables=TABLES)
    with pytest.raises(ValueError, match="'split_scale' is not one of 'E_corr', 'E_sep'"):
        lookup.microfacet_albedo_render(0.5, 0.3, quantity="split_scale", tables=TABLES)
