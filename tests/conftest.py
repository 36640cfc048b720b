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
# and every session starts from an empty one (one directory for all the
# session's xdist workers).
def _session_cache():
    import atexit
    import os
    import shutil
    import tempfile
    # pytest-xdist's workers inherit the controller's environment: they share
    # its directory (records are written atomically), so a law one worker
    # derived is read, and re-checked, by the other instead of derived twice
    inherited = os.environ.get(_SHARED_ENV)
    if os.environ.get("PYTEST_XDIST_WORKER") and inherited and os.path.isdir(inherited):
        os.environ["LINECONTACT_SYM_CACHE"] = inherited
        return inherited
    path = tempfile.mkdtemp(prefix="linecontact_sym-test-cache-")
    os.environ["LINECONTACT_SYM_CACHE"] = os.environ[_SHARED_ENV] = path
    atexit.register(shutil.rmtree, path, ignore_errors=True)
    return path


_SHARED_ENV = "LINECONTACT_SYM_TEST_SESSION_CACHE"


TEST_CACHE = _session_cache()


# ---------------------------------------------------------------- the fast loop
# `pytest -m "not slow"` is the development loop (about a minute on 2 cores):
# the tests below are marked `slow` here, in one place, from the measured
# durations (`--durations`, 2 cores: each took more than about 1 s on an idle
# machine, measured 14:06 on main 48ad1c3).  They still run in CI (plain `pytest`).  A test whose own
# file marks it `@pytest.mark.slow` needs no entry.
SLOW_TESTS = {
    "claims/test_baney_hui.py": ["test_baney_hui_claims_hold", "test_baney_hui_wrong_table_entry_fails"],
    "claims/test_claims.py": ["test_parameter_range_found_by_bisection",
                              "test_adhesive_claims_and_existence_bound",
                              "test_printed_eq10_holds_only_where_slope_at_origin_vanishes",
                              "test_flat_punch_from_first_principles",
                              "test_pull_off_force_is_the_negative_minimum_and_adhesion_force_its_opposite",
                              "test_hertz_force_holds_symbolically", "test_pressure_claim_with_flamant_check",
                              "test_printed_inverse_map_integral_is_an_arb_enclosure"],
    "claims/test_flat_claims.py": ["test_published_rounded_punch_and_wedge_pressures_hold",
                                   "test_flamant_checks_split_at_the_flat_and_report_their_resolution"],
    "claims/test_paper_results.py": ["test_gap_is_nonnegative_and_vanishes_at_edge",
                                     "test_pressure_integrates_to_the_load"],
    "contacts/test_adhesion.py": ["test_worn_cylinder_kink_and_stationary",
                                  "test_exact_cylinder_numeric_pull_off", "test_power_law_eq35_record",
                                  "test_wedge_eq36", "test_parabola_barquins_eq34",
                                  "test_force_eq33_and_pressure_eq29_symbolic", "test_gamma_zero_recovers_engine",
                                  "test_parabola_pull_off_independent_numbers",
                                  "test_power_law_independent_minimisation",
                                  "test_power_law_matches_printed_eq35", "test_user_profile_numeric_pull_off",
                                  "test_wedge_branches_closed_form", "test_wrong_formula_fails_verification"],
    "contacts/test_adhesion_law.py": ["test_expression_law_pull_off_by_the_generic_layer"],
    "contacts/test_flats.py": ["test_circular_corner_punch_search_ends",
                               "test_cosh_pull_off_within_budget_against_mpmath",
                               "test_numeric_search_stops_at_its_budget",
                               "test_pressure_without_closed_force_law_is_one_quadrature",
                               "test_quartic_pull_off_closed_and_remembered",
                               "test_rounded_punch_force_and_pressure_against_ciavarella",
                               "test_rounded_punch_jkr_pull_off_against_independent_minimum",
                               "test_rounded_punch_pull_off_where_the_grid_crossed_the_flat_end",
                               "test_rounded_punch_tangential_and_gap"],
    "contacts/test_maugis_dugdale.py": ["test_state_against_flamant_and_johnson", "test_law_of_the_generic_layer",
                                        "test_conditions_closed_and_verified", "test_baney_hui_table",
                                        "test_baney_hui_eq23_derived", "test_cohesive_zone_unique_gap_rises",
                                        "test_jkr_limit", "test_worn_cylinder_two_minima"],
    "contacts/test_tangential.py": ["test_claims_file_holds", "test_hertz_verification_records",
                                    "test_direct_boundary_element_solution"],
    "core/test_number_types.py": ["test_every_number_type_on_every_entry_point"],
    "core/test_precision.py": ["test_every_precision_change_is_under_the_lock",
                               "test_first_derivations_in_threads_leave_the_precision"],
    "core/test_sweeps.py": ["test_export_on_blocks_equals_one_call", "test_exports_and_contacts_pickle",
                            "test_scalar_calls_agree_with_the_array_path"],
    "method/test_closed_forms.py": ["test_evaluate_arrays_and_scalars_agree",
                                    "test_piecewise_pressure_and_gap_every_region",
                                    "test_cache_on_disk_and_in_memory",
                                    "test_exact_cylinder_float64_exports_at_small_a_over_r",
                                    "test_exact_cylinder_pressure_and_gap",
                                    "test_failure_is_remembered_not_retried"],
    "method/test_engine.py": ["test_power_law_sums", "test_inadmissible_profile_detected",
                              "test_numeric_export_numpy_and_mpmath",
                              "test_admissible_range_of_a_cosine_bump_and_quartic",
                              "test_half_width_closed_and_numeric",
                              "test_no_closed_form_is_honest_and_nothing_hangs",
                              "test_polynomials_with_nonnegative_coefficients"],
    "method/test_rules.py": ["test_decompose_and_beta_kernel_against_quadrature"],
    "numeric/test_evaluate.py": ["test_quantity_without_closed_form"],
    "numeric/test_extremes.py": ["test_extreme_grid_gap_closed_forms", "test_extreme_grid_gap_quadrature",
                                 "test_extreme_grid"],
    "test_architecture.py": ["test_no_import_of_another_modules_private_name"],
    "test_cli.py": ["test_check_adhesion_force_and_pull_off_signs", "test_model_maugis_dugdale",
                    "test_module_entry_point_runs", "test_paper_job_writes_report_table_and_figures"],
    "test_docs.py": ["test_sphinx_site_builds_offline"],
    "test_notebooks.py": ["test_notebook_runs"],
    "test_readme.py": ["test_readme_python_blocks_run"],
    "test_state.py": ["test_adhesive_and_every_kind_pickle_after_deriving"],
    "test_trust.py": ["test_item11_pressure_of_a_piecewise_profile_to_30_digits",
                      "test_item2_pull_off_inside_the_admissible_range",
                      "test_item1_pull_off_is_the_global_minimum", "test_property_every_minimum_found_ball",
                      "test_item4_wedge_typed_by_hand_keeps_its_closed_form",
                      "test_item6_pressure_behind_abs_and_oscillation_refused",
                      "test_item7_error_estimate_covers_the_error_next_to_a_kink"],
    "test_trust_round3.py": ["test_item2_a_parameter_of_any_name_is_a_parameter",
                             "test_item3_a_condition_that_fails_gives_no_number",
                             "test_item3_other_kinds_see_the_right_case"],
    "views/test_adhesion_map.py": ["test_adhesion_map_figure", "test_adhesion_map_limits"],
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
