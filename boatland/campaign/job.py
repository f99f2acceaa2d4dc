"""A campaign from a notebook: ``boatland.campaign("demo", seeds=2)`` runs (or resumes) it as ``boatland campaign``
does and returns its store as an ``xarray.Dataset`` (:func:`campaign`).

The package :mod:`boatland.campaign` is itself callable and calls :func:`campaign`, so that
``boatland.campaign(...)`` works however the package was first imported.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Mapping

from boatland.campaign.plan import load_campaign
from boatland.errors import BoatlandInputError
from boatland.outputs import Output, check_outputs
from boatland.resources import path_or_shipped, shipped_names
from boatland.tomlspec import key_changes

__all__ = ["campaign", "campaign_path"]


def campaign_path(name: str | Path) -> Path:
    """A campaign file: a path, or the name of one shipped in ``scenarios/campaigns/`` (``"demo"``,
    ``"isee_rare"``, ``"table414"``)."""
    found = path_or_shipped(name, "campaign")
    if found is not None:
        return found
    raise BoatlandInputError(f"{name}: no such file, and not a shipped campaign ({', '.join(shipped_names('campaign'))})")


def campaign(source, *, store: str | Path | None = None, changes: Mapping[str, Any] | None = None,
             workers: int | None = None, scheduler: str | None = None, progress=True, **overrides):
    """Run (or resume) a campaign, as ``boatland campaign`` does, and return its store as a Dataset.

    >>> ds = boatland.campaign("demo", seeds=2)                                 # doctest: +SKIP
    >>> ds.P.sel(incident="slip > 0.1 m")                                       # doctest: +SKIP

    Parameters
    ----------
    source : path, str or dict
        A campaign file, the name of a shipped one (:func:`campaign_path`: ``"demo"``, ``"isee_rare"``), or a
        campaign document as a dict (its ``scenario`` a path relative to the working directory or the name of
        a shipped scenario).
    store : path, optional
        The HDF5 store (default ``<campaign name>.h5`` in the working directory, as the command). A store of
        the same campaign is resumed; one of another campaign — or of this one with other inputs or
        changes — is refused, never mixed.
    changes : mapping, optional
        Key path → value, as ``boatland campaign --set`` (:func:`boatland.campaign.plan.change_campaign`):
        ``{"seeds": 2, "access": 600, "set.thrust.force": 100e3, "axes.sea.Hs": [0.5, 1.0]}``.
    workers : int, optional
        Local worker processes (default: all cores).
    scheduler : str, optional
        A Dask scheduler (``tcp://127.0.0.1:8786``) instead of local workers.
    progress : bool or callable
        True: a progress bar on stderr (tqdm); a callable: ``progress(done, total)`` after each trial (ISEE:
        after each sample, with the samples expected so far); False: none.
    **overrides
        More changes: ``seeds=2``, ``access=600``; dots as double underscores (``set__thrust__force=100e3``).

    Returns
    -------
    xarray.Dataset
        :func:`boatland.campaign.dataset.open_store` of the finished store (for ``method = "isee"``: its
        samples, runs and limits).

    Raises
    ------
    boatland.tomlspec.SpecError
        Problems of the campaign, its changes, its base scenario or a case (all at once, with key paths).
    boatland.errors.BoatlandInputError
        The store cannot be written there, would replace an input, or belongs to another campaign.
    """
    from boatland.campaign.dataset import open_store
    from boatland.campaign.isee import run_isee
    from boatland.campaign.runner import run_campaign
    from boatland.checks.files import load, resolve_database

    if isinstance(source, dict):
        doc = dict(source)
        name = str(doc.get("scenario", ""))
        found = path_or_shipped(name) if name else None
        if found is not None:
            doc["scenario"] = str(found)
    else:
        doc = campaign_path(source)
    camp = load_campaign(doc, load_scenario=load, changes=key_changes(changes, overrides))
    path = Path(store) if store is not None else Path(f"{camp.name}.h5")
    check_outputs([Output("store", path), *[Output("store (its side file)", path.with_name(path.name + s))
                                            for s in (".journal", ".lock", ".series")]], camp.input_files())
    run = run_isee if camp.method == "isee" else run_campaign
    with _progress(progress, "sample" if camp.method == "isee" else "trial") as report:
        run(camp, path, loaders=(load, resolve_database), executor="dask" if scheduler else "local",
            workers=workers, scheduler=scheduler, progress=report)
    return open_store(path)


def _progress(progress, unit: str):
    """A context giving the ``progress(done, total)`` callback of :func:`campaign`: a tqdm bar (True), the
    caller's callable, or None (False)."""
    import contextlib

    if callable(progress) or not progress:
        return contextlib.nullcontext(progress if callable(progress) else None)

    @contextlib.contextmanager
    def bar():
        from tqdm.auto import tqdm

        with tqdm(unit=unit, dynamic_ncols=True) as b:
            def report(done, total):
                b.total = max(total, b.total or 0)
                b.n = done
                b.refresh()
            yield report
    return bar()
