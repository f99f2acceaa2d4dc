"""A small Monte Carlo campaign of the default landing, run in this process: the stores the report tests read
(fixtures ``small_store`` in tests/conftest.py and ``active_store`` in tests/campaign/test_html.py)."""

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
