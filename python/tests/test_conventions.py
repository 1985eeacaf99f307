"""SciPy conventions (scipy.special is the model), checked on every quantity function where
they are generic and on chosen ones where they need values."""
import inspect
import os
import warnings

import numpy as np
import pytest

import brdftab
from conftest import TABLES


def test_positional_and_keyword_calls_agree():
    c, mu = np.array([0.2, 0.9]), np.array([0.1, 0.7])
    a = brdftab.h_iso(c, mu)
    np.testing.assert_array_equal(brdftab.h_iso(c=c, mu=mu), a)
    np.testing.assert_array_equal(brdftab.h_iso(c, mu=mu), a)
    with pytest.raises(TypeError, match="h_iso"):
        brdftab.h_iso(c, mu, 3)
    with pytest.raises(TypeError, match="h_iso"):
        brdftab.h_iso(c)
    with pytest.raises(TypeError, match="h_iso"):
        brdftab.h_iso(c, mu, nu=1)


def test_every_function_documents_its_signature_domain_units_and_reference():
    for name in brdftab.quantities():
        f = getattr(brdftab, name)
        sig = inspect.signature(f)
        params = [p for p in sig.parameters.values() if p.kind == p.POSITIONAL_OR_KEYWORD]
        assert params, name
        assert [p.name for p in sig.parameters.values() if p.kind == p.KEYWORD_ONLY] == [
            "method", "tables", "dataset", "errors"]
        doc = f.__doc__
        assert doc.startswith(f"{name}({', '.join(p.name for p in params)}, *"), name
        assert "Reference: " in doc and "domain " in doc and "units " in doc, name
    for name in brdftab.lookup.__all__:
        doc = getattr(brdftab.lookup, name).__doc__
        assert doc.lstrip().startswith(name + "("), name
        assert "units" in doc, name


def test_renderer_facing_functions_take_mu_then_alpha():
    for name in ("microfacet_albedo_ggx", "microfacet_albedo_beckmann"):
        assert list(inspect.signature(getattr(brdftab, name)).parameters)[:2] == ["mu", "alpha"]
    for name in ("microfacet_albedo", "smith_gbeckmann_g1"):
        assert list(inspect.signature(getattr(brdftab.lookup, name)).parameters)[:2] == ["mu", "alpha"]


def test_broadcasting_and_scalars():
    c = np.linspace(0.1, 0.9, 3)[:, None, None]
    mu = np.linspace(0.1, 1.0, 4)[None, :, None]
    out = brdftab.h_iso(c, mu)
    assert out.shape == (3, 4, 1)
    np.testing.assert_array_equal(out[1, 2, 0], brdftab.h_iso(c[1, 0, 0], mu[0, 2, 0]))
    s = brdftab.h_iso(0.5, 0.5)
    assert isinstance(s, np.float64) and np.ndim(s) == 0
    with pytest.raises(ValueError):
        brdftab.h_iso(np.zeros(3), np.zeros(4))
    assert brdftab.h_iso(np.zeros((0, 2)), 0.5).shape == (0, 2)


def test_one_output_is_an_array_several_a_named_tuple():
    assert isinstance(brdftab.h_iso(0.5, [0.5]), np.ndarray)
    r = brdftab.microfacet_albedo_ggx([0.5, 0.9], 0.3)
    assert type(r).__name__ == "MicrofacetAlbedoGgxResult"
    assert r._fields == ("E_corr", "E_sep", "split_scale", "split_bias")
    e_corr, e_sep, scale, bias = r  # unpacks like a tuple
    np.testing.assert_array_equal(e_corr, r.E_corr)
    # The split-sum pair adds up to E (height-correlated G2): scale + bias = Integral f cos at
    # F = 1, the weights (1 - (1 - cos)^5) and (1 - cos)^5 summing to 1 (separate quadratures).
    np.testing.assert_allclose(scale + bias, e_corr, rtol=1e-12)
    assert np.all(e_sep < e_corr)  # the separable G1 G1 masks more than the correlated G2


def test_float32_in_float32_out_computed_in_float64():
    c = np.array([0.3, 0.8], dtype=np.float32)
    mu = np.array([0.25, 0.5], dtype=np.float32)
    out = brdftab.h_iso(c, mu)
    assert out.dtype == np.float32
    # Computed in float64 at the float32 inputs, then rounded once.
    ref = brdftab.h_iso(c.astype(np.float64), mu.astype(np.float64))
    np.testing.assert_array_equal(out, ref.astype(np.float32))
    assert brdftab.h_iso(np.float32([0.5]), 0.5).dtype == np.float32  # a Python float does not promote an array
    assert brdftab.h_iso(c, mu.astype(np.float64)).dtype == np.float64
    assert brdftab.h_iso(1, 1).dtype == np.float64  # integers give float64, as in SciPy
    t = brdftab.Table(os.path.join(TABLES, "demo.h5"), "demo_exp_cos")
    assert t(np.float32([0.5]), np.float32([0.5])).dtype == np.float32
    assert brdftab.lookup.ls_kd(np.float32([0.5]), tables=TABLES).dtype == np.float32
    with pytest.raises(TypeError, match="complex"):
        brdftab.h_iso(0.5 + 1j, 0.5)


