"""Measured wave records (Ferreira González 2023 §5.2.3): CSV reading, FFT components, exact replay, bad files."""

import math

import numpy as np
import pytest

from boatland.errors import BoatlandInputError
from boatland.sea.spectra import SpectrumPart
from boatland.sea.states import MeasuredRecord, SeaState
from boatland.sea.records import read_elevation_csv
from boatland.waves.measured import record_components
from boatland.waves.realisation import Components
from boatland.waves.synthesis import elevation, elevation_series


def write_csv(path, t, eta, header="time [s],elevation [m]", sep=",", fmt="%.17g"):
    lines = ([header] if header else []) + [f"{fmt % a}{sep}{fmt % b}" for a, b in zip(t, eta)]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


@pytest.fixture
def record():
    """A 20-minute record of a JONSWAP sea (Hs 0.9 m, Tp 6 s) at a gauge, sampled at 10 Hz."""
    sea = SeaState(parts=SpectrumPart(Hs=0.9, Tp=6.0, direction_deg=30.0))
    c = sea.realise(11, 1200.0)
    dt, n = 0.1, 12_000
    return dt * np.arange(n) + 5.0, elevation_series(c, 12.0, -7.0, 0.0, dt, n) + 0.01


def test_replay_with_all_components_reproduces_the_record(tmp_path, record):
    t, eta = record
    path = write_csv(tmp_path / "gauge.csv", t, eta)
    rec = MeasuredRecord.from_csv(path, gauge_x=12.0, gauge_y=-7.0, direction_deg=30.0, remove_mean=False)
    assert rec.dt == pytest.approx(0.1, rel=1e-12) and rec.length == pytest.approx(1200.0, rel=1e-12)
    c = rec.realise()
    assert c.size == t.size // 2 + 1  # every rfft bin, the mean included
    replay = elevation_series(c, 12.0, -7.0, 0.0, rec.dt, t.size)  # simulation t = 0 at the first sample
    err = np.max(np.abs(replay - eta)) / np.max(np.abs(eta))
    assert err < 1e-6, err  # issue: 1e-6 relative; in practice ~1e-13
    assert err < 1e-11
    idx = np.arange(0, t.size, 331)  # direct cosine evaluation agrees too
    assert np.max(np.abs(elevation(c, 12.0, -7.0, idx * rec.dt)[:, 0] - eta[idx])) < 1e-9 * np.max(np.abs(eta))
    # default: the mean (a water level, not a wave) is dropped
    c0 = MeasuredRecord.from_csv(path, gauge_x=12.0, gauge_y=-7.0, direction_deg=30.0).realise()
    replay0 = elevation_series(c0, 12.0, -7.0, 0.0, rec.dt, t.size)
    assert np.max(np.abs(replay0 - (eta - eta.mean()))) < 1e-11 * np.max(np.abs(eta))


def test_rounded_whitespace_file_without_header_replays_its_own_numbers(tmp_path, record):
    t, eta = record
    path = write_csv(tmp_path / "gauge.txt", t, eta, header=None, sep="  ", fmt="%.5f")
    tt, ee = read_elevation_csv(path)
    assert np.array_equal(ee, np.round(eta, 5))
    rec = MeasuredRecord.from_csv(path, remove_mean=False)
    replay = elevation_series(rec.realise(), 0.0, 0.0, 0.0, rec.dt, t.size)
    assert np.max(np.abs(replay - ee)) < 1e-6 * np.max(np.abs(ee))


def test_keeping_the_largest_components_loses_exactly_the_dropped_variance(record):
    t, eta = record
    eta = eta - eta.mean()
    full = record_components(eta, 0.1)
    top = record_components(eta, 0.1, n_keep=20)
    assert top.size == 20 and np.all(np.diff(top.a) <= 0) and np.array_equal(top.a, full.a[:20])
    resid = eta - elevation_series(top, 0.0, 0.0, 0.0, 0.1, t.size)
    dropped = 0.5 * np.sum(full.a[20:] ** 2)
    assert np.mean(resid ** 2) == pytest.approx(dropped, rel=1e-6)  # Parseval (Nyquist term ≈ 0 here)


