"""sealsim vs ISO/TR 14179-2 seal losses -- a Python API example.

ISO/TR 14179-2 puts the loss of one contact lip seal at P = 7.69e-6 * d^2 * n [W] (d in mm,
n in rpm): a constant torque, whatever the oil, temperature or seal. This script computes
steady-state operating points of sealsim's default DIN 3760 NBR seal of each size, with VG 68 oil
and the sump held at 80 degC (the default 'gearbox' shaft environment), and prints a Markdown
table (the one in the documentation's rotary validation page).  A contact above the
elastomer's service limit is marked (as the notes of ``sealsim rotary run`` and
``sealsim.lip_seal_torque`` say it): the seal would not last there.

    python examples/rotary/iso_comparison.py
"""

import math

from sealsim.cases import validate_case
from sealsim.properties.elastomers import get_elastomer
from sealsim.rotary.case import RotaryCase
from sealsim.rotary.simulation import steady_state
from sealsim.units import ZERO_CELSIUS_K


def main() -> None:
    service_max = get_elastomer("NBR").service_range[1] - ZERO_CELSIUS_K
    print("| d [mm] | n [rpm] | ISO P [W] | sealsim P [W] | ratio | torque [N m] | "
          "T_contact [°C] | film [µm] |")
    print("|---|---|---|---|---|---|---|---|")
    for d in (40, 60, 80, 100, 120):
        case = validate_case(RotaryCase, {
            "seal": {"shaft_diameter": f"{d} mm", "material": "NBR"},
            "oil": {"name": "VG68-mineral"},
            "environment": {"sump_temperature": "80 degC"},
            "duty": {"steps": [{"speed": "1000 rpm", "duration": "1 s"}]}})  # not used here
        for n in (1000, 2000, 3000):
            point = steady_state(case, n * math.pi / 30)
            iso = 7.69e-6 * d**2 * n
            hot = " †" if point["T_contact_C"] > service_max else ""
            print(f"| {d} | {n} | {iso:.1f} | {point['power_W']:.1f} | "
                  f"{point['power_W'] / iso:.2f} | {point['torque_Nm']:.3f} | "
                  f"{point['T_contact_C']:.1f}{hot} | {point['film_um']:.2f} |")
    print(f"\n† above the service limit of NBR ({service_max:.0f} °C): a hotter elastomer "
          "(HNBR, FKM) or more cooling")


if __name__ == "__main__":
    main()
