"""Figure of the O-ring gland design check: the section in its groove with the tolerance
extremes.  Pyplot-free; plotting never changes results."""

from __future__ import annotations

import numpy as np
from matplotlib.patches import Circle, Polygon, Rectangle

from sealsim.plotting import new_figure

__all__ = ["check_label", "plot_gland_section"]

_METAL = {"facecolor": "#c8ccd2", "edgecolor": "#4a4f57", "linewidth": 1.0}

#: where a check is taken when it is not the worst case over all service temperatures
_CHECKED_AT = {"stretch_min": "at assembly"}


def check_label(check: dict) -> str:
    """The name of a check as printed, with where it is taken if that is not the worst case
    of the stack above it (the piston ring's stretch_min: at the assembly temperature,
    unswollen, while the stack's stretch minimum may be that of a warm, loosened ring).

    >>> check_label({"name": "stretch_min"}), check_label({"name": "squeeze_min"})
    ('stretch_min (at assembly)', 'squeeze_min')
    """
    at = _CHECKED_AT.get(check["name"])
    return f"{check['name']} ({at})" if at else check["name"]


def _grooved(ax, corners, label):
    """The grooved metal part as one outline (no edges inside the steel)."""
    ax.add_patch(Polygon(corners, closed=True, label=label, **_METAL))


def plot_gland_section(case, report: dict, title: str = ""):
    """Half-section of the gland at the assembly temperature: metal parts at nominal (the
    middle of each tolerance band), the smallest and largest position of the groove bottom
    and the sealing surface (dashed, dotted), the installed ring at nominal and at its
    smallest and largest cross-section, and the check results.

    Parameters
    ----------
    case : GlandCase
        The checked gland.
    report : dict
        :func:`sealsim.oring_gland`'s result (``report.json``).
    title : str
        Figure title (default: the case title).
    """
    from sealsim.structure.gland_check import geometry_of

    geometry, _, _ = geometry_of(case)
    dims = {k: np.array(v) * 1e3 for k, v in geometry.limits.items()}     # mm: lo, nom, hi
    t_ref = case.service.assembly_temperature
    cords = {}
    for label, index in (("smallest", 0), ("nominal", 1), ("largest", 2)):
        values = {k: v[index] / 1e3 for k, v in dims.items()}
        cords[label] = float(geometry.state(values, t_ref)["cord"]) * 1e3
    fig, (ax, axt) = new_figure(2, 1, width=11.0, height=5.0,
                                gridspec_kw={"width_ratios": [1.25, 1.0]})
    kind = case.housing.type
    if kind == "face":
        gap_at = _face(ax, dims, cords)
    else:
        gap_at = _radial(ax, kind, dims, cords)
    failed = "extrusion_gap" in report["failed"]
    ax.annotate(f"extrusion gap up to {report['extrusion_gap_mm']['max']:.3f} mm\n"
                f"(diametral; limit {report['extrusion']['gap_limit_mm']:.3f} mm)",
                xy=gap_at, xytext=(0.02, 0.03), textcoords="axes fraction", fontsize=8,
                color="#c53030" if failed else "#2d3748",
                arrowprops={"arrowstyle": "->", "color": "#c53030" if failed else "#2d3748"},
                bbox={"boxstyle": "round", "fc": "white", "ec": "none", "alpha": 0.8})
    ax.set_aspect("equal")
    ax.grid(alpha=0.25)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2, fontsize=8,
              frameon=False)
    _summary(axt, report)
    fig.suptitle(title or case.title or f"{kind} gland", fontsize=11)
    return fig


def _ring(ax, centre_of, cords):
    """Installed ring circles: nominal filled, smallest and largest cross-section outlined."""
    styles = {"nominal": {"facecolor": "#2b6cb0", "alpha": 0.55, "edgecolor": "#1a365d"},
              "smallest": {"fill": False, "edgecolor": "#c53030", "linestyle": "--"},
              "largest": {"fill": False, "edgecolor": "#2f855a", "linestyle": ":"}}
    for label, d in cords.items():
        ax.add_patch(Circle(centre_of(d), d / 2, lw=1.4,
                            label=f"ring, {label} section ({d:.3f} mm installed)",
                            **styles[label]))


def _band(ax, horizontal, lo, hi, span, name):
    """The tolerance band of a surface: its smallest (dashed) and largest (dotted) position."""
    for value, style, word in ((lo, "--", "smallest"), (hi, ":", "largest")):
        if horizontal:
            ax.plot(span, [value, value], color="#2d3748", ls=style, lw=1.0,
                    label=f"{name}, {word} ({value:.3f} mm)")
        else:
            ax.plot([value, value], span, color="#2d3748", ls=style, lw=1.0,
                    label=f"{name}, {word} ({value:.3f} mm)")


