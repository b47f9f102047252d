"""What moves the contact's rise over a held sump -- a Python API example (issue 24).

The default ``gearbox`` set-up and the ``test_rig`` set-up with the 80 mm DIN 3760 NBR seal in
VG 68, the sump held at 80 degC, 20 degC ambient, steady state: the contact's rise over the
sump for the defaults and for each environment option that stands for a candidate cause of a
too-cool contact (the annulus's convection, the oil-to-wall coefficient that sets the housing
temperature, the air side, the bearing's heat).  Every row changes one documented case field,
so each number can be reproduced from a case file.  Prints a Markdown table (the one in the
documentation's rotary validation page, finding 1).

    python examples/rotary/contact_rise_candidates.py
"""

import math
import warnings

from sealsim.cases import validate_case
from sealsim.rotary.case import RotaryCase
from sealsim.rotary.simulation import steady_state

#: (label, environment fields) of each row; the sump is held at 80 degC in all of them.
VARIANTS = [
    ("gearbox (default)", {}),
    ("gearbox, oil_gap 2 mm (wall h x1.6)", {"oil_gap": "2 mm"}),
    ("gearbox, oil_gap 40 mm (wall h x0.6)", {"oil_gap": "40 mm"}),
    ("gearbox, shaft_oil_convection open", {"shaft_oil_convection": "open"}),
    ("gearbox, oil_housing_heat_transfer 300", {"oil_housing_heat_transfer": "300 W/(m**2*K)"}),
    ("gearbox, oil_housing_heat_transfer 1000",
     {"oil_housing_heat_transfer": "1000 W/(m**2*K)"}),
    ("gearbox, housing held at 80 degC", {"housing_temperature": "80 degC"}),
    ("gearbox, shaft_air_end insulated", {"shaft_air_end": "insulated"}),
    ("gearbox, shaft_air_end housing", {"shaft_air_end": "housing"}),
    ("gearbox, bearing shaft_share 1", {"bearing": {"shaft_share": 1.0}}),
    ("gearbox, bearing none", {"bearing": {"model": "none"}}),
    ("test_rig (default)", {"setup": "test_rig"}),
    ("test_rig, oil_gap 40 mm", {"setup": "test_rig", "oil_gap": "40 mm"}),
    ("test_rig, shaft_oil_convection open", {"setup": "test_rig",
                                             "shaft_oil_convection": "open"}),
]
#: (shaft diameter, speed [rpm]) of each column.
POINTS = [("80 mm", 10), ("80 mm", 100), ("80 mm", 1000), ("80 mm", 3000), ("40 mm", 1000)]


def rise(environment: dict, diameter: str, rpm: float) -> float:
    """Contact temperature minus the held 80 degC sump [K]."""
    case = validate_case(RotaryCase, {
        "seal": {"shaft_diameter": diameter},
        "environment": {"sump_temperature": "80 degC", **environment}})
    with warnings.catch_warnings():  # film-range notes are not the subject here
        warnings.simplefilter("ignore")
        return steady_state(case, rpm * math.pi / 30)["T_contact_C"] - 80.0


def main() -> None:
    print("| environment | " + " | ".join(f"{d}, {n} rpm" for d, n in POINTS) + " |")
    print("|---" * (len(POINTS) + 1) + "|")
    for label, environment in VARIANTS:
        cells = [f"{rise(environment, d, n):+.1f} K" for d, n in POINTS]
        print(f"| {label} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
