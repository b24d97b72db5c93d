"""Extreme gains: the loops' stability check gives its verdict (or a HybridError), never a foreign
exception from the eigenvalue solver or the matrix exponential."""

from __future__ import annotations

import math
import warnings

import pytest

import hybrid
from hybrid.control.loops import Gains
from hybrid.validate import field_values

GAINS_FIELDS = list(field_values(Gains()))

T = 1e-3


def _radii(**gains) -> dict[str, float]:
    exp = hybrid.paper_experiment(sample_time=T, integration_step=T / 10, allow_unstable=True, **gains)
    report = hybrid.stability(exp, margins=False)
    return {loop.axis: loop.spectral_radius for loop in report.loops} | {"coupled": report.spectral_radius}


@pytest.mark.parametrize("name", GAINS_FIELDS)
@pytest.mark.parametrize("value", [1e300, 1e305, 1.7e308, 1e-300])
def test_an_extreme_gain_gets_a_verdict(name, value):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        radii = _radii(**{name: value})
    for radius in radii.values():
        assert radius >= 0 and not math.isnan(radius)


@pytest.mark.parametrize("name", ["KPf", "KDf", "KPv"])
def test_the_radius_grows_with_the_gain_up_to_inf(name):
    # independent of the overflow handling: the finite radii already grow with the gain
    axis = "n" if name.endswith("f") else "t1"
    radii = [_radii(**{name: v})[axis] for v in (1e2, 1e4, 1e6, 1e300, 1.7e308)]
    assert radii == sorted(radii) and radii[2] > 1


def test_an_overflowing_gain_is_an_unstable_loop_naming_the_gain():
    with pytest.raises(hybrid.HybridError, match=r"force loop on n is unstable.*overflows: KPf = 1.7e\+308"):
        hybrid.paper_experiment(KPf=1.7e308)  # KPf*k beyond the largest float


@pytest.mark.parametrize("name", GAINS_FIELDS)
def test_a_tiny_gain_is_accepted_or_refused_in_words(name):
    # 1e-300 leaves an integrator's eigenvalue at 1 (marginal): a verdict, never a solver's exception
    try:
        hybrid.paper_experiment(**{name: 1e-300})
    except hybrid.HybridError as exc:
        assert "loop" in str(exc) and "is unstable" in str(exc) and "spectral radius" in str(exc)