def _radial(ax, kind, dims, cords):
    b = dims["groove_width"][1]
    z0, z1 = -1.2 * b, 1.2 * b
    if kind == "piston":
        r_groove, r_seal = dims["groove_diameter"] / 2, dims["bore"] / 2
        r_land = dims["piston_diameter"][1] / 2
        base = r_groove[1] - 1.2 * cords["nominal"]
        _grooved(ax, [(z0, base), (z1, base), (z1, r_land), (b / 2, r_land),
                      (b / 2, r_groove[1]), (-b / 2, r_groove[1]), (-b / 2, r_land),
                      (z0, r_land)], "piston")
        top = r_seal[1] + 1.0 * cords["nominal"]
        ax.add_patch(Rectangle((z0, r_seal[1]), z1 - z0, top - r_seal[1], label="cylinder",
                               **{**_METAL, "facecolor": "#e2e8f0"}))
        centre = lambda d: (0.0, r_groove[1] + d / 2)  # noqa: E731
        names = ("groove bottom Ø/2", "bore Ø/2")
        gap_at = (0.8 * z1, 0.5 * (r_land + r_seal[1]))
    else:
        r_groove, r_seal = dims["groove_diameter"] / 2, dims["rod"] / 2
        r_land = dims["bore"][1] / 2
        top = r_groove[1] + 1.2 * cords["nominal"]
        _grooved(ax, [(z0, top), (z1, top), (z1, r_land), (b / 2, r_land),
                      (b / 2, r_groove[1]), (-b / 2, r_groove[1]), (-b / 2, r_land),
                      (z0, r_land)], "housing")
        base = r_seal[1] - 1.0 * cords["nominal"]
        ax.add_patch(Rectangle((z0, base), z1 - z0, r_seal[1] - base, label="rod",
                               **{**_METAL, "facecolor": "#e2e8f0"}))
        centre = lambda d: (0.0, r_seal[1] + d / 2)  # noqa: E731
        names = ("groove bottom Ø/2", "rod Ø/2")
        gap_at = (0.8 * z1, 0.5 * (r_land + r_seal[1]))
    span = [z0, z1]
    _band(ax, True, r_groove[0], r_groove[2], [-b / 2, b / 2], names[0])
    _band(ax, True, r_seal[0], r_seal[2], span, names[1])
    # the groove width's band at the right-hand wall (the left wall held)
    _band(ax, False, -b / 2 + dims["groove_width"][0], -b / 2 + dims["groove_width"][2],
          sorted([r_groove[1], r_seal[1]]), "groove wall z")
    _ring(ax, centre, cords)
    ax.set_xlim(z0, z1)
    ax.set_ylim(min(base, r_seal[0]), max(top, r_seal[2]))
    ax.set_xlabel("axial position z [mm]")
    ax.set_ylabel("radius r [mm]")
    return gap_at


def _face(ax, dims, cords):
    b, h = dims["groove_width"][1], dims["groove_depth"]
    r_in = dims["groove_inner_diameter"] / 2
    gap = dims["gap"][1]
    r0, r1 = r_in[1] - 0.8 * b, r_in[1] + 1.8 * b
    bottom = -1.0 * cords["nominal"]
    # the flange with the groove (below), the cover flange (above, at the groove depth + gap)
    _grooved(ax, [(r0, bottom), (r1, bottom), (r1, h[1]), (r_in[1] + b, h[1]),
                  (r_in[1] + b, 0.0), (r_in[1], 0.0), (r_in[1], h[1]), (r0, h[1])],
             "flange with groove")
    top = h[1] + gap + 1.0 * cords["nominal"]
    ax.add_patch(Rectangle((r0, h[1] + gap), r1 - r0, top - h[1] - gap, label="cover flange",
                           **{**_METAL, "facecolor": "#e2e8f0"}))
    _band(ax, True, h[0], h[2], [r_in[1], r_in[1] + b], "groove depth")
    _band(ax, False, r_in[0], r_in[2], [0.0, h[1]], "groove inner Ø/2")
    d1 = dims["inner_diameter"][1] / 2
    _ring(ax, lambda d: (max(d1, r_in[1]) + d / 2, d / 2), cords)
    ax.set_xlim(r0, r1)
    ax.set_ylim(bottom, top)
    ax.set_xlabel("radius r [mm]")
    ax.set_ylabel("axial position z [mm]")
    return (r_in[1] + b + 0.5 * (r1 - r_in[1] - b), h[1] + 0.5 * gap)


def _summary(ax, report: dict) -> None:
    """Stack and checks as text."""
    ax.axis("off")
    lines = ["worst-case stack       min     nominal   max"]
    for key, label in (("squeeze_percent", "squeeze [%]"), ("stretch_percent", "stretch [%]"),
                       ("gland_fill_percent", "gland fill [%]"),
                       ("extrusion_gap_mm", "extrusion gap [mm]")):
        s = report[key]
        fmt = "{:8.3f}" if key.endswith("_mm") else "{:8.1f}"
        lines.append(f"{label:<20}" + "".join(fmt.format(s[k]) for k in ("min", "nominal",
                                                                          "max")))
    lines.append("")
    lines.append("check                           value         limit")
    for c in report["checks"]:
        sign = ">=" if c["bound"] == "min" else "<="
        mark = "ok  " if c["ok"] else "FAIL"
        lines.append(f"{mark} {check_label(c):<26}{c['value']:7.3g} {c['unit']:<2} {sign}"
                     f"{c['limit']:6.3g} {c['unit']}")
    ax.text(0.0, 1.0, "\n".join(lines), va="top", ha="left", family="monospace", fontsize=9,
            transform=ax.transAxes)
    verdict = "all checks pass" if report["ok"] else "FAILS: " + ", ".join(report["failed"])
    ax.text(0.0, 0.02, verdict, va="bottom", ha="left", fontsize=10, fontweight="bold",
            color="#2f855a" if report["ok"] else "#c53030", transform=ax.transAxes, wrap=True)
