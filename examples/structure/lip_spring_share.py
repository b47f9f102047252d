"""What the garter spring of a DIN 3760 lip carries -- a Python API example.

The 80 x 101 x 9 NBR lip of the rotary model's FE (``radial_lip_profile``, 80 mm shaft,
mounted at 20 degC) is run with its rubber constants scaled from 1.0 to 0.4 of the catalogue's
(the 1 Hz level they are fitted at; the held modulus of a lip held an hour is 0.51 of it), each
with and without its garter spring, and at the default modulus with the spring's axial offset
from the lip edge (the R value) from 0 to 0.8 mm. It prints a Markdown table and writes
``lip_spring_share.csv``, ``lip_spring_share.png`` (forces, shares, contact width and peak
pressure against the modulus) and ``lip_sections.png`` (the installed lip at each modulus).

The lip with its spring presses with F = alpha * 2 pi T + F_without: the lip without its spring
carries a force proportional to the modulus, and the spring adds a constant part of its own
radial force 2 pi T -- constant because the split of a load between the supports of an elastic
body does not depend on its modulus, and only a part (alpha < 1) because the spring's seat lies
behind the contact edge and the flex carries the rest to the case (alpha grows as the R value
shrinks). See docs/guide/seal_profiles.md.

    python examples/structure/lip_spring_share.py --out results/lip_spring_share [--mesh medium]
"""

import argparse
import warnings

import numpy as np
import pandas as pd
from matplotlib.collections import PolyCollection

from sealsim.cases import validate_case
from sealsim.output import ResultFolder
from sealsim.plotting import new_figure
from sealsim.properties.elastomers import get_elastomer
from sealsim.structure.case import StructureCase
from sealsim.structure.profiles import SPRING_OFFSET
from sealsim.structure.run import run_case

SCALES = (1.0, 0.85, 0.7, 0.6, 0.51, 0.4)
OFFSETS = (0.0, 0.3e-3, SPRING_OFFSET, 0.8e-3)


def installed_lip(scale: float, spring: bool, offset: float, mesh: str):
    """The last state of the lip installed at 20 degC with the rubber constants x ``scale``."""
    c10, c01, bulk = get_elastomer("NBR").mooney_rivlin(293.15)
    seal = {"type": "radial_lip", "outer_diameter": "101 mm", "width": "9 mm",
            "spring_offset": f"{offset} m"}
    if not spring:
        seal.update(spring_rate="0 N/m", spring_tension="0 N")
    case = validate_case(StructureCase, {
        "seal": seal, "gland": {"arrangement": "shaft", "sealing_diameter": "80 mm"},
        "material": {"c10": f"{c10 * scale} Pa", "c01": f"{c01 * scale} Pa",
                     "bulk_modulus": f"{bulk} Pa", "temperature_scaling": "none"},
        "mesh": {"level": mesh}, "load": {"installation_temperature": "20 degC",
                                          "squeeze_increments": 8}})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        return run_case(case).states[-1]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="results/lip_spring_share")
    parser.add_argument("--mesh", default="coarse", choices=("coarse", "medium", "fine"))
    parser.add_argument("--force", action="store_true", help="replace an existing folder")
    args = parser.parse_args()
    with ResultFolder(args.out, force=args.force) as folder:
        rows, sections = [], {}
        for scale, offset in [(s, SPRING_OFFSET) for s in SCALES] + [
                (1.0, o) for o in OFFSETS if o != SPRING_OFFSET]:
            with_spring = installed_lip(scale, True, offset, args.mesh)
            bare = installed_lip(scale, False, offset, args.mesh)
            if offset == SPRING_OFFSET:
                sections[scale] = with_spring
            rows.append({
                "modulus_scale": scale, "spring_offset_mm": offset * 1e3,
                "F_N": with_spring.F_N, "F_without_spring_N": bare.F_N,
                "spring_radial_force_N": with_spring.spring_force,
                "alpha": (with_spring.F_N - bare.F_N) / with_spring.spring_force,
                "rubber_share": bare.F_N / with_spring.F_N,
                "F_minus_spring_share": 1 - with_spring.spring_force / with_spring.F_N,
                "b_mm": with_spring.b * 1e3, "p_max_MPa": with_spring.p_max / 1e6,
                "b_without_spring_mm": bare.b * 1e3,
                "p_max_without_spring_MPa": bare.p_max / 1e6})
        table = pd.DataFrame(rows)
        folder.write_csv("lip_spring_share.csv", table, float_format="%.6g")
        folder.savefig("lip_spring_share.png", _curves(table[table.spring_offset_mm ==
                                                             SPRING_OFFSET * 1e3]))
        folder.savefig("lip_sections.png", _sections(sections))
    print("| modulus x constants | R [mm] | F [N] | F without spring [N] | 2πT [N] | α | "
          "F_without/F | (F − 2πT)/F | b [mm] | p_max [MPa] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['modulus_scale']:g} | {r['spring_offset_mm']:g} | {r['F_N']:.2f} | "
              f"{r['F_without_spring_N']:.2f} | {r['spring_radial_force_N']:.2f} | "
              f"{r['alpha']:.3f} | {r['rubber_share']:.3f} | "
              f"{r['F_minus_spring_share']:.3f} | {r['b_mm']:.3f} | {r['p_max_MPa']:.2f} |")


