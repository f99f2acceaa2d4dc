"""Small campaigns the tests run: a Monte Carlo campaign of the default landing, run in this process (the stores
the report tests read: fixtures ``small_store`` in tests/conftest.py and ``active_store`` in
tests/campaign/test_html.py), and the file of a short rare-event campaign of ctv24 (tests/campaign/test_isee.py,
tests/site/test_limits_table.py)."""

from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


def run_small_campaign(folder: Path, name: str, hs, directions) -> tuple[Path, Path, dict]:
    """A finished Monte Carlo store of the default landing over ``hs`` × ``directions`` (relative, deg): 3 seeds,
    6 s of full waves each, state-space radiation, slips over 0.1 m counted, run in this process;
    ``(campaign file, store, JSON the campaign printed)``."""
    import contextlib
    import io
    import json

    from boatland.cli import main

    camp = folder / f"{name.split()[0]}.toml"
    camp.write_text(f"""
name = "{name}"
scenario = "{REPO / 'scenarios' / 'ctv_landing.toml'}"
seeds = 3
master_seed = 5
access = 6.0
[set]
"radiation.method" = "state_space"
[axes]
"sea.Hs" = {list(map(float, hs))}
"sea.relative_direction_deg" = {list(map(float, directions))}
[incidents]
slip_distance = [0.1]
""")
    store = camp.with_suffix(".h5")
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        status = main(["campaign", str(camp), "-o", str(store), "--workers", "1", "--json"])
    assert status == 0
    return camp, store, json.loads(out.getvalue())


def isee_file(folder: Path, name: str = "isee", extra: str = "",
              axes: str = '"sea.relative_direction_deg" = [180.0, 90.0]', seed: int = 17) -> Path:
    """A rare-event campaign file of ctv24 (scenarios/ctv24_landing.toml) with a 20-s access, an accepted
    P = 0.05 and few samples (seconds to run): ``axes`` and ``extra`` (more [isee] keys) as TOML text."""
    path = folder / f"{name}.toml"
    path.write_text(f"""
name = "{name}"
scenario = "{REPO / 'scenarios' / 'ctv24_landing.toml'}"
method = "isee"
master_seed = {seed}
access = 20.0
[axes]
{axes}
[isee]
target_cov = 0.3
batch = 6
min_samples = 12
max_samples = 30
settle = 10.0
accept = 0.05
levels = 3
limit_width = 0.02
{extra}
""")
    return path
