"""The README's Python examples run as written and give what they say."""
import re
from pathlib import Path

import sympy as sp

README = Path(__file__).resolve().parents[1] / "README.md"


def test_readme_python_blocks_run():
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), re.S)
    assert len(blocks) >= 2
    ns: dict = {}
    for block in blocks:
        exec(compile(block, str(README), "exec"), ns)  # the project's own README, not user input
    lcs, R, a = ns["lcs"], ns["R"], ns["a"]
    assert ns["c"].force == sp.pi * lcs.E_star * a**2 / (4 * R)
    roots = ns["ad"].half_width(-0.01, R=1, E_star=1, gamma=0.01)
    assert len(roots) == 2 and roots[0] > roots[1] > 0
