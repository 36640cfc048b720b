"""Every closed form read from disk is re-checked (issue 42, class 9): a
record of :func:`~linecontact_sym.method.derivation.remembered` whose closed
form was changed and its checksum recomputed (tests/store_records.py) is
dropped with a warning and derived afresh, for the periodic array's force
and full-contact load and the JKR pull-off as for every other record; and
a FIFO where a record is expected is never opened."""
import os
import threading

import pytest
import sympy as sp

import linecontact_sym as lcs
from linecontact_sym.method import store
from store_records import cache, rewrite_derivations  # noqa: F401 (cache: a fixture)

h, L = sp.symbols("h L", positive=True)


def _sinusoid():
    return lcs.LineContact(h * (1 - sp.cos(2 * sp.pi * lcs.x / L)), period=L, verify=False)


def test_a_forged_periodic_force_and_full_contact_load_are_rechecked(cache):
    c = _sinusoid()
    force, full = c.force, c.derivation("full_contact_force").expr
    # the array's force with sin for sin**2, the full-contact load doubled; checksums recomputed
    n = rewrite_derivations(cache, lambda old: old.replace("Integer(2)", "Integer(1)", 1)
                            if "sin" in old else f"Mul(Integer(2), {old})")
    assert n >= 2
    store.clear_memory()
    c2 = _sinusoid()
    with pytest.warns(store.UntrustedCacheWarning, match="independent check"):
        assert sp.simplify(c2.force - force) == 0
    store.clear_memory()
    with pytest.warns(store.UntrustedCacheWarning, match="independent check"):
        assert sp.simplify(_sinusoid().derivation("full_contact_force").expr - full) == 0
    # Westergaard's load per period, P = pi E* h sin(pi a/L)**2: the truth the forged record contradicted
    assert sp.simplify(force - sp.pi * lcs.E_star * h * sp.sin(sp.pi * lcs.a / L)**2) == 0


def test_a_forged_jkr_pull_off_is_rechecked(cache):
    ad = lcs.parabola(verify=False).adhesive()
    P = ad.pull_off_force
    assert rewrite_derivations(cache, lambda old: f"Mul(Integer(2), {old})") >= 1
    store.clear_memory()
    with pytest.warns(store.UntrustedCacheWarning, match="independent check"):
        P2 = lcs.parabola(verify=False).adhesive().pull_off_force
    assert sp.simplify(P2 - P) == 0
    # at R = E* = gamma = 1, the minimum of P(a) = pi a**2/4 - sqrt(2 pi a) (Eq. 33 typed here), found here
    import mpmath
    a_min = mpmath.findroot(lambda u: mpmath.pi * u / 2 - mpmath.sqrt(2 * mpmath.pi / u) / 2, 0.8)
    p_min = mpmath.pi * a_min**2 / 4 - mpmath.sqrt(2 * mpmath.pi * a_min)
    assert abs(float(P.subs({lcs.R: 1, lcs.E_star: 1, lcs.gamma: 1})) - float(p_min)) < 1e-12
    assert abs(float(p_min) + 1.74367) < 1e-5


def test_a_fifo_at_a_record_path_is_not_opened(cache):
    """A FIFO where a record is expected: skipped at once (before: open()
    blocked forever waiting for a writer)."""
    key = store.make_key("remembered", "a fifo test")
    path = store._path(key)
    path.parent.mkdir(parents=True, exist_ok=True)
    os.mkfifo(path)
    out = []
    t = threading.Thread(target=lambda: out.append(store.get(key)), daemon=True)
    t.start()
    t.join(10)
    assert not t.is_alive(), "reading a FIFO record blocked"
    assert out == [None]
