import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, settings

# benchmarks/extremes.py (the grid of extreme arguments) is shared by
# tests/test_extremes.py and benchmarks/bench.py
_BENCHMARKS = str(Path(__file__).resolve().parents[1] / "benchmarks")
if _BENCHMARKS not in sys.path:
    sys.path.insert(0, _BENCHMARKS)

settings.register_profile(
    "ci", max_examples=12, deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
settings.load_profile("ci")


@pytest.fixture(scope="session")
def paper_contacts():
    """The paper's seed contacts, derived once per test session."""
    import linecontact_sym as lcs
    return {
        "parabola": lcs.parabola(),
        "power": lcs.power_law(),
        "wedge": lcs.wedge(),
        "worn": lcs.worn_cylinder(),
        "cylinder": lcs.exact_cylinder(),
    }


# The derivation cache (linecontact_sym.method.store) of a test session lives in
# a temporary directory of its own: tests never read or write the user's cache,
# and every session starts from an empty one.
def _session_cache():
    import atexit
    import os
    import shutil
    import tempfile
    path = tempfile.mkdtemp(prefix="linecontact_sym-test-cache-")
    os.environ["LINECONTACT_SYM_CACHE"] = path
    atexit.register(shutil.rmtree, path, ignore_errors=True)
    return path


TEST_CACHE = _session_cache()


# ---------------------------------------------------------------- the fast loop
# `pytest -m "not slow"` is the development loop (about a minute on 2 cores):
# the tests below are marked `slow` here, in one place, from the measured
# durations of the whole suite (`--durations`, 2 cores, load about 2: each took
# more than about 3 s).  They still run in CI (plain `pytest`).  A test whose own
# file marks it `@pytest.mark.slow` needs no entry.
SLOW_TESTS = {
    "contacts/test_tangential.py": ["test_claims_file_holds", "test_hertz_verification_records",
                                    "test_direct_boundary_element_solution"],
    "method/test_engine.py": ["test_power_law_sums", "test_inadmissible_profile_detected",
                              "test_numeric_export_numpy_and_mpmath"],
    "test_trust.py": ["test_item11_pressure_of_a_piecewise_profile_to_30_digits",
                      "test_item2_pull_off_inside_the_admissible_range", "test_item1_pull_off_is_the_global_minimum",
                      "test_property_every_minimum_found_ball"],
    "test_notebooks.py": ["test_notebook_runs"],
    "claims/test_claims.py": ["test_parameter_range_found_by_bisection", "test_adhesive_claims_and_existence_bound",
                              "test_printed_eq10_holds_only_where_slope_at_origin_vanishes",
                              "test_flat_punch_from_first_principles",
                              "test_pull_off_force_is_the_negative_minimum_and_adhesion_force_its_opposite",
                              "test_hertz_force_holds_symbolically"],
    "contacts/test_adhesion.py": ["test_worn_cylinder_kink_and_stationary", "test_exact_cylinder_numeric_pull_off",
                                  "test_power_law_eq35_record", "test_wedge_eq36", "test_parabola_barquins_eq34",
                                  "test_force_eq33_and_pressure_eq29_symbolic"],
    "numeric/test_extremes.py": ["test_extreme_grid_gap_closed_forms", "test_extreme_grid_gap_quadrature"],
    "test_cli.py": ["test_check_adhesion_force_and_pull_off_signs"],
    "test_readme.py": ["test_readme_python_blocks_run"],
    "test_state.py": ["test_adhesive_and_every_kind_pickle_after_deriving"],
    "numeric/test_evaluate.py": ["test_quantity_without_closed_form"],
    "test_docs.py": ["test_sphinx_site_builds_offline"],
    "method/test_closed_forms.py": ["test_evaluate_arrays_and_scalars_agree",
                                    "test_piecewise_pressure_and_gap_every_region"],
}


def pytest_collection_modifyitems(config, items):
    here = Path(__file__).resolve().parent
    slow = {(f, n) for f, names in SLOW_TESTS.items() for n in names}
    for item in items:
        try:
            rel = Path(str(item.fspath)).resolve().relative_to(here).as_posix()
        except ValueError:
            continue
        if (rel, getattr(item, "originalname", item.name)) in slow:
            item.add_marker(pytest.mark.slow)
