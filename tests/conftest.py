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
# `pytest -m "not slow"` is the development loop (about half a minute on 2 cores):
# the tests below are marked `slow` here, in one place, from the measured
# durations (`--durations`, 2 cores: each took more than about 1 s on an idle
# machine, measured 14:06 on main 48ad1c3; those above about 3.5 s with the
# machine at load 7, i.e. about 1 s idle, measured 23:20 on 8866819; since
# 2026-11-29 every test of half a second or more, idle: the loop 65 s -> 42 s).
# They still run in CI (plain `pytest`).  A test whose own file marks it
# `@pytest.mark.slow` needs no entry.
SLOW_TESTS = {
    "claims/test_baney_hui.py": ["test_baney_hui_claims_hold", "test_baney_hui_wrong_table_entry_fails"],
    "claims/test_claims.py": ["test_adhesive_claims_and_existence_bound", "test_assumption_restricts_the_points",
                              "test_elliptic_argument_convention_matters", "test_flat_punch_from_first_principles",
                              "test_hertz_force_holds_symbolically", "test_parameter_range_found_by_bisection",
                              "test_pressure_claim_with_flamant_check",
                              "test_pressure_counterexample_shows_the_pressure",
                              "test_printed_eq10_holds_only_where_slope_at_origin_vanishes",
                              "test_printed_inverse_map_integral_is_an_arb_enclosure",
                              "test_pull_off_force_is_the_negative_minimum_and_adhesion_force_its_opposite",
                              "test_wrong_formula_gives_counterexample_with_both_values",
                              "test_removable_point_is_reported_as_condition",
                              "test_table_values_identified_with_exponents",
                              "test_pull_off_at_a_kink_of_the_force_law_holds"],
    "claims/test_diagnosis.py": ["test_elliptic_mistakes"],
    "claims/test_flat_claims.py": ["test_flamant_checks_split_at_the_flat_and_report_their_resolution",
                                   "test_published_rounded_punch_and_wedge_pressures_hold"],
    "claims/test_paper_results.py": ["test_cylinder_force_against_direct_quadrature", "test_eq13_14_parabola",
                                     "test_eq19_20_wedge", "test_eq23_worn_cylinder", "test_fallbacks_are_honest",
                                     "test_gap_is_nonnegative_and_vanishes_at_edge",
                                     "test_pressure_integrates_to_the_load"],
    "claims/test_parallel.py": ["test_any_executor"],
    "contacts/test_adhesion.py": ["test_exact_cylinder_numeric_pull_off", "test_existence_condition_power_law",
                                  "test_force_eq33_and_pressure_eq29_symbolic", "test_gamma_zero_recovers_engine",
                                  "test_parabola_barquins_eq34", "test_parabola_equilibria",
                                  "test_parabola_pull_off_independent_numbers", "test_power_law_eq35_record",
                                  "test_power_law_independent_minimisation", "test_power_law_matches_printed_eq35",
                                  "test_power_law_special_cases", "test_user_profile_numeric_pull_off",
                                  "test_wedge_branches_closed_form", "test_wedge_eq36",
                                  "test_worn_cylinder_kink_and_stationary", "test_wrong_formula_fails_verification",
                                  "test_solve_is_not_tried_where_trigonometric_and_algebraic_terms_mix"],
    "contacts/test_adhesion_law.py": ["test_expression_law_pull_off_by_the_generic_layer",
                                      "test_inner_solve_law_pull_off_branches_and_jump_in"],
    "contacts/test_asymmetric.py": ["test_cubic_bounded_against_collocation",
                                    "test_exponential_states_against_collocation",
                                    "test_wedge_states_against_chebyshev_moments",
                                    "test_wedge_tilt_is_the_mean_slope"],
    "contacts/test_asymmetric_claims.py": ["test_verdicts_of_the_punch_and_the_shifted_hertz"],
    "contacts/test_asymmetric_edges.py": ["test_sign_check_pressure_of_a_bounded_state_without_closed_form"],
    "contacts/test_domain.py": ["test_values_outside_the_domain_are_refused",
                                "test_singular_points_and_negative_loads_are_domain_errors",
                                "test_values_inside_the_domain_still_evaluate"],
    "contacts/test_equilibria.py": ["test_pull_off_is_the_global_minimum",
                                    "test_pull_off_inside_the_admissible_range", "test_every_equilibrium_at_a_load",
                                    "test_wedge_typed_by_hand_keeps_its_closed_form",
                                    "test_property_every_minimum_found_adaptive",
                                    "test_property_every_minimum_found_ball"],
    "contacts/test_flats.py": ["test_circular_corner_punch_search_ends",
                               "test_cosh_pull_off_within_budget_against_mpmath",
                               "test_numeric_search_stops_at_its_budget",
                               "test_pressure_without_closed_force_law_is_one_quadrature",
                               "test_quartic_pull_off_closed_and_remembered",
                               "test_rounded_punch_force_and_pressure_against_ciavarella",
                               "test_rounded_punch_half_width_at_every_load",
                               "test_rounded_punch_jkr_pull_off_against_independent_minimum",
                               "test_rounded_punch_pull_off_where_the_grid_crossed_the_flat_end",
                               "test_rounded_punch_tangential_and_gap", "test_sin_profile_force_evaluates",
                               "test_smooth_pressure_refuses_at_once_and_gives_a_number",
                               "test_stick_half_width_budget_is_a_deadline_and_remembered",
                               "test_rounded_punch_float64_beside_the_flat_end"],
    "contacts/test_maugis_dugdale.py": ["test_baney_hui_eq23_derived", "test_baney_hui_table",
                                        "test_cohesive_zone_unique_gap_rises", "test_conditions_closed_and_verified",
                                        "test_jkr_limit", "test_law_of_the_generic_layer",
                                        "test_planted_wrong_condition_fails_certification",
                                        "test_small_lambda_rigid_limit", "test_state_against_flamant_and_johnson",
                                        "test_worn_cylinder_two_minima", "test_exponentially_small_minimum",
                                        "test_model_choice", "test_parabola_small_lambda_sqrt"],
    "contacts/test_maugis_limits.py": ["test_cohesive_zone_stops_at_the_crest",
                                       "test_jkr_limit_of_the_pull_off_is_reached_at_once",
                                       "test_slope_of_the_law_at_a_large_maugis_parameter"],
    "contacts/test_periodic.py": ["test_half_width_at_the_full_contact_load_is_half_the_period",
                                  "test_kernel_condition_is_mapped_not_copied"],
    "contacts/test_pickle.py": ["test_adhesive_and_every_kind_pickle_after_deriving"],
    "contacts/test_rolling.py": ["test_a_leading_slip_zone_is_refused",
                                 "test_asymmetric_profile_under_a_moment_against_the_bem",
                                 "test_asymmetric_rolling_takes_the_materials", "test_even_power_x4_against_the_bem",
                                 "test_rolling_states_the_coupling_and_keeps_its_numbers"],
    "contacts/test_stresses.py": ["test_critical_friction_von_mises",
                                  "test_hertz_closed_form_is_verified_and_is_mcewens",
                                  "test_hertz_maximum_shear_closed_form", "test_partial_slip_against_flamant",
                                  "test_power_law_closed_form_is_hypergeometric_and_field_matches_reference",
                                  "test_punch_quadrature_at_a_kink_against_mpmath", "test_registry_and_construction",
                                  "test_to_numeric_field_and_plots",
                                  "test_kolosov_field_equals_flamant_quadrature_with_friction",
                                  "test_stress_plot_needs_only_the_profile_parameters",
                                  "test_a_frictional_field_states_the_neglected_coupling_and_keeps_its_numbers"],
    "contacts/test_tangential.py": ["test_claims_file_holds", "test_direct_boundary_element_solution",
                                    "test_fretting_loop_area_is_the_dissipated_energy", "test_hertz_closed_forms",
                                    "test_hertz_verification_records", "test_mindlin_deresiewicz_identities",
                                    "test_gross_sliding",
                                    "test_materials_state_the_neglected_coupling_once_and_change_no_number"],
    "contacts/test_viscoelastic.py": ["test_extreme_relaxation_times",
                                      "test_force_ramp_and_recede_against_own_quadrature"],
    "contacts/test_viscoelastic_edges.py": ["test_numbers_at_the_entry_are_checked"],
    "contacts/test_viscoelastic_work.py": ["test_elastic_limit_eta_to_zero",
                                           "test_quadrature_fallback_agrees_with_the_antiderivatives",
                                           "test_kelvin_voigt_rate_change_while_loading",
                                           "test_kelvin_voigt_cycle_against_time_stepping",
                                           "test_maxwell_cycle_against_its_depth_identity",
                                           "test_error_estimate_covers_the_true_error_at_coarse_grids"],
    "core/test_budget.py": ["test_a_child_taking_work_done_ahead_is_charged_for_it",
                            "test_waiting_costs_no_cpu_and_only_the_wall_clock_guard_stops_a_hang"],
    "core/test_budget_daemon.py": ["test_budget_inside_a_daemonic_pool_worker"],
    "core/test_lazy_import.py": ["test_threads_touching_public_names_at_once_do_not_deadlock"],
    "core/test_number_types.py": ["test_every_number_type_on_every_entry_point"],
    "core/test_precision.py": ["test_every_precision_change_is_under_the_lock",
                               "test_first_derivations_in_threads_leave_the_precision"],
    "core/test_ranges.py": ["test_physical_ranges_in_one_place"],
    "core/test_sweeps.py": ["test_export_on_blocks_equals_one_call", "test_exports_and_contacts_pickle",
                            "test_scalar_calls_agree_with_the_array_path",
                            "test_scalar_domain_check_is_the_full_check"],
    "method/test_budgets.py": ["test_budget_covers_the_whole_derivation"],
    "method/test_cases.py": ["test_parameter_case_of_a_piecewise_is_a_condition",
                             "test_a_condition_that_fails_gives_no_number",
                             "test_every_case_is_derived_and_every_path_agrees",
                             "test_other_kinds_see_the_right_case"],
    "method/test_closed_forms.py": ["test_cache_on_disk_and_in_memory", "test_evaluate_arrays_and_scalars_agree",
                                    "test_exact_cylinder_float64_exports_at_small_a_over_r",
                                    "test_exact_cylinder_pressure_and_gap", "test_failure_is_remembered_not_retried",
                                    "test_inverse_map_of_k_minus_e_merges_the_series",
                                    "test_piecewise_pressure_and_gap_every_region",
                                    "test_worn_cylinder_pressure_is_infinite_at_the_kink"],
    "method/test_engine.py": ["test_admissible_range_of_a_cosine_bump_and_quartic",
                              "test_half_width_closed_and_numeric", "test_inadmissible_profile_detected",
                              "test_inverse_of_a_three_power_sum_closes_within_the_budget",
                              "test_no_closed_form_is_honest_and_nothing_hangs",
                              "test_numeric_export_numpy_and_mpmath",
                              "test_polynomials_with_nonnegative_coefficients", "test_power_law_sums",
                              "test_profiles_nobody_typed_in", "test_rounded_punch_piecewise_with_kink",
                              "test_round_trip_cylinder_numeric"],
    "method/test_profiles.py": ["test_float_exponents_in_a_profile_mean_their_decimal"],
    "method/test_rules.py": ["test_gap_sympy", "test_pressure_swap",
                             "test_sympy_integrate_on_a_linear_part_of_an_asymmetric_contact_is_capped"],
    "method/test_store_recheck.py": ["test_a_forged_periodic_force_and_full_contact_load_are_rechecked"],
    "method/test_symbols.py": ["test_a_parameter_of_any_name_is_a_parameter"],
    "numeric/test_evaluate.py": ["test_array_point_breaking_a_condition_is_nan",
                                 "test_float64_estimate_honest_at_weak_spots", "test_mpmath_path_meets_rtol",
                                 "test_quantity_without_closed_form", "test_certified_enclosure_contains_reference",
                                 "test_every_path_meets_rtol_and_bound_is_honest", "test_power_law_pressure_rtol"],
    "numeric/test_extremes.py": ["test_extreme_grid", "test_extreme_grid_gap_closed_forms",
                                 "test_extreme_grid_gap_power_law", "test_extreme_grid_gap_quadrature",
                                 "test_known_traps_fixed", "test_extreme_grid_periodic",
                                 "test_periodic_near_full_contact_relative"],
    "numeric/test_kinks.py": ["test_inside_the_flat_is_zero_not_overflow",
                              "test_pressure_of_a_piecewise_profile_to_30_digits",
                              "test_hidden_kinks_are_breakpoints",
                              "test_pressure_behind_abs_and_oscillation_refused",
                              "test_error_estimate_covers_the_error_next_to_a_kink"],
    "numeric/test_reference.py": ["test_seed_verification_records_are_certified_by_arb",
                                  "test_log_end_point_is_certified_and_a_planted_value_is_left_out"],
    "numeric/test_removable_limit.py": ["test_no_limit_is_sought_where_every_contact_refuses_zero"],
    "numeric/test_scalar_path.py": ["test_scalar_calls_take_the_scalar_path",
                                    "test_monomial_one_pass_is_the_general_path"],
    "numeric/test_stable_rules.py": ["test_asin_to_atan_complement_form",
                                     "test_hyp2f1_connection_of_a_sum_of_three_powers_is_fast"],
    "test_architecture.py": ["test_imports_run_down_the_layers",
                             "test_no_import_cycle_even_through_function_level_imports",
                             "test_no_import_of_another_modules_private_name"],
    "test_cli.py": ["test_check_adhesion_force_and_pull_off_signs", "test_check_json", "test_model_maugis_dugdale",
                    "test_module_entry_point_runs", "test_paper_job_writes_report_table_and_figures",
                    "test_paper_shipped_subset_json", "test_cli_edges_are_input_errors", "test_check_file",
                    "test_eval_takes_the_arrays_own_quantities"],
    "test_docs.py": ["test_sphinx_site_builds_offline", "test_a_tutorial_shows_its_formulas_and_figures",
                     "test_a_rebuild_executes_nothing", "test_gallery_draws_every_entry_with_its_code"],
    "test_extras.py": ["test_the_package_imports_without_the_extras"],
    "test_no_eval.py": ["test_no_string_can_reach_eval"],
    "test_notebooks.py": ["test_notebook_runs"],
    "test_readme.py": ["test_readme_python_blocks_run"],
    "views/test_adhesion_map.py": ["test_adhesion_map_figure", "test_adhesion_map_limits"],
    "views/test_latex.py": ["test_reports_are_well_formed"],
    "views/test_plots.py": ["test_contact_plot_writes_figures",
                            "test_a_figure_is_redrawn_only_when_its_inputs_or_its_files_changed",
                            "test_plot_quantity_writes_png_and_pdf_with_a_ratio_panel",
                            "test_adhesive_view_branches_pull_off_and_jump_in"],
}

