"""boatland — will the crew transfer vessel's fender hold on the boat landing, and if it slips, when
and how far?

In a notebook::

    import boatland
    r = boatland.simulate("ctv_landing", **{"sea.Hs": 1.0, "simulation.duration": 300})
    print(r.verdict().text())            # HELD … / SLIPPED at t = … s, slid … m — the inputs
    ds = r.to_xarray()                   # time × dof / contact, units, inputs as attributes
    store = boatland.open_store("demo.h5", grid=True)    # a campaign: P over Hs × heading

Exported (imported on first use, so ``import boatland`` stays light): :func:`simulate`,
:func:`load_scenario` (:mod:`boatland.api`), :func:`open_store` (:mod:`boatland.campaign.dataset`),
:class:`Result` (:mod:`boatland.trial.result`), :func:`load_builtin` (the built-in vessel databases).

Layers (each imports only from those below it; checked by import-linter in CI):

1. kernels: :mod:`boatland.irf`, :mod:`boatland.contact`, :mod:`boatland.integrate`, :mod:`boatland.waves`
2. model: :mod:`boatland.model` (validated, immutable data: hydrodynamic database, vessel, ...)
3. services: one trial (:mod:`boatland.trial`), frequency domain (:mod:`boatland.freqdomain`),
   campaigns (:mod:`boatland.campaign`)
4. edges: :mod:`boatland.hydro` (BEM readers / writers / builder), :mod:`boatland.record`,
   :mod:`boatland.api` (the notebook API), :mod:`boatland.cli`
"""

__version__ = "0.1.0"

__all__ = ["simulate", "load_scenario", "open_store", "Result", "load_builtin", "__version__"]

_EXPORTS = {
    "simulate": ("boatland.api", "simulate"),
    "load_scenario": ("boatland.api", "load_scenario"),
    "open_store": ("boatland.campaign.dataset", "open_store"),
    "Result": ("boatland.trial.result", "Result"),
    "load_builtin": ("boatland.hydro.builtin", "load_builtin"),
}


def __getattr__(name: str):
    if name in _EXPORTS:
        import importlib

        module, attr = _EXPORTS[name]
        value = getattr(importlib.import_module(module), attr)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'boatland' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(_EXPORTS))