def _curves(t):
    fig, ax = new_figure(4, 1, width=16.0, height=4.0)
    s = t["modulus_scale"]
    ax[0].plot(s, t["F_N"], "-o", label="lip with its spring, F")
    ax[0].plot(s, t["F_without_spring_N"], "-s", label="without its spring, F_without")
    ax[0].plot(s, t["F_N"] - t["F_without_spring_N"], ":^", label="F − F_without")
    ax[0].plot(s, t["spring_radial_force_N"], "--", label="spring's own radial force 2πT")
    ax[0].set_ylabel("radial force (360°) [N]")
    ax[1].plot(s, t["rubber_share"], "-s", label="F_without / F")
    ax[1].plot(s, t["F_minus_spring_share"], "-o", label="(F − 2πT) / F")
    ax[1].axhline(0.0, color="0.3", lw=0.6)
    ax[1].set_ylabel("rubber's share [-]")
    ax[2].plot(s, t["b_mm"], "-o", label="with spring")
    ax[2].plot(s, t["b_without_spring_mm"], "-s", label="without spring")
    ax[2].set_ylabel("contact width b [mm]")
    ax[3].plot(s, t["p_max_MPa"], "-o", label="with spring")
    ax[3].plot(s, t["p_max_without_spring_MPa"], "-s", label="without spring")
    ax[3].set_ylabel("peak contact pressure [MPa]")
    for a in ax:
        a.axvline(0.51, color="0.6", lw=0.8, ls="--")
        a.set_xlabel("rubber constants × catalogue (held modulus: 0.51)")
        a.invert_xaxis()
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    fig.suptitle("DIN 3760 lip 80 x 101 x 9, NBR, installed at 20 °C: what the spring carries")
    return fig


def _sections(states):
    fig, axes = new_figure(len(states), 1, width=3.0 * len(states), height=3.6)
    vmax = max(float(st.von_mises.max()) for st in states.values()) / 1e6
    for ax, (scale, st) in zip(np.atleast_1d(axes), states.items()):
        pts = st.deformed_points * 1e3
        coll = ax.add_collection(PolyCollection(
            pts[st.cells], array=st.von_mises / 1e6, cmap="viridis", clim=(0.0, vmax),
            edgecolors="face", linewidths=0.2))
        shaft = st.lines[0].point[1] * 1e3
        ax.axhline(shaft, color="0.2", lw=2.0)
        seat = st.spring_points.mean(axis=0) * 1e3
        ax.plot(*seat, "o", mfc="none", mec="tab:red", ms=10, mew=1.5)
        edge = pts[np.argmin(pts[:, 1])]
        ax.set_xlim(edge[0] - 1.5, edge[0] + 4.5)
        ax.set_ylim(shaft - 0.5, shaft + 5.5)
        ax.set_aspect("equal")
        ax.set_xlabel("z [mm] (oil side left)")
        ax.set_title(f"× {scale:g}: F = {st.F_N:.1f} N\nb = {st.b * 1e3:.3f} mm, "
                     f"R = {seat[0] - edge[0]:.2f} mm", fontsize=9)
    np.atleast_1d(axes)[0].set_ylabel("radius r [mm]")
    fig.colorbar(coll, ax=axes, shrink=0.8, label="von Mises stress [MPa]")
    fig.suptitle("installed lip (red: spring seat)")
    return fig


if __name__ == "__main__":
    main()
