"""Sea-state model objects: validation (errors name the field and the valid range), defaults,
realisation, and the excitation series for a database."""

import dataclasses
import math
import warnings

import numpy as np
import pytest

from boatland.errors import BoatlandInputError
from boatland.hydro.builtin import load_builtin
from boatland.sea.spectra import SeaStateWarning, SpectrumPart, spectrum_part_problems
from boatland.sea.states import MeasuredRecord, RegularWave, SeaState, excitation_table, wave_excitation
from boatland.waves.synthesis import elevation


@pytest.fixture(scope="module")
def ctv24():
    return load_builtin("ctv24")


def no_warnings(fn):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return fn()


# ---------------------------------------------------------------------- bad input
@pytest.mark.parametrize("kwargs, match", [
    (dict(Hs=-1.0, Tp=8.0), r"sea state: Hs: must be > 0 m \(significant wave height\), got -1"),
    (dict(Hs=0.0, Tp=8.0), r"Hs: must be > 0 m"),
    (dict(Hs=1.0, Tp=0.0), r"Tp: must be > 0 s \(peak period\), got 0"),
    (dict(Hs=1.0, Tp=float("nan")), r"Tp: must be > 0 s"),
    (dict(Hs=1.0, Tp=8.0, gamma=0.5), r"gamma: must be in \[1, 10\] .* got 0.5"),
    (dict(Hs=1.0, Tp=8.0, gamma=12.0), r"gamma: must be in \[1, 10\]"),
    (dict(Hs=1.0, Tp=8.0, kind="pm", gamma=3.3), r"gamma: a Pierson–Moskowitz part has γ = 1"),
    (dict(Hs=1.0, Tp=8.0, spreading=0.0), r"spreading: must be > 0 .* got 0"),
    (dict(Hs=1.0, Tp=8.0, spreading=-2.0), r"spreading: must be > 0"),
    (dict(Hs=1.0, Tp=8.0, kind="jonswp"), r"kind: must be one of 'jonswap', 'pm', 'tma', 'gaussian', got 'jonswp' \(did you mean 'jonswap'\?\)"),
    (dict(Hs=1.0, Tp=8.0, sigma_a=0.0), r"sigma_a: must be in \(0, 0.5\]"),
    (dict(Hs="1", Tp=8.0), r"Hs: must be > 0 m .* got '1'"),
])
def test_bad_spectrum_part_names_the_field_and_range(kwargs, match):
    with pytest.raises(BoatlandInputError, match=match):
        SpectrumPart(**kwargs)


def test_all_problems_at_once_and_with_a_key_prefix():
    with pytest.raises(BoatlandInputError) as exc:
        SpectrumPart(Hs=-1.0, Tp=-2.0, gamma=20.0, spreading=0.0)
    assert exc.value.keys() == ["Hs", "Tp", "gamma", "spreading"]
    problems, warns = spectrum_part_problems({"Hs": 1.0, "Tp": -3, "gamma": 8.0}, prefix="sea.parts[1].")
    assert problems == [("sea.parts[1].Tp", "must be > 0 s (peak period), got -3")]
    assert warns == ["sea.parts[1].gamma = 8 is outside the usual range 1–7 of measured JONSWAP spectra"]


def test_unusual_gamma_and_breaking_steepness_warn():
    with pytest.warns(SeaStateWarning, match=r"gamma = 8.5 is outside the usual range 1–7"):
        SpectrumPart(Hs=1.0, Tp=8.0, gamma=8.5)
    no_warnings(lambda: SpectrumPart(Hs=1.0, Tp=8.0, gamma=7.0))
    # Hs / λp = 3 / 14.05 = 0.21 > 1/7 in deep water
    with pytest.warns(SeaStateWarning, match=r"steepness 0\.213 .* past the breaking limit 0\.143"):
        SeaState(parts=SpectrumPart(Hs=3.0, Tp=3.0))
    no_warnings(lambda: SeaState(parts=SpectrumPart(Hs=2.0, Tp=6.0)))
    # finite depth: Miche's limit tanh(kh)/7 is lower
    with pytest.warns(SeaStateWarning, match=r"steepness 0\.049 .* breaking limit 0\.045"):
        RegularWave(H=2.4, T=10.0, water_depth=2.5)  # H / h = 0.96 > 0.89 (Miche in shallow water)
    with pytest.warns(SeaStateWarning, match="regular wave"):
        RegularWave(H=3.0, T=3.0)


