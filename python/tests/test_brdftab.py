"""The Python bindings against independent references: closed forms written here in
NumPy, Chandrasekhar's published H-function value, and the CLI's own error messages."""
import math
import os

import numpy as np
import pytest

import brdftab

TABLES = os.path.join(os.environ["BRDFTAB_SOURCE_DIR"], "tables")


def test_every_eval_quantity_is_a_function():
    names = brdftab.quantities()
    assert "h_iso" in names and "smith_gb" in names and "demo_exp_cos" in names
    for name in names:
        assert callable(getattr(brdftab, name))


def test_demo_exact_is_the_closed_form_and_broadcasts():
    x = np.linspace(0.0, 3.0, 7)[:, None]
    y = np.array([0.0, 0.3, 1.5])
    out = brdftab.demo_exp_cos(x=x, y=y)
    assert out["value"].shape == (7, 3)
    np.testing.assert_allclose(out["value"], np.exp(-x) * np.cos(y), rtol=1e-15, atol=0)


def test_table_method_within_the_stated_error():
    x = np.random.default_rng(1).uniform(0, 5, 500)
    y = np.random.default_rng(2).uniform(0, np.pi / 2, 500)
    got = brdftab.demo_exp_cos(x=x, y=y, method="table", tables=TABLES)["value"]
    t = brdftab.Table(os.path.join(TABLES, "demo.h5"), "demo_exp_cos")
    assert np.max(np.abs(got - np.exp(-x) * np.cos(y))) <= t.max_abs_error
    np.testing.assert_array_equal(t(x, y), got)  # the same lookup
    assert [a["name"] for a in t.axes] == ["x", "y"]


def test_h_iso_conservative_published_value():
    # Chandrasekhar, Radiative Transfer (1960), Table XI: H(mu = 1) = 2.90781 for c = 1.
    h = brdftab.h_iso(c=1.0, mu=1.0)["H"]
    assert abs(float(h) - 2.90781) < 1e-5


def test_smith_gb_at_p1_is_the_beckmann_closed_form():
    a = np.array([0.1, 0.5, 1.0, 3.0])
    nu = 1 / a
    lam = np.array([(math.exp(-v * v) / (v * math.sqrt(math.pi)) - math.erfc(v)) / 2 for v in nu])
    out = brdftab.smith_gb(p=1.0, a=a)
    np.testing.assert_allclose(out["Lambda"], lam, rtol=1e-12)
    np.testing.assert_allclose(out["G1"], 1 / (1 + lam), rtol=1e-13)


def test_bad_input_raises_valueerror_with_eval_message():
    with pytest.raises(ValueError, match=r"h_iso: index 1, column 'c': value 1.5 is outside the valid domain \[0, 1\]"):
        brdftab.h_iso(c=[0.5, 1.5], mu=0.5)
    with pytest.raises(ValueError, match="is not a number"):
        brdftab.h_iso(c=float("nan"), mu=0.5)
    with pytest.raises(ValueError, match="missing column 'mu'"):
        brdftab.h_iso(c=0.5)
    with pytest.raises(ValueError, match="unknown column 'nu'"):
        brdftab.h_iso(c=0.5, mu=0.5, nu=1)
    with pytest.raises(ValueError, match="no method 'fit'"):
        brdftab.demo_exp_cos(x=1, y=1, method="fit")
    t = brdftab.Table(os.path.join(TABLES, "demo.h5"), "demo_exp_cos")
    with pytest.raises(ValueError, match="outside the table domain"):
        t(1.0, 2.0)
    assert np.isfinite(t(1.0, 2.0, clamp=True))
