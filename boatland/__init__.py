"""boatland — will the crew transfer vessel's fender hold on the boat landing, and if it slips, when
and how far?

In a notebook::

    import boatland
    r = boatland.simulate("ctv_landing", **{"sea.Hs": 1.0, "simulation.duration": 300})
    print(r.verdict().text())            # HELD … / SLIPPED at t = … s, slid … m — the inputs
    ds = r.to_xarray()                   # time × dof / contact, units, inputs as attributes
    ds = boatland.campaign("demo", seeds=2)              # a campaign, run (or resumed) into demo.h5
    store = boatland.open_store("demo.h5", grid=True)    # its store: P over Hs × heading
    op = boatland.operability("ctv_landing", "hindcast.csv", landings=[45, 165, 285])   # a site's year

Exported (imported on first use, so ``import boatland`` stays light): :func:`simulate`,
:func:`load_scenario` (:mod:`boatland.api`), :func:`campaign` (:mod:`boatland.campaign.job`; the package
:mod:`boatland.campaign` is callable as it), :func:`open_store` (:mod:`boatland.campaign.dataset`),
:func:`operability` (:mod:`boatland.api`, over :mod:`boatland.site`), :class:`Result`
(:mod:`boatland.trial.result`), :func:`load_builtin` (the built-in vessel databases).

Rooms, in layers (each imports only from those below it; checked by import-linter in CI and by
``tests/test_architecture.py``):

1. kernels — plain numba functions on arrays: :mod:`boatland.irf` (radiation IRFs, state-space fit),
   :mod:`boatland.contact` (the fender), :mod:`boatland.waves` (spectra, synthesis, diffraction),
   :mod:`boatland.integrate` (the RK4 Cummins stepper; its tableau :mod:`boatland.rk4`);
2. the middle floor — validated, immutable data named after what it holds: :mod:`boatland.vessel` (the
   hydrodynamic database, its directions and radiation memory, vessel files, hull lines),
   :mod:`boatland.hydro` (BEM readers, the BEMIO writer, the Capytaine builder, the built-in vessels),
   :mod:`boatland.sea` (spectral parts, sea states, the pile's scattered wave), :mod:`boatland.scenario`
   (the file format), :mod:`boatland.landing` (the scenario on its vessel: one :class:`Setup`),
   :mod:`boatland.checks` (everything that refuses or warns before a run);
3. services: one trial (:mod:`boatland.trial`; its incident definitions :mod:`boatland.trial.incidents`),
   frequency domain (:mod:`boatland.freqdomain`), campaigns (:mod:`boatland.campaign`); above them the
   planner's site (:mod:`boatland.site`: the compass, a site's weather, operability at its landings);
4. edges: :mod:`boatland.record` (MCAP, Rerun, replay, figures), :mod:`boatland.api` (the notebook API),
   :mod:`boatland.validation`, :mod:`boatland.cli`.

``boatland.model`` (the names of the middle floor before the redesign) still imports, with a deprecation
warning, for one release.
"""

__version__ = "0.1.0"

__all__ = ["simulate", "load_scenario", "campaign", "open_store", "operability", "Result", "load_builtin",
           "__version__"]

_EXPORTS = {
    "simulate": ("boatland.api", "simulate"),
    "load_scenario": ("boatland.api", "load_scenario"),
    "campaign": ("boatland.campaign", None),     # the package, callable: boatland.campaign("demo", seeds=2)
    "open_store": ("boatland.campaign.dataset", "open_store"),
    "operability": ("boatland.api", "operability"),
    "Result": ("boatland.trial.result", "Result"),
    "load_builtin": ("boatland.hydro.builtin", "load_builtin"),
}


def __getattr__(name: str):
    if name in _EXPORTS:
        import importlib

        module, attr = _EXPORTS[name]
        value = importlib.import_module(module) if attr is None else getattr(importlib.import_module(module), attr)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'boatland' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(_EXPORTS))
