"""The scenario file format, by stage: :mod:`~boatland.scenario.schema` (keys, types, defaults, the JSON
Schema) → :mod:`~boatland.scenario.build` (the section builders: cross-field rules, problems with key
paths) → :mod:`~boatland.scenario.parts` (the frozen records) → :mod:`~boatland.scenario.scenario` (the
:class:`Scenario` and its loader, :func:`load_scenario`).

Nothing here reads a hydrodynamic database: the scenario on its vessel is :mod:`boatland.landing`, the
checks against the database :mod:`boatland.checks`.
"""