def test_nan_in_nan_out_whatever_the_errors_policy():
    for errors in ("nan", "raise", "clamp"):
        out = brdftab.h_iso([0.5, np.nan, 0.5], [0.5, 0.5, np.nan], errors=errors)
        assert np.isfinite(out[0]) and np.isnan(out[1]) and np.isnan(out[2])
        r = brdftab.microfacet_albedo_ggx([np.nan, 0.5], 0.3, errors=errors)
        assert all(np.isnan(x[0]) and np.isfinite(x[1]) for x in r)
        got = brdftab.lookup.microfacet_albedo([np.nan, 0.5], 0.3, tables=TABLES, errors=errors)
        assert np.isnan(got[0]) and np.isfinite(got[1])


def test_errors_policy_out_of_the_domain():
    c = [0.5, 1.5, -0.1]
    out = brdftab.h_iso(c, 0.5)  # default "nan": only the bad elements
    assert np.isfinite(out[0]) and np.isnan(out[1:]).all()
    with pytest.raises(ValueError, match=r"h_iso: index 1, parameter 'c': value 1.5 is outside the valid domain \[0, 1\]"):
        brdftab.h_iso(c, 0.5, errors="raise")
    clamped = brdftab.h_iso(c, 0.5, errors="clamp")
    np.testing.assert_array_equal(clamped[1:], brdftab.h_iso([1.0, 0.0], 0.5))
    with pytest.raises(ValueError, match="errors = 'ignore' is not one of"):
        brdftab.h_iso(0.5, 0.5, errors="ignore")


def test_errors_policy_outside_a_table_range():
    # The microfacet tables cover mu in [1e-6, 1]: mu = 0 and 5e-7 are in the quantity's
    # domain for clamping only. One such element no longer fails the whole array.
    mu = np.array([0.0, 5e-7, 0.5])
    got = brdftab.lookup.microfacet_albedo(mu, 0.3, tables=TABLES)
    assert np.isnan(got[:2]).all() and np.isfinite(got[2])
    with pytest.raises(ValueError, match=r"index 0, parameter 'mu': value 0 is outside the table range \[1e-06, 1\]"):
        brdftab.lookup.microfacet_albedo(mu, 0.3, tables=TABLES, errors="raise")
    edge = brdftab.lookup.microfacet_albedo(1e-6, 0.3, tables=TABLES)
    np.testing.assert_array_equal(brdftab.lookup.microfacet_albedo(mu, 0.3, tables=TABLES, errors="clamp")[:2], edge)
    # The same through the quantity's table method.
    r = brdftab.microfacet_albedo_ggx(mu, 0.3, method="table", tables=TABLES, errors="clamp")
    np.testing.assert_array_equal(r.E_corr[:2], edge)
    t = brdftab.Table(os.path.join(TABLES, "demo.h5"), "demo_exp_cos")
    assert np.isnan(t(1.0, 2.0))
    with pytest.raises(ValueError, match=r"parameter 'y': value 2 is outside the table range"):
        t(1.0, 2.0, errors="raise")
    assert t(1.0, 2.0, errors="clamp") == t(1.0, np.pi / 2)


def test_deprecated_names_warn_once_per_call():
    a = np.array([0.3, 1.2])
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        old = brdftab.smith_gb(1.5, a)
    assert len(w) == 1 and issubclass(w[0].category, DeprecationWarning) and "smith_gbeckmann" in str(w[0].message)
    np.testing.assert_array_equal(old.G1, brdftab.smith_gbeckmann(1.5, a).G1)
    assert "k_d" in inspect.signature(brdftab.ls_c).parameters
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        c_old = brdftab.ls_c(kd=0.5)
    assert len(w) == 1 and issubclass(w[0].category, DeprecationWarning) and "k_d" in str(w[0].message)
    assert c_old == brdftab.ls_c(k_d=0.5) == brdftab.ls_c(0.5)
    # ls_c inverts ls_kd (two methods that share no code: the k_d(c) solve and its inversion).
    assert abs(brdftab.ls_kd(brdftab.ls_c(0.5)) - 0.5) < 1e-9


def test_a_path_with_an_embedded_nul_is_refused_naming_the_parameter():
    # The C++ side would stop reading the path at the NUL: another file, silently.
    hfunc = os.path.join(TABLES, "hfunc.h5")
    for call, name in [
        (lambda: brdftab.list_tables(hfunc + "\0.bak"), "path"),
        (lambda: brdftab.open_dataset(hfunc + "\0x", "hfunc_iso"), "path"),
        (lambda: brdftab.Table(hfunc + "\0x", "hfunc_iso"), "path"),
        (lambda: brdftab.lookup.microfacet_albedo(0.5, 0.3, tables=TABLES + "\0/elsewhere"), "tables"),
    ]:
        with pytest.raises(ValueError, match=name + ": embedded null byte"):
            call()
    # bytes paths are file-system paths too
    assert "hfunc_iso" in brdftab.list_tables(os.fsencode(hfunc))
