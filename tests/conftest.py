import pytest
from hypothesis import HealthCheck, settings

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
        "worn": lcs.worn_cylinder(budget=3),
        "cylinder": lcs.exact_cylinder(budget=3),
    }
