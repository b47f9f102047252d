"""sealsim.friction_loop: the hysteresis loop of a friction law over a harmonic velocity,
checked against the steady friction of the same law (sealsim.seal_friction)."""

import numpy as np
import pytest

import sealsim
from sealsim.errors import InputError

ORING = {"cord_diameter": "2 mm", "squeeze": 0.12}


def test_a_law_without_states_follows_its_steady_curve():
    law = {"law": "stribeck", "parameter_set": "pneumatic_demo"}
    loop = sealsim.friction_loop(ORING, "0.2 m/s", "2 Hz", "6 bar", law=law, diameter="12 mm",
                                 cycles=1, steps_per_cycle=50)
    steady = sealsim.seal_friction(ORING, [f"{v!r} m/s" for v in loop["velocity_m_s"]], "6 bar",
                                   law=law, diameter="12 mm")
    # the same law and contact map, evaluated point by point: equal to round-off
    np.testing.assert_allclose(loop["friction_N"], steady["friction_N"], rtol=1e-9, atol=1e-9)


def test_lugre_lags_behind_the_velocity_and_the_lag_vanishes_when_slow():
    law = {"law": "lugre", "parameter_set": "canudas1995"}
    # Canudas de Wit et al. (1995), Fig. 3: v = 1e-3 (cos wt + 1.5) m/s; the loop opens up
    # as w grows.  Loop area (friction over velocity, last cycle) at 0.16 Hz and 4 Hz.
    areas = []
    for f in ("0.159 Hz", "3.98 Hz"):
        loop = sealsim.friction_loop(ORING, "1 mm/s", f, "6 bar", law=law, diameter="12 mm",
                                     mean_velocity="1.5 mm/s", cycles=3, steps_per_cycle=2000)
        last = loop.iloc[-2001:]
        v, force = last["velocity_m_s"].to_numpy(), last["friction_N"].to_numpy()
        areas.append(abs(np.sum(0.5 * (force[1:] + force[:-1]) * np.diff(v))))
    assert areas[1] > 5 * areas[0] > 0


def test_bad_arguments_are_refused():
    with pytest.raises(InputError, match="frequency"):
        sealsim.friction_loop(ORING, "1 mm/s", "0 Hz", diameter="12 mm")
    with pytest.raises(InputError):
        sealsim.friction_loop(ORING, "1 mm/s", "1 Hz", diameter="12 mm", cycles=0)


@pytest.mark.parametrize(("kwargs", "message"), [
    # 2.5 cycles were run as 2 and '400' steps as 400, without a word
    ({"cycles": 2.5}, r"cycles = 2.5 must be a whole number from 1 to 50"),
    ({"steps_per_cycle": "400"}, r"steps_per_cycle = '400' must be a whole number"),
    ({"cycles": 0}, r"cycles = 0 must be a whole number from 1 to 50"),
    # 'velocity_amplitude and frequency must be > 0, pressure >= 0': which one, which value?
    ({"velocity_amplitude": "-1 mm/s"}, r"velocity_amplitude: '-1 mm/s' must be > 0"),
    ({"pressure": "-1 bar"}, r"pressure: '-1 bar' must be >= 0"),
])
def test_a_bad_argument_is_named_with_its_value(kwargs, message):
    args = {"seal": ORING, "velocity_amplitude": "1 mm/s", "frequency": "1 Hz",
            "diameter": "12 mm", **kwargs}
    with pytest.raises(InputError, match=message):
        sealsim.friction_loop(**args)
