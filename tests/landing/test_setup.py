"""The scenario on its vessel (boatland.landing): the contact dynamics, the time-step rule they bound and
the additional damping — each derived once, in the Setup."""

import math

import pytest

from boatland.landing.contacts import contact_period
from boatland.landing.setup import Setup, additional_damping
from boatland.vessel.database import roll_critical_damping

from box_vessel import make  # a CTV-like scenario on the box vessel (fixture box_db)


def test_contact_period_and_dt_rule(box_db):
    s = make(remove=("simulation.dt",))
    cp = contact_period(s, box_db)
    m = box_db.M[0, 0] + box_db.A_inf[0, 0]
    # two contacts in parallel along the surge axis, lightly damped: T ≈ 2π √(m / 2c)
    assert cp.period == pytest.approx(2 * math.pi * math.sqrt(m / 2e6), rel=0.05)
    assert cp.undamped[0] == pytest.approx(2 * math.pi * math.sqrt(cp.m_eff[0] / 1e6))
    assert Setup.of(s, box_db).dt == 0.05
    stiff = make({"fender.stiffness": 1e8}, remove=("simulation.dt",))
    assert Setup.of(stiff, box_db).dt == pytest.approx(contact_period(stiff, box_db).period / 20)


def test_roll_damping_fraction_of_critical(box_db):
    s = make({"vessel.damping": {"roll_critical_fraction": 0.05, "linear": [0, 0, 0, 1e4, 0, 0]}})
    Bv, Bq = additional_damping(s, box_db)
    crit = roll_critical_damping(box_db)
    M44, A44, C44 = box_db.M[3, 3], box_db.A_inf[3, 3], box_db.C[3, 3]  # A is constant in this database
    assert crit == pytest.approx(2 * math.sqrt((M44 + A44) * C44))
    assert Bv[3, 3] == pytest.approx(1e4 + 0.05 * crit) and not Bq.any()


def test_the_setup_derives_each_value_once_and_agrees_with_its_parts(box_db, monkeypatch):
    """One contact-period solve per Setup; its dt, contacts and law come from that one derivation."""
    import boatland.landing.contacts as contacts

    calls = []
    real = contacts.contact_period
    monkeypatch.setattr(contacts, "contact_period", lambda *a: calls.append(a) or real(*a))
    s = make(remove=("simulation.dt",))
    setup = Setup.of(s, box_db)
    kernel, law = setup.contacts(), setup.contact_law()
    assert len(calls) == 1
    assert setup.dt == pytest.approx(min(0.05, 7.0 / 100, setup.contact_period.dt_limit))
    assert setup.n_steps == math.ceil(s.simulation.duration / setup.dt - 1e-9)
    assert kernel[0].shape == (2, 3) and law.n_points == 2
    assert law.c_t == pytest.approx(setup.fender.shear_damping) and law.k_t == pytest.approx(s.fender.shear_stiffness)
    assert setup.start_pose == s.start_pose()
    assert setup.pile == (3.25, (0.0, 0.0), math.inf)         # on by default: the database has a hull mesh
    assert Setup.of(s.replace({"landing.diffraction": False}), box_db).pile is None


def test_a_setup_is_used_only_with_its_own_scenario_and_database(box_db):
    from boatland.landing.setup import Setup

    s = make()
    setup = Setup.of(s, box_db)
    assert Setup.of(s, box_db, setup) is setup
    with pytest.raises(ValueError, match="another scenario or database"):
        Setup.of(make(), box_db, setup)
    with pytest.raises(ValueError, match="another scenario or database"):
        Setup.of(s, box_db.replace(name="other"), setup)


def test_a_trial_without_a_mass_matrix_is_one_clear_error(box_db):
    from boatland.errors import BoatlandInputError
    from boatland.trial.simulate import simulate

    with pytest.raises(BoatlandInputError, match="'box' has no mass matrix M: a time-domain run needs it"):
        simulate(make(), box_db.replace(M=None))
