"""The house rules a newcomer relies on, held by walking the package's source (every import statement,
function-level ones included):

- no import cycle between modules (a package's ``__init__`` counts as a module);
- no module imports a private name (``_x``) of another module;
- no folder of ``boatland/`` holds more than 15 % of the package's lines (one concept per room, not a
  category that gathers a quarter of the code).

The layer order between the packages is import-linter's contract (``pyproject.toml``, ``lint-imports``).
"""

from __future__ import annotations

import ast
from collections import defaultdict
from pathlib import Path

import boatland

PACKAGE = Path(boatland.__file__).resolve().parent
MAX_FOLDER_SHARE = 0.15


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


def _modules() -> dict[str, Path]:
    return {_module_name(p): p for p in PACKAGE.rglob("*.py")}


def _imports(name: str, path: Path, modules: dict[str, Path]):
    """(target module, imported name or None) of every boatland import in the module, anywhere in it."""
    is_package = path.name == "__init__.py"
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.split(".")[0] == "boatland":
                    yield alias.name, None
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = name.split(".") if is_package else name.split(".")[:-1]
                base = base[:len(base) - (node.level - 1)]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            if target.split(".")[0] != "boatland":
                continue
            for alias in node.names:
                sub = f"{target}.{alias.name}"
                yield (sub, None) if sub in modules else (target, alias.name)


def _graph():
    modules = _modules()
    edges: dict[str, set[str]] = defaultdict(set)
    private = []
    for name, path in modules.items():
        for target, imported in _imports(name, path, modules):
            if target in modules and target != name:
                edges[name].add(target)
            if imported is not None and imported.startswith("_") and not imported.startswith("__") \
                    and target != name:
                private.append(f"{name} imports {target}.{imported}")
    return modules, edges, private


def _cycles(nodes, edges) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    out = []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(nodes):
        if v not in index:
            visit(v)
    return out


def test_the_walk_sees_the_imports_it_must():
    """The walk is not vacuous: it finds module-level, function-level and package imports."""
    modules, edges, _ = _graph()
    assert len(modules) > 100
    assert "boatland.vessel.database" in edges["boatland.landing.contacts"]             # module level
    assert "boatland.checks.memory" in edges["boatland.campaign.runner"]                # inside a function
    assert "boatland.hydro.read" in edges["boatland.hydro"]                              # a package's __init__


def test_no_import_cycle_between_modules():
    modules, edges, _ = _graph()
    assert _cycles(modules, edges) == []


def test_the_cycle_finder_finds_a_cycle():
    assert _cycles(["a", "b", "c"], {"a": {"b"}, "b": {"c"}, "c": {"a"}}) == [["a", "b", "c"]]
    assert _cycles(["a", "b"], {"a": {"b"}}) == []


def test_no_module_imports_a_private_name_of_another():
    _, _, private = _graph()
    assert private == []


def test_no_folder_holds_more_than_its_share_of_the_lines():
    lines = {p: len(p.read_text(encoding="utf-8").splitlines()) for p in PACKAGE.rglob("*.py")}
    total = sum(lines.values())
    folders: dict[str, int] = defaultdict(int)
    for p, n in lines.items():
        rel = p.relative_to(PACKAGE)
        if len(rel.parts) > 1:
            folders[rel.parts[0]] += n
    assert len(folders) >= 10
    too_big = {f: f"{n / total:.1%}" for f, n in folders.items() if n > MAX_FOLDER_SHARE * total}
    assert too_big == {}
