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