@pytest.mark.parametrize("kwargs, match", [
    (dict(parts=()), r"parts: must hold at least one SpectrumPart"),
    (dict(parts=(1.0,)), r"parts\[0\]: must be a SpectrumPart, got float"),
    (dict(water_depth=0.0), r"water_depth: must be > 0 m \(inf for deep water\)"),
    (dict(water_depth=-5), r"water_depth: must be > 0 m"),
    (dict(n_components=0), r"n_components: must be an integer ≥ 1"),
    (dict(band_tail=0.5), r"band_tail: must be in \(0, 0.1\]"),
    (dict(repeat_period=0.0), r"repeat_period: must be a finite time > 0 s"),
    (dict(repeat_period=math.inf), r"repeat_period: must be a finite time > 0 s"),
    (dict(omega_min=0.3), r"omega_max: give both omega_min and omega_max"),
    (dict(omega_min=2.0, omega_max=1.0), r"omega_max: must be > omega_min = 2 rad/s"),
    (dict(amplitudes="random"), r"amplitudes: must be one of 'deterministic', 'rayleigh'"),
    (dict(g=3.7), r"g: must be the Earth's gravity"),
])
def test_bad_sea_state(kwargs, match):
    kwargs = {"parts": SpectrumPart(Hs=1.0, Tp=7.0), **kwargs}
    with pytest.raises(BoatlandInputError, match=match):
        SeaState(**kwargs)


@pytest.mark.parametrize("kwargs, match", [
    (dict(H=0.0, T=6.0), r"regular wave: H: must be > 0 m \(wave height, crest to trough\), got 0"),
    (dict(H=1.0, T=-6.0), r"T: must be > 0 s \(wave period\)"),
    (dict(H=1.0, T=6.0, direction_deg=float("inf")), r"direction_deg: must be a finite number"),
])
def test_bad_regular_wave(kwargs, match):
    with pytest.raises(BoatlandInputError, match=match):
        RegularWave(**kwargs)


# ---------------------------------------------------------------------- defaults and realisation
def test_defaults_and_immutability():
    p = SpectrumPart(Hs=1, Tp=7)
    assert (p.kind, p.gamma, p.sigma_a, p.sigma_b, p.spreading, p.direction_deg) == ("jonswap", 3.3, 0.07, 0.09, None, 0.0)
    assert isinstance(p.Hs, float) and SpectrumPart(Hs=1, Tp=7, kind="pm").gamma == 1.0
    sea = SeaState(parts=p)
    assert sea.parts == (p,) and sea.water_depth == math.inf and sea.n_components == 256
    assert sea.repeat_period == 600.0 and sea.n_components_for(60.0) == sea.n_components_for(600.0) == [402]
    assert sea.amplitudes == "deterministic" and sea.default_ramp_time == 14.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        sea.water_depth = 10.0
    with pytest.raises(TypeError):
        SpectrumPart(1.0, 7.0)  # keyword-only


