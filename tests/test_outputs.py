"""Outputs are checked before any work: a symbolic link (to an input, to an unrelated file, a loop) is never
written through, a FIFO or a device is never replaced — for ``-o`` and for a campaign store's side files
(``.lock``, ``.journal``), from the command line and from Python. The files the links point to are unchanged."""

import os
from pathlib import Path

import pytest

from boatland.cli import main
from boatland.errors import BoatlandInputError
from boatland.outputs import Output, check_outputs
from boatland.resources import shipped_file

SCENARIO = shipped_file("ctv_landing")


def links(tmp_path):
    """(name, link) for a link to an input, to an unrelated file and in a loop; the unrelated file."""
    other = tmp_path / "notes.txt"
    other.write_text("mine\n")
    (tmp_path / "to_input").symlink_to(SCENARIO)
    (tmp_path / "to_other").symlink_to(other)
    (tmp_path / "loop_a").symlink_to(tmp_path / "loop_b")
    (tmp_path / "loop_b").symlink_to(tmp_path / "loop_a")
    return [tmp_path / n for n in ("to_input", "to_other", "loop_a")], other


def test_a_link_a_fifo_or_a_device_as_output_is_refused(tmp_path):
    made, _ = links(tmp_path)
    for link in made:
        with pytest.raises(BoatlandInputError, match=f"^-o {link}: is a symbolic link"):
            check_outputs([Output("-o", link)], [SCENARIO])
    os.mkfifo(tmp_path / "pipe")
    with pytest.raises(BoatlandInputError, match="is a FIFO \\(named pipe\\), which an output would replace"):
        check_outputs([Output("-o", tmp_path / "pipe")])
    with pytest.raises(BoatlandInputError, match="is a character device, which an output would replace"):
        check_outputs([Output("-o", Path("/dev/null"))])


@pytest.mark.parametrize("side", [".lock", ".journal"])
def test_a_campaign_never_writes_through_a_linked_side_file(tmp_path, side, capsys):
    made, other = links(tmp_path)
    before = SCENARIO.read_bytes()
    for link in made:
        store = tmp_path / f"{link.name}_store.h5"
        Path(str(store) + side).symlink_to(link)
        assert main(["campaign", "demo", "--set", "seeds=1", "-o", str(store)]) == 2
        assert "is a symbolic link" in capsys.readouterr().err
        assert not store.exists()
    assert other.read_text() == "mine\n" and SCENARIO.read_bytes() == before


def test_the_store_itself_refuses_links_below_the_command(tmp_path):
    """The same when a program opens the store directly (the lock and journal opened with O_NOFOLLOW)."""
    from boatland.campaign.store import CampaignStore

    _, other = links(tmp_path)
    (tmp_path / "s.h5.journal").symlink_to(other)
    with pytest.raises(BoatlandInputError, match="is a symbolic link"):
        CampaignStore.open(tmp_path / "s.h5", {"campaign_digest": "x", "n_trials": 1}, ["first slip"])
    assert other.read_text() == "mine\n" and not (tmp_path / "s.h5.lock").exists()
