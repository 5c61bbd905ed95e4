"""A seeded random search over the Python module's entry points (issue 36: "every internal error
reachable from input is a finding"): points, directions, skies, sites and luminaire numbers drawn
from ordinary and extreme values (0, ±1e-300, ±1e300, nan, inf). Each call must return finite
results or raise candela.InputError (bad input, with its place); a RuntimeError (candela's
internal error), any other exception or a crash is a finding. Deterministic: the same draws
every run."""
import math

import numpy as np
import pytest

import candela

EXTREMES = [0.0, -0.0, 1e-300, -1e-300, 1e300, -1e300, math.nan, math.inf, -math.inf, 1e8, -1e8]


def draw(rng, typical):
    """An ordinary value (about `typical`) three times in four, else an extreme one."""
    if rng.random() < 0.75:
        return float(typical * (0.5 + rng.random()))
    return EXTREMES[int(rng.integers(len(EXTREMES)))]


def accepted_or_input_error(call):
    try:
        lux, err = call()
    except candela.InputError:
        return "refused"
    assert np.all(np.isfinite(lux)) and np.all(np.isfinite(err))
    return "accepted"


def test_random_points_skies_and_luminaires_are_results_or_input_errors(reference):
    rng = np.random.default_rng(36)
    ies = next((reference / "photometry").rglob("*.ies"))
    outcomes = {"accepted": 0, "refused": 0}
    for _ in range(120):
        point = [draw(rng, 1.0) for _ in range(3)] + [draw(rng, 1.0) for _ in range(3)]
        sky = candela.Sky.uniform(draw(rng, 10000.0), ground_reflectance=min(1.0, abs(draw(rng, 0.2))))
        outcomes[accepted_or_input_error(
            lambda: candela.illuminance(None, [point], sky=sky, quality="draft", threads=1))] += 1
    for _ in range(60):
        lum = candela.Luminaire(ies, tuple(draw(rng, 2.0) for _ in range(3)),
                                aim=tuple(draw(rng, -1.0) for _ in range(3)), spin=draw(rng, 30.0),
                                multiplier=draw(rng, 1.0), maintenance_factor=min(1.0, abs(draw(rng, 0.8))))
        outcomes[accepted_or_input_error(
            lambda: candela.illuminance(None, [[0, 0, 0, 0, 0, 1]], luminaires=[lum], quality="draft",
                                        threads=1))] += 1
    for _ in range(60):
        try:
            site = candela.Site(draw(rng, 45.0), draw(rng, 10.0), timezone=draw(rng, 1.0))
            candela.sun_position(site, "2026-06-21 12:00")
            outcomes["accepted"] += 1
        except candela.InputError:
            outcomes["refused"] += 1
    # Both kinds occurred: the search reached the readers' checks and the tracing alike.
    assert outcomes["accepted"] > 0 and outcomes["refused"] > 0, outcomes
