"""Curves (paper Fig. 3): every kind at its key points, continuity, keyframed tangent modes, the
coarticulation dominance (paper eq. 3)."""

import math

import numpy as np
import pytest

import thespis
from thespis import Curve, CurveKey, CurveKind, TangentMode


def derivative(curve, t, duration, h=1e-6):
    return (curve.evaluate(t + h, duration) - curve.evaluate(t - h, duration)) / (2 * h)


def test_default_curve_is_constant_one():
    c = Curve()
    assert c.kind == CurveKind.constant
    assert c.is_identity
    assert c.evaluate(-5.0) == 1.0 and c.evaluate(1e9) == 1.0
    assert Curve.constant(0.25).evaluate(3.0, 10.0) == 0.25
    assert not Curve.constant(0.25).is_identity


def test_linear_fade_key_points():
    c = Curve.linear_fade(1.0, 2.0, peak=0.8)
    d = 10.0
    expected = {-1.0: 0.0, 0.0: 0.0, 0.5: 0.4, 1.0: 0.8, 5.0: 0.8, 8.0: 0.8, 9.0: 0.4, 10.0: 0.0}
    for t, v in expected.items():
        assert c.evaluate(t, d) == pytest.approx(v, abs=1e-12), t
    assert c.kind == CurveKind.linear_fade
    assert c.envelope.attack == 1.0 and c.envelope.release == 2.0 and c.envelope.peak == 0.8


def test_cubic_fade_key_points_and_c1():
    c = Curve.cubic_fade(1.0, 1.0)
    d = 4.0
    assert c.evaluate(0.0, d) == 0.0
    assert c.evaluate(0.25, d) == pytest.approx(0.15625)  # 3u² − 2u³ at u = 1/4
    assert c.evaluate(0.5, d) == pytest.approx(0.5)
    assert c.evaluate(1.0, d) == pytest.approx(1.0)
    assert c.evaluate(3.5, d) == pytest.approx(0.5)
    # C1: the slope is 0 where each ramp meets the flat parts, on both sides.
    for t in (0.0, 1.0, 3.0, 4.0):
        assert abs(derivative(c, t, d, 1e-5)) < 1e-4, t
    assert thespis.smooth_step(0.25) == pytest.approx(0.15625)


def test_linear_fade_has_corners_where_cubic_does_not():
    lin = Curve.linear_fade(1.0, 1.0)
    assert derivative(lin, 1.0 - 1e-3, 4.0, 1e-5) == pytest.approx(1.0)
    assert derivative(lin, 1.0 + 1e-3, 4.0, 1e-5) == pytest.approx(0.0)


def test_linear_adsr_key_points():
    c = Curve.linear_adsr(1.0, 1.0, 0.5, 1.0)
    d = 10.0
    expected = {0.0: 0.0, 0.5: 0.5, 1.0: 1.0, 1.5: 0.75, 2.0: 0.5, 5.0: 0.5, 9.0: 0.5, 9.5: 0.25, 10.0: 0.0}
    for t, v in expected.items():
        assert c.evaluate(t, d) == pytest.approx(v, abs=1e-12), t


def test_cubic_adsr_key_points_and_c1():
    c = Curve.cubic_adsr(1.0, 1.0, 0.5, 1.0, peak=2.0)
    d = 10.0
    assert c.evaluate(1.0, d) == pytest.approx(2.0)
    assert c.evaluate(1.5, d) == pytest.approx(2.0 * 0.75)
    assert c.evaluate(2.0, d) == pytest.approx(1.0)
    assert c.evaluate(9.5, d) == pytest.approx(0.5)
    ts = np.linspace(0.0, d, 2001)
    values = c.evaluate(ts, d)
    slopes = np.gradient(values, ts)
    # C1: no jump in slope anywhere. Between samples 5 ms apart the slope changes by at most
    # |f''|·dt ≈ 12·0.005 here; the linear ADSR jumps by its whole ramp slope (2) at a corner.
    assert np.max(np.abs(np.diff(slopes))) < 0.1
    linear_slopes = np.gradient(Curve.linear_adsr(1.0, 1.0, 0.5, 1.0, peak=2.0).evaluate(ts, d), ts)
    assert np.max(np.abs(np.diff(linear_slopes))) > 0.9
    for t in (0.0, 1.0, 2.0, 9.0, 10.0):
        assert abs(derivative(c, t, d, 1e-5)) < 1e-3, t


def test_open_ended_actions_never_release():
    c = Curve.linear_fade(1.0, 1.0)
    assert c.evaluate(100.0) == 1.0
    assert c.evaluate(100.0, Curve.INFINITE) == 1.0
    assert math.isinf(Curve.INFINITE)


def test_evaluate_accepts_arrays():
    c = Curve.linear_fade(1.0, 1.0)
    values = c.evaluate(np.array([0.0, 0.5, 1.0, 2.5, 3.0]), 3.0)
    assert isinstance(values, np.ndarray)
    np.testing.assert_allclose(values, [0.0, 0.5, 1.0, 0.5, 0.0])


def test_keyframed_curve_passes_through_keys():
    keys = [CurveKey(0.0, 0.0), CurveKey(1.0, 1.0), CurveKey(2.0, 0.5), CurveKey(4.0, 2.0)]
    c = Curve.keyframed(keys)
    assert c.kind == CurveKind.keyframed
    for k in keys:
        assert c.evaluate(k.time) == pytest.approx(k.value)
    # Outside the keys the curve holds the end values.
    assert c.evaluate(-1.0) == 0.0 and c.evaluate(10.0) == 2.0
    assert len(c.keys) == 4 and c.keys[1] == keys[1]