def test_swell_plus_wind_sea_keep_their_own_directions():
    """Grøtting (2015) Table 4.12, case 1: wind sea Hs 1.3 m, Tp 5 s towards 0°; swell Hs 1 m, Tp 10 s towards 45°."""
    sea = SeaState(parts=(SpectrumPart(Hs=1.3, Tp=5.0, direction_deg=0.0),
                          SpectrumPart(Hs=1.0, Tp=10.0, kind="pm", direction_deg=45.0)))
    c = sea.realise(4, 1200.0)
    n1, n2 = sea.n_components_for(1200.0)
    assert c.size == n1 + n2
    assert np.all(c.theta[:n1] == 0.0) and np.allclose(c.theta[n1:], math.radians(45.0))
    assert 0.5 * np.sum(c.a[:n1] ** 2) == pytest.approx(0.998 * 1.3 ** 2 / 16, rel=1e-6)
    assert 0.5 * np.sum(c.a[n1:] ** 2) == pytest.approx(0.998 * 1.0 / 16, rel=1e-6)
    assert sea.hm0() == pytest.approx(math.hypot(1.3, 1.0), rel=1e-6)
    w = np.linspace(0.2, 3, 50)
    assert np.allclose(sea.spectrum(w), sea.parts[0].spectrum(w) + sea.parts[1].spectrum(w))


def test_short_crested_directional_spectrum_integrates_to_the_spectrum():
    sea = SeaState(parts=SpectrumPart(Hs=1.0, Tp=6.0, spreading=10.0, direction_deg=90.0))
    w = np.linspace(0.5, 3.0, 7)
    th = np.linspace(0, 2 * math.pi, 3601)
    S2 = sea.directional_spectrum(w, th)
    assert np.allclose(np.trapezoid(S2, th, axis=1), sea.spectrum(w), rtol=1e-10)
    assert th[np.argmax(S2[3])] == pytest.approx(math.pi / 2)


def test_tma_sea_in_shallow_water_has_less_energy():
    deep = SeaState(parts=SpectrumPart(Hs=1.5, Tp=8.0, kind="tma"))
    shallow = SeaState(parts=SpectrumPart(Hs=1.5, Tp=8.0, kind="tma"), water_depth=8.0)
    assert deep.hm0() == pytest.approx(1.5, rel=1e-6)
    assert shallow.hm0() < 0.9 * 1.5
    c = shallow.realise(1, 600.0)
    assert 4 * math.sqrt(c.variance) == pytest.approx(shallow.hm0(), rel=2e-3)
    assert np.allclose(9.81 * c.k * np.tanh(c.k * 8.0), c.omega ** 2, rtol=1e-13)


def test_explicit_band_and_rayleigh_amplitudes():
    sea = SeaState(parts=SpectrumPart(Hs=1.0, Tp=6.0), omega_min=0.4, omega_max=3.0, amplitudes="rayleigh")
    c = sea.realise(2, 600.0)
    assert c.omega.min() >= 0.4 and c.omega.max() < 3.0 and c.size == sea.n_components_for(600.0)[0]
    assert sea.realise(2, 600.0).a.tolist() == c.a.tolist()
    with pytest.raises(ValueError, match="duration must be"):
        sea.realise(2, -1.0)


def test_regular_wave_realises_one_crest_at_the_origin():
    wave = RegularWave(H=1.2, T=7.0, direction_deg=180.0, phase_deg=90.0)
    c = wave.realise()
    assert c.size == 1 and c.a[0] == 0.6 and c.theta[0] == pytest.approx(math.pi)
    assert elevation(c, 0.0, 0.0, 0.0)[0, 0] == pytest.approx(0.0, abs=1e-15)
    assert elevation(c, 0.0, 0.0, -7.0 / 4)[0, 0] == pytest.approx(0.6)
    assert wave.default_ramp_time == 14.0


# ---------------------------------------------------------------------- excitation through a database
def test_excitation_table_starts_with_the_long_wave_limit(ctv24):
    om, beta, X = excitation_table(ctv24)
    assert om[0] == 0.0 and np.array_equal(om[1:], ctv24.omega) and np.array_equal(beta, ctv24.wave_dir_deg)
    assert np.array_equal(X[:, :, 0], np.repeat(ctv24.C[:, 2][:, None], ctv24.n_dir, axis=1).astype(complex))
    # the first BEM frequency is close to that limit (heave: ρ g A_wp, in phase)
    assert abs(ctv24.X[2, 12, 0] / X[2, 12, 0] - 1) < 1e-3


