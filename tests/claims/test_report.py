"""The report's tables (claims/report.py) take numbers, never code.  Moved
from tests/test_hardening.py (issue 10)."""
import pytest

from linecontact_sym.core.errors import LineContactError


def test_report_rows_refuse_code_strings():
    from linecontact_sym.claims.report import power_law_rows
    with pytest.raises(LineContactError):
        power_law_rows(["__import__('os').system('id') or 2"])
