"""scripts/real_data/plots.py: the rim ring it draws as the centred patches' torque envelope is the
library's (coulomb_envelope.hpp: Lambda(2) = 0.276872, Lambda(1) = 1, Lambda(10) = 0.0501884, and
the limits P -> s/2, Q -> 1 at s -> 0 and P -> 1, Q -> 1/(2 s) at s -> infinity)."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts" / "real_data"))
pytest.importorskip("scipy")
pytest.importorskip("matplotlib")
import plots  # noqa: E402


def test_the_rim_ring_is_the_librarys_envelope():
    s = np.array([1.0, 2.0, 10.0])
    P, Q = plots.ring(s)
    np.testing.assert_allclose(Q / P, [1.0, 0.276872, 0.0501884], rtol=2e-6)


def test_the_rim_ring_has_the_right_limits():
    P, Q = plots.ring(np.array([1e-4, 1e4]))
    np.testing.assert_allclose([P[0] / 1e-4, Q[0]], [0.5, 1.0], rtol=1e-3)
    np.testing.assert_allclose([P[1], Q[1] * 2e4], [1.0, 1.0], rtol=1e-3)