def test_keyframed_keys_are_sorted():
    c = Curve.keyframed([CurveKey(2.0, 4.0), CurveKey(0.0, 0.0)])
    assert [k.time for k in c.keys] == [0.0, 2.0]


def test_auto_clamped_never_overshoots():
    c = Curve.keyframed([CurveKey(0.0, 0.0), CurveKey(1.0, 1.0), CurveKey(1.2, 1.0), CurveKey(3.0, 0.0)])
    values = c.evaluate(np.linspace(0.0, 3.0, 3001))
    assert values.max() <= 1.0 + 1e-12 and values.min() >= -1e-12


def test_constant_tangent_steps():
    c = Curve.keyframed([CurveKey(0.0, 1.0, TangentMode.constant), CurveKey(1.0, 3.0)])
    assert c.evaluate(0.999) == 1.0
    assert c.evaluate(1.0) == 3.0


def test_linear_tangents_give_straight_segments():
    c = Curve.keyframed([CurveKey(0.0, 0.0, TangentMode.linear), CurveKey(2.0, 4.0, TangentMode.linear)])
    for t in (0.25, 0.5, 1.0, 1.5):
        assert c.evaluate(t) == pytest.approx(2.0 * t)


def test_free_and_broken_slopes():
    free = Curve.keyframed([CurveKey(0.0, 0.0, TangentMode.free, in_slope=3.0), CurveKey(1.0, 1.0, TangentMode.free, in_slope=0.0)])
    assert derivative(free, 1e-4, math.inf) == pytest.approx(3.0, rel=1e-2)
    assert derivative(free, 1.0 - 1e-4, math.inf) == pytest.approx(0.0, abs=1e-2)
    broken = Curve.keyframed([CurveKey(0.0, 0.0), CurveKey(1.0, 1.0, TangentMode.broken, in_slope=2.0, out_slope=-2.0),
                              CurveKey(2.0, 0.0)])
    assert derivative(broken, 1.0 - 1e-4, math.inf) == pytest.approx(2.0, rel=1e-2)
    assert derivative(broken, 1.0 + 1e-4, math.inf) == pytest.approx(-2.0, rel=1e-2)


def test_keyframed_errors_are_value_errors_with_messages():
    with pytest.raises(ValueError, match="at least one key"):
        Curve.keyframed([])
    with pytest.raises(ValueError, match="same time"):
        Curve.keyframed([CurveKey(1.0, 0.0), CurveKey(1.0, 2.0)])
    with pytest.raises(ValueError, match="finite"):
        Curve.keyframed([CurveKey(0.0, float("nan"))])


def test_validate_rejects_bad_parameters():
    Curve.cubic_adsr(0.1, 0.2, 0.5, 0.3).validate()
    with pytest.raises(ValueError, match="negative"):
        Curve.linear_fade(-1.0, 0.0).validate()
    with pytest.raises(ValueError, match="sustain"):
        Curve.linear_adsr(0.1, 0.1, 1.5, 0.1).validate()


def test_curves_are_values():
    a = Curve.cubic_fade(0.5, 0.25)
    assert a == Curve.cubic_fade(0.5, 0.25)
    assert a != Curve.linear_fade(0.5, 0.25)
    assert "cubic_fade" in repr(a)


def paper_dominance(alpha, x):
    """Eq. 3 written out apart from the module: C_α(x) = e^(−α·2|x−0.5|) − 2|x−0.5|·e^(−α)."""
    distance = abs(2 * x - 1)
    return math.exp(-alpha * distance) - distance / math.exp(alpha)


@pytest.mark.parametrize("alpha", [2.0, 5.0])
def test_dominance_follows_equation_3(alpha):
    xs = [i / 10 for i in range(11)] + list(np.random.default_rng(7).uniform(0.0, 1.0, 50))
    d = 3.0
    c = Curve.dominance(alpha, peak=0.7)
    for x in xs:
        assert thespis.dominance(alpha, x) == pytest.approx(paper_dominance(alpha, x), abs=1e-12), x
        assert c.evaluate(x * d, d) == pytest.approx(0.7 * paper_dominance(alpha, x), abs=1e-12), x
    assert c.evaluate(d / 2, d) == pytest.approx(0.7)
    assert c.evaluate(0.0, d) == pytest.approx(0.0, abs=1e-15)
    assert c.evaluate(d, d) == pytest.approx(0.0, abs=1e-15)
    # Arrays of x as well as numbers, as Curve.evaluate takes them.
    np.testing.assert_allclose(thespis.dominance(alpha, np.array(xs)), [paper_dominance(alpha, x) for x in xs], atol=1e-12)


def test_dominance_curve_parameters_repr_and_validation():
    c = Curve.dominance(5.0)
    assert c.kind == CurveKind.dominance
    assert c.envelope.alpha == 5.0 and c.envelope.peak == 1.0
    assert c == Curve.dominance(5.0, peak=1.0) and c != Curve.dominance(2.0)
    assert repr(Curve.dominance(2.5, peak=0.5)) == "Curve.dominance(2.5, peak=0.5)"
    assert c.evaluate(100.0) == 1.0  # open-ended: holds the peak
    c.validate()
    for alpha in (0.0, -1.0):
        with pytest.raises(ValueError, match="alpha"):
            Curve.dominance(alpha).validate()
    with pytest.raises(ValueError, match="finite"):
        Curve.dominance(float("inf")).validate()