#: doctests of the package (by their name) that take more than about 1 s
SLOW_DOCTESTS = {"linecontact_sym.claims.references.flamant_relative_displacement",
                 "linecontact_sym.contacts.adhesion.maugis.law.MaugisDugdaleContact",
                 "linecontact_sym.contacts.normal.inverse.periodic_profile_from_force",
                 "linecontact_sym.numeric.evaluate"}



def pytest_collection_modifyitems(config, items):
    here = Path(__file__).resolve().parent
    slow = {(f, n) for f, names in SLOW_TESTS.items() for n in names}
    for item in items:
        if item.name in SLOW_DOCTESTS:
            item.add_marker(pytest.mark.slow)
            continue
        try:
            rel = Path(str(item.fspath)).resolve().relative_to(here).as_posix()
        except ValueError:
            continue
        if (rel, getattr(item, "originalname", item.name)) in slow:
            item.add_marker(pytest.mark.slow)


# ---------------------------------------------------------------- the docs site
# Built once per test session (tests/docs_site.py): the build executes every
# notebook, tests/test_docs.py reads its pages and tests/test_notebooks.py its
# executed notebooks.  Their tests are one xdist group ("docs", --dist loadgroup
# in pyproject.toml), so one worker normally asks for it; a second worker that
# asks anyway (xdist has run the group's tests on two workers in CI) waits for
# the first one's build and reads it: two builds at once in the one docs/ folder
# removed each other's generated API pages (docs/conf.py starts docs/reference
# afresh), a red CI.  The lock and the build's result are in the folder all
# workers of the session share (the parent of each worker's basetemp).
@pytest.fixture(scope="session")
def docs_site(tmp_path_factory):
    pytest.importorskip("sphinx")
    pytest.importorskip("myst_nb")
    pytest.importorskip("ipykernel")
    import json
    import os
    import subprocess
    import docs_site as site
    base = tmp_path_factory.getbasetemp()
    root = (base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base) / "docs_site"
    root.mkdir(exist_ok=True)
    out, result = root / "docs", root / "result.json"
    try:
        import fcntl
    except ImportError:         # no POSIX locks (Windows): one build per worker, as xdist groups them
        fcntl = None
    with open(root / "lock", "w") as lock:
        if fcntl is not None:
            fcntl.flock(lock, fcntl.LOCK_EX)
        if not result.exists():
            out.mkdir(exist_ok=True)
            proc = site.build(out)
            result.write_text(json.dumps({"returncode": proc.returncode, "stdout": proc.stdout,
                                          "stderr": proc.stderr}), encoding="utf-8")
    done = json.loads(result.read_text(encoding="utf-8"))
    proc = subprocess.CompletedProcess(args=["sphinx"], returncode=done["returncode"], stdout=done["stdout"],
                                       stderr=done["stderr"])
    assert proc.returncode == 0, proc.stderr[-5000:]
    return out, proc
