"""Write ``scenarios/example_hindcast.csv``: a SYNTHETIC, ILLUSTRATIVE year of 3-hourly sea states with wind-sea
and swell partitions, for ``boatland operability`` (not measured data; replace with a hindcast such as NORA10 —
Grøtting 2015 §4.1 used it for Dogger Bank — or ERA5 for real studies).

The model (seeded, numpy's PCG64; ``python docs/make_example_hindcast.py`` rewrites the file byte for byte):

- wind speed at 10 m: a seasonal mean 6 m/s (July) – 10 m/s (January), times a log-normal AR(1) anomaly
  (σ_ln 0.35, correlation time 18 h), capped at :data:`U_CAP` (an assumption: the log-normal's tail alone
  reached 39 m/s and a fetch-limited Hs of 24 m, far beyond southern North Sea storms); the wind comes from a
  direction that wanders (AR(1), σ 50°, 30 h) about the south-west (225°), the prevailing wind of the southern
  North Sea;
- wind sea: Hs = 0.016 U² (fetch-limited, about 60 % of the fully developed 0.021 U² — Pierson–Moskowitz),
  Tp = 1.5 + 3.2 √Hs s, from the wind's direction;
- swell from the northern North Sea / Atlantic (from 330° ± 20°): Hs log-normal about a seasonal 0.25 (July) –
  0.55 m (January), AR(1) over 36 h; Tp 8–12 s;
- the total sea: Hs = √(Hs_w² + Hs_s²); Tp and direction those of the part with more energy (peak values);
- with ``tide=True`` (the benchmark's variant; the shipped file has none): an M2 tidal current, 1.2 m/s at its
  peaks (12.42 h period), the flood coming from 45°, the ebb from 225°;
- with ``wind=True`` (the benchmark's variant; the shipped file has none): the model's wind itself, its speed at
  10 m (to 0.1 m/s) and the direction it comes from.

Rounded as hindcasts give them: Hs to 1 cm, Tp to 0.1 s, directions to 1°.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

OUT = Path(__file__).resolve().parents[1] / "scenarios" / "example_hindcast.csv"
SEED = 2026
STEP_H = 3
#: The model wind's cap [m/s] at 10 m (Beaufort 9, a severe gale): its wind sea then stays below 0.016 U² = 7.7 m.
U_CAP = 22.0


def ar1(rng, n: int, tau_h: float, sigma: float, step_h: float = STEP_H) -> np.ndarray:
    """A stationary AR(1) series of standard deviation ``sigma`` and correlation time ``tau_h`` at steps of
    ``step_h`` hours."""
    a = np.exp(-step_h / tau_h)
    e = rng.standard_normal(n) * sigma * np.sqrt(1 - a * a)
    x = np.empty(n)
    x[0] = rng.standard_normal() * sigma
    for i in range(1, n):
        x[i] = a * x[i - 1] + e[i]
    return x


def make(step_h: int = STEP_H, tide: bool = False, wind: bool = False) -> str:
    """The file's text (``step_h``: the step in hours; the shipped file is 3-hourly, the benchmark makes an
    hourly year with the same model; ``tide``, ``wind``: add the tidal current's, the wind's columns)."""
    rng = np.random.default_rng(SEED)
    t = np.arange(np.datetime64("2021-01-01T00:00"), np.datetime64("2022-01-01T00:00"),
                  np.timedelta64(step_h, "h"))
    n = t.size
    day = (t - t[0]).astype("timedelta64[h]").astype(float) / 24.0
    winter = 0.5 * (1 + np.cos(2 * np.pi * (day - 15) / 365.25))         # 1 mid-January, 0 mid-July
    U = np.minimum((6.0 + 4.0 * winter) * np.exp(ar1(rng, n, 18.0, 0.35, step_h) - 0.5 * 0.35 ** 2), U_CAP)
    wind_from = np.mod(225.0 + ar1(rng, n, 30.0, 50.0, step_h), 360.0)
    hw = 0.016 * U ** 2
    tw = 1.5 + 3.2 * np.sqrt(hw)
    hs_ = (0.25 + 0.30 * winter) * np.exp(ar1(rng, n, 36.0, 0.4, step_h) - 0.5 * 0.4 ** 2)
    ts = 10.0 + ar1(rng, n, 48.0, 1.0, step_h).clip(-2.0, 2.0)
    swell_from = np.mod(330.0 + ar1(rng, n, 48.0, 20.0, step_h), 360.0)
    hw, tw, hs_, ts = np.round(hw, 2).clip(0.01), np.round(tw, 1), np.round(hs_, 2).clip(0.01), np.round(ts, 1)
    wind_from, swell_from = np.round(wind_from) % 360, np.round(swell_from) % 360
    H = np.round(np.hypot(hw, hs_), 2)
    wind_dominant = hw >= hs_
    T = np.where(wind_dominant, tw, ts)
    D = np.where(wind_dominant, wind_from, swell_from)
    lines = [
        f"# example_hindcast — SYNTHETIC, ILLUSTRATIVE year of {step_h}-hourly sea states for `boatland operability`",
        "# (not measured data). Made by docs/make_example_hindcast.py (seed 2026), whose docstring gives the model:",
        "# wind sea from a south-westerly wind that wanders, swell from the north-north-west, stormier in winter.",
        "# Replace with a hindcast (NORA10, as Grøtting 2015 §4.1 used for Dogger Bank; ERA5) for real studies.",
        f"# Columns: time (UTC, start of the {step_h} h), Hs [m], Tp [s], direction_from_deg = compass degrees from true",
        "# North the waves come FROM (total sea: the dominant part's peak), then the wind-sea and swell partitions.",
        "# On a landing at bearing 180° (the tower's south side; the vessel heads North): waves from 0° are head",
        "# seas, from 90° beam (from starboard), from 180° following, from 270° beam (from port).",
        "time,Hs,Tp,direction_from_deg,wind_sea_Hs,wind_sea_Tp,wind_sea_direction_from_deg,swell_Hs,swell_Tp,"
        "swell_direction_from_deg",
    ]
    if tide:
        phase = np.sin(2 * np.pi * (day * 24.0) / 12.42)
        speed, cur_from = np.round(1.2 * np.abs(phase), 2), np.where(phase >= 0, 45, 225)
        lines[-1] += ",current_speed,current_direction_from_deg"
    if wind:
        lines[-1] += ",wind_speed,wind_direction_from_deg"
    for i in range(n):
        lines.append(f"{str(t[i])[:16]},{H[i]:.2f},{T[i]:.1f},{D[i]:.0f},{hw[i]:.2f},{tw[i]:.1f},{wind_from[i]:.0f},"
                     f"{hs_[i]:.2f},{ts[i]:.1f},{swell_from[i]:.0f}" + (f",{speed[i]:.2f},{cur_from[i]}" if tide else "")
                     + (f",{U[i]:.1f},{wind_from[i]:.0f}" if wind else ""))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    OUT.write_text(make(), encoding="utf-8")
    print(f"wrote {OUT}")
