"""What every boatland figure shares: the Agg backend (files only), one polar orientation for wave
directions, saving.

Polar orientation (the same in ``boatland screen -o`` and the campaign report): the vessel seen from
above with its **bow up**; an angle is the relative wave direction (where the waves travel towards,
DESIGN.md §2) drawn **where the waves come from** — 180° (head seas) at the top, 0° (following seas)
at the bottom, 90° (waves travelling towards port, coming from starboard) on the right, 270° on the
left.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from boatland.atomic import atomic_path

__all__ = ["pyplot", "heading_polar", "save_figure", "POLAR_NOTE"]

#: One line for titles or captions of polar figures.
POLAR_NOTE = "bow up: 180° = head seas at the top, 90° = waves from starboard on the right"


def pyplot():
    """``matplotlib.pyplot`` on the Agg backend (no display needed)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def heading_polar(ax, *, rlabel: str | None = None) -> None:
    """Orient a polar axes for relative wave directions (module docstring) and label its angles.

    Parameters
    ----------
    ax : matplotlib PolarAxes
    rlabel : str, optional
        Name and unit of the radius (e.g. "Tp [s]"), written beside the radial tick labels.
    """
    ax.set_theta_zero_location("S")        # 0° following seas at the bottom
    ax.set_theta_direction(1)              # counterclockwise: 90° on the right, 180° at the top
    angles = np.arange(0, 360, 45)
    names = {0: "0°\nfollowing", 90: "90°\nbeam, from stbd", 180: "180° head seas", 270: "270°\nbeam, from port"}
    ax.set_xticks(np.radians(angles))
    ax.set_xticklabels([names.get(int(a), f"{a:g}°") for a in angles], fontsize=8)
    ax.set_rlabel_position(157.5)          # radial labels between 135° and 180°, clear of the data's usual spokes
    ax.tick_params(axis="y", labelsize=7)
    if rlabel:
        ax.text(np.radians(157.5), ax.get_rmax() * 1.12, rlabel, fontsize=8, ha="center", va="center")


def figure_title(fig) -> str:
    """The title a reader sees: the figure's suptitle, else the first axes' title ("" if none)."""
    sup = getattr(fig, "_suptitle", None)
    if sup is not None and sup.get_text():
        return sup.get_text()
    return next((ax.get_title() for ax in fig.axes if ax.get_title()), "")


def save_figure(fig, path: str | Path, *, dpi: int = 110) -> Path:
    """Save ``fig`` to ``path`` (format from the suffix) and close it. A PNG carries its title in its
    ``Title`` text chunk (:func:`figure_title`; what ``docs/make_figures.py``'s test reads back) and
    ``Software`` = boatland and its version."""
    from boatland import __version__

    plt = pyplot()
    path = Path(path)
    meta = {"Title": figure_title(fig), "Software": f"boatland {__version__}"} if path.suffix.lower() == ".png" else None
    try:
        with atomic_path(path) as tmp:      # nothing half-written; a full disk names the figure
            fig.savefig(tmp, dpi=dpi, metadata=meta, format=path.suffix[1:].lower() or None)
    finally:
        plt.close(fig)
    return path
