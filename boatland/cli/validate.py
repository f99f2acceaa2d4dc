"""``boatland validate``: run the validation cases and write the report (Markdown + figures)."""

from __future__ import annotations

import json
import sys
import tempfile
import time
from pathlib import Path

from boatland.cli.guard import integer
from boatland.outputs import Output, check_outputs
from boatland.errors import BoatlandInputError
from boatland.reproducible import pinned

__all__ = ["add_parser", "cmd", "default_refdata"]


def default_refdata() -> Path:
    """The checkout's reference data folder, ``tests/data/refdata`` beside the package (not in a wheel)."""
    return Path(__file__).resolve().parents[2] / "tests" / "data" / "refdata"


def add_parser(sub) -> None:
    v = sub.add_parser(
        "validate", help="run the validation cases and write a report (Markdown + figures)",
        description="Run boatland's validation cases — Hulme's hemisphere, three BEM codes, the sphere's IRF, "
                    "time domain vs frequency domain, state space vs convolution, the contact in closed form, "
                    "the stuck fender vs the frequency-domain hinge, Ferreira González's (2023) tank runs, "
                    "Grøtting's (2015) trends, the screening vs Monte Carlo — and write DIR/README.md with a "
                    "summary table (case, reference, error, tolerance, PASS/MISS), a section and a figure per "
                    "case, the date, version, commit, machine and wall times. A case that misses its tolerance "
                    "is reported as MISS, never dropped. Exit status: 0 every case passed; 1 a case is MISS or "
                    "ERROR (the report is written in full first); 2 a usage error.")
    v.add_argument("--quick", action="store_true",
                   help="cheaper settings (fewer seeds, periods and sea states; a few minutes): what CI runs")
    v.add_argument("-o", "--output", type=Path, default=Path("docs/validation"), metavar="DIR",
                   help="report folder (default docs/validation): README.md and the PNG figures")
    v.add_argument("--case", action="append", metavar="NAME",
                   help="run only this case (repeatable; --list names them)")
    v.add_argument("--refdata", type=Path, metavar="DIR",
                   help="the public reference data folder (default: the checkout's tests/data/refdata)")
    v.add_argument("--workers", type=integer(1, 256), default=2, metavar="N",
                   help="local worker processes of the Monte Carlo cases (default 2)")
    v.add_argument("--list", action="store_true", help="list the cases and exit")
    v.add_argument("--json", action="store_true", help="print the results as JSON (progress goes to stderr)")
    v.set_defaults(func=cmd)


def _select(names: list[str] | None):
    from boatland.validation import all_cases

    cases = all_cases()
    if not names:
        return cases
    known = {c.name: c for c in cases}
    unknown = [n for n in names if n not in known]
    if unknown:
        raise BoatlandInputError(f"--case {unknown[0]}: no such case; use one of {', '.join(known)}")
    return [c for c in cases if c.name in set(names)]


def _refdata(args, cases) -> Path | None:
    need = [(c, f) for c in cases for f in c.refdata_files]
    if not need:
        return None
    folder = args.refdata if args.refdata is not None else default_refdata()
    flag = "--refdata" if args.refdata is not None else "reference data"
    if not folder.is_dir():
        if args.refdata is None:
            raise BoatlandInputError(
                f"reference data: {folder} not found (the reference data are in a boatland checkout, not in "
                "the installed package); give --refdata DIR (a checkout's tests/data/refdata), or --case for "
                "cases that need none")
        raise BoatlandInputError(f"--refdata {folder}: not a folder; give a checkout's tests/data/refdata")
    for case, f in need:
        if not (folder / f).is_file():
            raise BoatlandInputError(f"{flag} {folder}: {f} is missing (case {case.name}); give a checkout's "
                                     "tests/data/refdata")
    return folder


def _scenarios(cases) -> Path:
    files = {f for c in cases for f in c.scenario_files}
    if not files:
        return Path(".")
    from boatland.checks.files import default_scenario_path

    folder = default_scenario_path().parent          # one line if the checkout's scenarios are not there
    missing = sorted(f for f in files if not (folder / f).is_file())
    if missing:
        raise BoatlandInputError(f"scenarios: {folder / missing[0]} not found; validate runs from a boatland "
                                 "checkout (its scenarios/ folder)")
    return folder


@pinned
def cmd(args) -> int:
    from boatland.validation import PASS, Context, run_case
    from boatland.validation.report import machine, write_report

    cases = _select(args.case)
    if args.list:
        for c in cases:
            print(f"{c.name:28s} {c.title}")
        return 0
    refdata = _refdata(args, cases)
    scenarios = _scenarios(cases)
    out = args.output
    inputs = [p for p in (refdata,) if p is not None]
    check_outputs([Output("-o", out, "folder", ("README.md",))], inputs)
    for i in inputs:
        if out.resolve().is_relative_to(i.resolve()):
            raise BoatlandInputError(f"-o {out}: inside the reference data folder {i}; give a folder outside it")
    out.mkdir(parents=True, exist_ok=True)
    say = (lambda m: print(m, file=sys.stderr, flush=True)) if args.json else (lambda m: print(m, flush=True))
    meta = machine()
    results = []
    from boatland.cli.common import compile_notice

    compile_notice()             # the first validation on a machine compiles the kernels inside its first trials
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="boatland-validate-") as work:
        for k, case in enumerate(cases, 1):
            say(f"[{k}/{len(cases)}] {case.name}: {case.title}")
            ctx = Context(quick=args.quick, refdata=refdata, scenarios=scenarios, out=out,
                          work=Path(work) / case.name, workers=args.workers, progress=say)
            ctx.work.mkdir()
            r = run_case(case, ctx)
            results.append(r)
            say(f"    {r.verdict} in {r.seconds:.1f} s: {r.outcome.headline if r.outcome else r.error}")
    total = time.perf_counter() - t0
    path = write_report(results, out, meta, quick=args.quick, total_seconds=total)
    ok = all(r.verdict == PASS for r in results)
    if args.json:
        print(json.dumps({"report": str(path), "quick": args.quick, "machine": meta, "wall_time_s": round(total, 1),
                          "passed": ok, "cases": [r.to_dict() for r in results]}, indent=2, ensure_ascii=False))
    else:
        print(f"\n{'case':28s} {'verdict':8s} {'wall':>8s}  error")
        for r in results:
            print(f"{r.case.name:28s} {r.verdict:8s} {r.seconds:7.1f}s  {r.outcome.headline if r.outcome else r.error}")
        print(f"report: {path} ({total:.0f} s)")
    return 0 if ok else 1
