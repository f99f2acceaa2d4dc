"""The reference data in tests/data/refdata are the published files, all of them listed and attributed."""

from __future__ import annotations

import hashlib

NOT_DATA = {"README.md", "SHA256SUMS", ".gitattributes", "LICENSE.WEC-Sim", "COPYRIGHT.WEC-Sim",
            "LICENSE.HydroChrono", "LICENSE.MSS"}


def listed(refdata):
    """``SHA256SUMS`` as {relative path: hex digest} (``sha256sum -c SHA256SUMS`` reads the same file)."""
    rows = (line.split(maxsplit=1) for line in (refdata / "SHA256SUMS").read_text().splitlines() if line)
    return {name.strip(): digest for digest, name in rows}


def test_every_data_file_is_listed_and_nothing_else(refdata):
    on_disk = {p.relative_to(refdata).as_posix() for p in refdata.rglob("*")
               if p.is_file() and p.name not in NOT_DATA and "__pycache__" not in p.parts}
    assert on_disk == set(listed(refdata))
    assert len(on_disk) == 20


def test_files_are_unchanged(refdata):
    """An edited file, or a text file whose line ends git converted, no longer matches its digest."""
    changed = [name for name, digest in listed(refdata).items()
               if hashlib.sha256((refdata / name).read_bytes()).hexdigest() != digest]
    assert changed == []


def test_readme_names_every_folder_and_licence(refdata):
    readme = (refdata / "README.md").read_text()
    for folder in {name.split("/")[0] for name in listed(refdata)}:
        assert f"`{folder}" in readme, folder
    for notice in ("LICENSE.WEC-Sim", "COPYRIGHT.WEC-Sim", "LICENSE.HydroChrono", "LICENSE.MSS"):
        assert (refdata / notice).is_file() and notice in readme