def test_regular_wave_excitation_on_the_rk4_grid(ctv24):
    w = ctv24.omega[30]
    wave = RegularWave(H=1.0, T=2 * math.pi / w, direction_deg=200.0, phase_deg=10.0)
    dt, n_steps, x0, y0, psi = 0.05, 1200, 5.0, -3.0, 20.0  # β = 200° − 20° = 180°: head seas
    F = wave.excitation(ctv24, dt=dt, n_steps=n_steps, x0=x0, y0=y0, heading_deg=psi, ramp_time=0.0)
    assert F.shape == (2 * n_steps + 1, 6)
    t = 0.5 * dt * np.arange(2 * n_steps + 1)
    c = wave.realise()
    phase = math.radians(10.0) - c.k[0] * (x0 * math.cos(c.theta[0]) + y0 * math.sin(c.theta[0]))
    Xj = ctv24.X[:, int(np.flatnonzero(ctv24.wave_dir_deg == 180.0)[0]), 30]
    ref = 0.5 * np.abs(Xj) * np.cos(w * t[:, None] + np.angle(Xj) + phase)
    assert np.max(np.abs(F - ref)) < 1e-6 * 0.5 * np.abs(Xj).max()
    # default ramp: two periods, starting from zero
    Fr = wave.excitation(ctv24, dt=dt, n_steps=n_steps, x0=x0, y0=y0, heading_deg=psi)
    assert np.all(Fr[0] == 0) and np.array_equal(Fr[t >= 2 * wave.T], F[t >= 2 * wave.T])


def test_irregular_excitation_is_reproducible_and_warns_out_of_band(ctv24):
    sea = SeaState(parts=SpectrumPart(Hs=1.2, Tp=6.0, spreading=10.0, direction_deg=170.0))
    kw = dict(seed=np.random.SeedSequence(8), dt=0.05, n_steps=2000, x0=-12.0, y0=3.0, heading_deg=-10.0)
    F1 = no_warnings(lambda: sea.excitation(ctv24, **kw))
    assert np.array_equal(F1, sea.excitation(ctv24, **kw)) and np.all(np.isfinite(F1))
    assert F1.shape == (4001, 6) and np.std(F1[2000:, 2]) > 0
    short = SeaState(parts=SpectrumPart(Hs=0.5, Tp=2.0))  # peak at 3.1 rad/s, band to 16 rad/s
    with pytest.warns(SeaStateWarning, match=r"wave components \([0-9.]+ % of the wave variance\) lie above"):
        short.excitation(ctv24, seed=1, dt=0.05, n_steps=200)


def test_depth_mismatch_with_the_database_warns(ctv24):
    sea = SeaState(parts=SpectrumPart(Hs=1.0, Tp=9.0), water_depth=12.0)
    with pytest.warns(SeaStateWarning, match=r"computed for water depth inf m, these waves for 12 m"):
        sea.excitation(ctv24, seed=1, dt=0.1, n_steps=100)


def test_excitation_argument_checks(ctv24):
    c = RegularWave(H=1.0, T=6.0).realise()
    with pytest.raises(ValueError, match="dt must be"):
        wave_excitation(c, ctv24, dt=0.0, n_steps=10)
    with pytest.raises(ValueError, match="ramp_time must be"):
        wave_excitation(c, ctv24, dt=0.1, n_steps=10, ramp_time=-1.0)


def test_measured_record_model_from_arrays():
    t = 0.2 * np.arange(1000)  # 200 s: whole periods of 8 s and 5 s
    eta = 0.3 * np.cos(2 * math.pi * t / 8.0) + 0.1 * np.sin(2 * math.pi * t / 5.0)
    rec = MeasuredRecord(eta=eta, dt=0.2, n_components=2)
    c = rec.realise()
    assert c.size == 2 and np.allclose(sorted(c.a), [0.1, 0.3]) and rec.default_ramp_time == pytest.approx(16.0)
    assert not rec.eta.flags.writeable