def test_record_moved_from_the_gauge_to_the_vessel():
    """A periodic long-crested sea on the FFT frequencies: the replay is exact at any other point."""
    rng = np.random.default_rng(5)
    M, dt, theta = 2048, 0.25, math.radians(200.0)
    m = np.arange(40, 400)
    w = 2 * math.pi * m / (M * dt)
    k = w ** 2 / 9.81
    truth = Components(w, k, rng.rayleigh(0.02, m.size), np.full(m.size, theta), rng.uniform(0, 2 * math.pi, m.size))
    xg, yg = 30.0, 12.0
    eta = elevation_series(truth, xg, yg, 0.0, dt, M)
    rec = MeasuredRecord(eta=eta, dt=dt, gauge_x=xg, gauge_y=yg, direction_deg=200.0)
    c = rec.realise()
    t = np.linspace(0.0, 100.0, 57)
    for x, y in ((0.0, 0.0), (-25.0, 40.0)):
        assert np.max(np.abs(elevation(c, x, y, t) - elevation(truth, x, y, t))) < 1e-12


def test_duration_longer_than_the_record_warns(record):
    t, eta = record
    rec = MeasuredRecord(eta=eta, dt=0.1)
    with pytest.warns(UserWarning, match="longer than the record"):
        rec.realise(duration=2000.0)


# ---------------------------------------------------------------------- bad files
def lines_file(tmp_path, text, name="bad.csv"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


GOOD = ["t,eta"] + [f"{0.1 * i:.1f},{math.sin(i):.4f}" for i in range(10)]


@pytest.mark.parametrize("edit, match", [
    (lambda L: L[:5] + L[6:], r"line 6: gap of 0\.2 s between t = 0\.3 s and 0\.5 s \(about 1 missing sample"),
    (lambda L: L[:4] + ["0.31,0.2"] + L[5:], r"line 5: time step 0\.11 s differs .* uniform within 1 %"),
    (lambda L: L[:3] + ["0.2,nan"] + L[4:], r"line 4: elevation is nan; every sample must be a finite number"),
    (lambda L: L[:3] + ["0.2,"] + L[4:], r"line 4: 1 column\(s\); expected at least 2"),
    (lambda L: L[:7] + ["time,eta"] + L[7:], r"line 8: 'time,eta' is not two numbers .* only the first line may be a header"),
    (lambda L: L[:4] + ["0.2,0.1"] + L[5:], r"line 5: time 0\.2 s does not increase"),
    (lambda L: L[:3], r"2 sample\(s\); a wave record needs at least 4"),
])
def test_bad_csv_names_the_file_line_and_what_is_valid(tmp_path, edit, match):
    path = lines_file(tmp_path, "\n".join(edit(list(GOOD))) + "\n")
    with pytest.raises(BoatlandInputError, match=match) as exc:
        MeasuredRecord.from_csv(path)
    assert str(exc.value).startswith(str(path)) and "\n" not in str(exc.value)


def test_comments_semicolons_and_tolerance(tmp_path):
    text = "# gauge 3, tank run 12\n" + "\n".join(f"{0.1 * i:.3f}; {math.cos(i):.3f}  # sample {i}" for i in range(8))
    t, eta = read_elevation_csv(lines_file(tmp_path, text))
    assert t.size == 8 and eta[0] == 1.0
    jitter = "\n".join(f"{0.1 * i + (0.003 if i == 4 else 0):.4f},{i}" for i in range(8))
    p = lines_file(tmp_path, jitter, "j.csv")
    with pytest.raises(BoatlandInputError, match="uniform within 1 %"):
        read_elevation_csv(p)
    assert read_elevation_csv(p, rtol=0.05)[0].size == 8


def test_missing_file_and_bad_record_fields(tmp_path):
    with pytest.raises(BoatlandInputError, match="no such file \\(the wave record\\)"):
        MeasuredRecord.from_csv(tmp_path / "nope.csv")
    with pytest.raises(BoatlandInputError, match=r"eta: sample 2 is nan; every sample must be finite"):
        MeasuredRecord(eta=[0.0, 1.0, np.nan, 0.0, 1.0], dt=0.1)
    with pytest.raises(BoatlandInputError, match=r"dt: must be > 0 s"):
        MeasuredRecord(eta=np.zeros(8), dt=0.0)
    with pytest.raises(BoatlandInputError, match=r"n_components: must be an integer ≥ 1"):
        MeasuredRecord(eta=np.zeros(8), dt=0.1, n_components=0)
